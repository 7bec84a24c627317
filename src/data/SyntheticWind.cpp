#include "data/SyntheticWind.hpp"

#include <netcdf.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "core/Error.hpp"

namespace og::data {
namespace {

void check(int status, const std::filesystem::path& file) {
  if (status != NC_NOERR)
    throw InternalError(file.string() + ": netCDF: " + nc_strerror(status));
}

void text(int id, int var, const char* name, const std::string& value,
          const std::filesystem::path& file) {
  check(nc_put_att_text(id, var, name, value.size(), value.c_str()), file);
}

}  // namespace

void writeSyntheticEra5Wind(const std::filesystem::path& file, SyntheticFormat format,
                            int columns, int rows) {
  if (columns < 2 || rows < 2) throw InternalError("synthetic wind: grid too small");
  const double dLon = 360.0 / columns;
  const double dLat = 180.0 / (rows - 1);
  const int mode = format == SyntheticFormat::kNetcdf4Deflate ? NC_NETCDF4 : NC_64BIT_OFFSET;
  int id = -1;
  check(nc_create(file.c_str(), mode | NC_CLOBBER, &id), file);
  struct Closer {
    int& id;
    ~Closer() {
      if (id >= 0) nc_close(id);
    }
  } closer{id};

  int timeDim = -1, latDim = -1, lonDim = -1;
  check(nc_def_dim(id, "valid_time", 1, &timeDim), file);
  check(nc_def_dim(id, "latitude", static_cast<std::size_t>(rows), &latDim), file);
  check(nc_def_dim(id, "longitude", static_cast<std::size_t>(columns), &lonDim), file);
  int timeVar = -1, latVar = -1, lonVar = -1;
  check(nc_def_var(id, "valid_time", NC_DOUBLE, 1, &timeDim, &timeVar), file);
  text(id, timeVar, "units", "seconds since 1970-01-01", file);
  text(id, timeVar, "calendar", "proleptic_gregorian", file);
  check(nc_def_var(id, "latitude", NC_DOUBLE, 1, &latDim, &latVar), file);
  text(id, latVar, "units", "degrees_north", file);
  text(id, latVar, "standard_name", "latitude", file);
  check(nc_def_var(id, "longitude", NC_DOUBLE, 1, &lonDim, &lonVar), file);
  text(id, lonVar, "units", "degrees_east", file);
  text(id, lonVar, "standard_name", "longitude", file);

  constexpr double kScale = 0.001;  // ±32.7 m/s in shorts
  constexpr short kFill = -32767;
  const std::array<int, 3> dims{timeDim, latDim, lonDim};
  std::array<int, 2> vars{};
  for (std::size_t k = 0; k < 2; ++k) {
    const char* name = k == 0 ? "u10" : "v10";
    check(nc_def_var(id, name, NC_SHORT, 3, dims.data(), &vars[k]), file);
    if (format == SyntheticFormat::kNetcdf4Deflate) {
      const std::array<std::size_t, 3> chunks{1, static_cast<std::size_t>(rows),
                                              static_cast<std::size_t>(columns)};
      check(nc_def_var_chunking(id, vars[k], NC_CHUNKED, chunks.data()), file);
      check(nc_def_var_deflate(id, vars[k], 1, 1, 1), file);
    }
    const double scale = kScale, offset = 0.0;
    check(nc_put_att_double(id, vars[k], "scale_factor", NC_DOUBLE, 1, &scale), file);
    check(nc_put_att_double(id, vars[k], "add_offset", NC_DOUBLE, 1, &offset), file);
    if (format == SyntheticFormat::kNetcdf4Deflate)
      check(nc_def_var_fill(id, vars[k], NC_FILL, &kFill), file);
    else
      check(nc_put_att_short(id, vars[k], "_FillValue", NC_SHORT, 1, &kFill), file);
    text(id, vars[k], "units", "m s**-1", file);
    text(id, vars[k], "long_name",
         k == 0 ? "10 metre U wind component" : "10 metre V wind component", file);
  }
  check(nc_enddef(id), file);

  const double time = 1718841600.0;  // 2024-06-20T00:00:00Z
  check(nc_put_var_double(id, timeVar, &time), file);
  std::vector<double> lat(static_cast<std::size_t>(rows)), lon(static_cast<std::size_t>(columns));
  for (int r = 0; r < rows; ++r) lat[static_cast<std::size_t>(r)] = 90.0 - dLat * r;
  for (int c = 0; c < columns; ++c) lon[static_cast<std::size_t>(c)] = dLon * c;
  check(nc_put_var_double(id, latVar, lat.data()), file);
  check(nc_put_var_double(id, lonVar, lon.data()), file);

  // Trade winds and westerlies by latitude, with waves in longitude.
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  std::vector<short> packed(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
  for (std::size_t k = 0; k < 2; ++k) {
    std::size_t i = 0;
    for (int r = 0; r < rows; ++r) {
      const double phi = lat[static_cast<std::size_t>(r)] * kRad;
      for (int c = 0; c < columns; ++c, ++i) {
        const double lambda = lon[static_cast<std::size_t>(c)] * kRad;
        const double value = k == 0
                                 ? -8.0 * std::cos(3.0 * phi) + 2.0 * std::sin(4.0 * lambda)
                                 : 3.0 * std::sin(2.0 * phi) * std::cos(3.0 * lambda + phi);
        packed[i] = static_cast<short>(std::lround(value / kScale));
      }
    }
    check(nc_put_var_short(id, vars[k], packed.data()), file);
  }
  const int status = nc_close(id);
  id = -1;
  check(status, file);
}

}  // namespace og::data
