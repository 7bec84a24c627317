#pragma once
// Writers for data-layer fixtures (NetCDF via netCDF-C, GRIB2 via ecCodes), shared by the unit
// and cli tiers: ERA5-style and GFS-style wind files are created by the tests, not committed.
// Any library error throws std::runtime_error.
#include <eccodes.h>
#include <netcdf.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace og::test {

/// Thin netCDF-C writer.
class NcWriter {
 public:
  NcWriter(const std::filesystem::path& file, int mode) : path_(file) {
    std::filesystem::remove(file);
    ok(nc_create(file.c_str(), mode | NC_CLOBBER, &id_));
  }
  ~NcWriter() {
    if (id_ >= 0) nc_close(id_);
  }
  NcWriter(const NcWriter&) = delete;
  NcWriter& operator=(const NcWriter&) = delete;

  int dim(const std::string& name, std::size_t length) {
    int d = -1;
    ok(nc_def_dim(id_, name.c_str(), length, &d));
    return d;
  }
  int var(const std::string& name, nc_type type, const std::vector<int>& dims) {
    int v = -1;
    ok(nc_def_var(id_, name.c_str(), type, static_cast<int>(dims.size()), dims.data(), &v));
    return v;
  }
  /// A coordinate variable on its own new dimension; returns {dimension, variable}.
  std::pair<int, int> axis(const std::string& name, const std::vector<double>& values,
                           const std::string& units, nc_type type = NC_DOUBLE) {
    const int d = dim(name, values.size());
    const int v = var(name, type, {d});
    if (!units.empty()) text(v, "units", units);
    pending_.emplace_back(v, values);
    return {d, v};
  }
  void text(int v, const std::string& name, const std::string& value) {
    ok(nc_put_att_text(id_, v, name.c_str(), value.size(), value.c_str()));
  }
  void number(int v, const std::string& name, nc_type type, double value) {
    ok(nc_put_att_double(id_, v, name.c_str(), type, 1, &value));
  }
  void values(int v, std::vector<double> data) { pending_.emplace_back(v, std::move(data)); }
  /// Queues several variables' values (written by close(), after the axes).
  void data(const std::vector<std::pair<int, std::vector<double>>>& fields) {
    for (const auto& [v, d] : fields) pending_.emplace_back(v, d);
  }
  /// No fill value: unwritten data stays whatever the file holds.
  void noFill(int v) { ok(nc_def_var_fill(id_, v, NC_NOFILL, nullptr)); }
  void close() {
    ok(nc_enddef(id_));
    for (const auto& [v, data] : pending_) ok(nc_put_var_double(id_, v, data.data()));
    ok(nc_close(id_));
    id_ = -1;
  }

 private:
  void ok(int status) const {
    if (status != NC_NOERR)
      throw std::runtime_error(path_.string() + ": netCDF: " + nc_strerror(status));
  }
  std::filesystem::path path_;
  int id_ = -1;
  std::vector<std::pair<int, std::vector<double>>> pending_;
};

/// A folder for a test group's fixture files under the build's test output (kept between tests).
inline std::filesystem::path fixtureDir(const std::string& group) {
  const std::filesystem::path dir = std::filesystem::path(OG_TEST_OUT_DIR) / group;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::vector<double> steps(double first, double step, int count) {
  std::vector<double> v(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) v[static_cast<std::size_t>(i)] = first + step * i;
  return v;
}

/// The synthetic wind of the fixtures, m/s, at time step `t`.
inline double fixtureU(double latDeg, double lonDeg, int t) {
  return 2.0 * t + latDeg / 30.0 + lonDeg / 100.0;
}
inline double fixtureV(double latDeg, double lonDeg, int t) {
  return -1.0 + lonDeg / 100.0 - latDeg / 60.0 - 0.5 * t;
}

/// A CF wind layer with a time axis, uniform in space: the test's own time coordinate.
struct TimedWind {
  std::vector<double> times;           ///< the time coordinate's values
  std::string units;                   ///< e.g. "hours since 2024-06-20 00:00:00"
  std::string calendar;                ///< the `calendar` attribute; none when empty
  std::string flagAttribute;           ///< an attribute set on the axis (e.g. "climatology")
  std::vector<double> eastMs;          ///< u at each time, m/s
  std::vector<double> northMs;         ///< v at each time, m/s (0 when empty)
  double gridStepDeg = 30.0;           ///< global grid: latitude -90..90, longitude 0..360-step
};

/// Writes `wind` as NetCDF-4 (time, lat, lon variables uwnd and vwnd) to `file`.
inline std::filesystem::path writeTimedWind(const std::filesystem::path& file, const TimedWind& wind) {
  NcWriter nc(file, NC_NETCDF4);
  const auto [td, tv] = nc.axis("time", wind.times, wind.units);
  if (!wind.calendar.empty()) nc.text(tv, "calendar", wind.calendar);
  if (!wind.flagAttribute.empty()) nc.text(tv, wind.flagAttribute, "climatology_bounds");
  const int rows = static_cast<int>(std::lround(180.0 / wind.gridStepDeg)) + 1;
  const int columns = static_cast<int>(std::lround(360.0 / wind.gridStepDeg));
  const auto lat = steps(-90.0, wind.gridStepDeg, rows);
  const auto lon = steps(0.0, wind.gridStepDeg, columns);
  const auto [latD, latV] = nc.axis("lat", lat, "degrees_north");
  const auto [lonD, lonV] = nc.axis("lon", lon, "degrees_east");
  for (const char* n : {"uwnd", "vwnd"}) {
    const int v = nc.var(n, NC_FLOAT, {td, latD, lonD});
    nc.text(v, "units", "m/s");
    std::vector<double> values;
    for (std::size_t t = 0; t < wind.times.size(); ++t) {
      const double value = n[0] == 'u' ? wind.eastMs.at(t) : wind.northMs.empty() ? 0.0 : wind.northMs.at(t);
      values.insert(values.end(), lat.size() * lon.size(), value);
    }
    nc.values(v, values);
  }
  nc.close();
  return file;
}

/// ERA5-style: u10/v10 packed shorts (scale 0.001, offset 1), _FillValue -32767 at (lat 0,
/// lon 90), latitude 90..-90 descending by 30, longitude 0..330 by 30 (no seam), valid_time
/// 2024-06-20T00/06/12Z as "seconds since 1970-01-01", proleptic_gregorian.
inline void writeEra5Wind(const std::filesystem::path& file, int mode = NC_NETCDF4) {
  NcWriter nc(file, mode);
  const double t0 = 1718841600.0;  // 2024-06-20T00:00:00Z
  const auto [td, tv] = nc.axis("valid_time", {t0, t0 + 21600.0, t0 + 43200.0},
                                "seconds since 1970-01-01",
                                mode == NC_CLASSIC_MODEL ? NC_DOUBLE : NC_INT64);
  nc.text(tv, "calendar", "proleptic_gregorian");
  nc.text(tv, "standard_name", "time");
  const auto lat = steps(90.0, -30.0, 7);
  const auto lon = steps(0.0, 30.0, 12);
  const auto [latD, latV] = nc.axis("latitude", lat, "degrees_north", NC_DOUBLE);
  nc.text(latV, "standard_name", "latitude");
  const auto [lonD, lonV] = nc.axis("longitude", lon, "degrees_east", NC_DOUBLE);
  nc.text(lonV, "standard_name", "longitude");
  for (const char* name : {"u10", "v10"}) {
    const bool isU = name[0] == 'u';
    const int v = nc.var(name, NC_SHORT, {td, latD, lonD});
    nc.number(v, "scale_factor", NC_DOUBLE, 0.001);
    nc.number(v, "add_offset", NC_DOUBLE, 1.0);
    nc.number(v, "_FillValue", NC_SHORT, -32767);
    nc.text(v, "units", "m s**-1");
    nc.text(v, "long_name", isU ? "10 metre U wind component" : "10 metre V wind component");
    std::vector<double> packed;
    for (int t = 0; t < 3; ++t)
      for (double la : lat)
        for (double lo : lon) {
          const bool hole = la == 0.0 && lo == 90.0;
          const double value = isU ? fixtureU(la, lo, t) : fixtureV(la, lo, t);
          packed.push_back(hole ? -32767.0 : std::round((value - 1.0) / 0.001));
        }
    nc.values(v, std::move(packed));
  }
  nc.close();
}

/// One GRIB2 message from ecCodes' regular_ll_sfc_grib2 sample, appended to `file`.
struct GribField {
  std::string shortName = "10u";
  long date = 20240620;  ///< YYYYMMDD
  long time = 0;         ///< HHMM
  long ni = 12;
  long nj = 7;
  double lat1 = 90.0, lon1 = 0.0, lat2 = -90.0, lon2 = 330.0;
  std::vector<double> values;  ///< ni·nj, rows of longitudes, first row at lat1
  bool bitmap = false;         ///< values equal to 9999 are missing
};

inline void appendGrib(const std::filesystem::path& file, const GribField& f) {
  codes_handle* h = codes_handle_new_from_samples(nullptr, "regular_ll_sfc_grib2");
  if (h == nullptr) throw std::runtime_error("ecCodes: no regular_ll_sfc_grib2 sample");
  const auto check = [&](int status, const char* what) {
    if (status != 0) {
      codes_handle_delete(h);
      throw std::runtime_error(std::string("ecCodes: setting ") + what + ": " +
                               codes_get_error_message(status));
    }
  };
  check(codes_set_long(h, "Ni", f.ni), "Ni");
  check(codes_set_long(h, "Nj", f.nj), "Nj");
  check(codes_set_double(h, "latitudeOfFirstGridPointInDegrees", f.lat1), "lat1");
  check(codes_set_double(h, "longitudeOfFirstGridPointInDegrees", f.lon1), "lon1");
  check(codes_set_double(h, "latitudeOfLastGridPointInDegrees", f.lat2), "lat2");
  check(codes_set_double(h, "longitudeOfLastGridPointInDegrees", f.lon2), "lon2");
  check(codes_set_double(h, "iDirectionIncrementInDegrees",
                         std::abs(f.lon2 - f.lon1) / static_cast<double>(f.ni - 1)),
        "di");
  check(codes_set_double(h, "jDirectionIncrementInDegrees",
                         std::abs(f.lat2 - f.lat1) / static_cast<double>(f.nj - 1)),
        "dj");
  check(codes_set_long(h, "jScansPositively", f.lat2 > f.lat1 ? 1 : 0), "jScansPositively");
  check(codes_set_string(h, "typeOfLevel", "heightAboveGround", nullptr), "typeOfLevel");
  check(codes_set_long(h, "level", 10), "level");
  std::size_t length = f.shortName.size();
  check(codes_set_string(h, "shortName", f.shortName.c_str(), &length), "shortName");
  check(codes_set_long(h, "dataDate", f.date), "dataDate");
  check(codes_set_long(h, "dataTime", f.time), "dataTime");
  if (f.bitmap) {
    check(codes_set_double(h, "missingValue", 9999.0), "missingValue");
    check(codes_set_long(h, "bitmapPresent", 1), "bitmapPresent");
  }
  check(codes_set_long(h, "bitsPerValue", 16), "bitsPerValue");
  check(codes_set_double_array(h, "values", f.values.data(), f.values.size()), "values");
  const void* message = nullptr;
  std::size_t size = 0;
  check(codes_get_message(h, &message, &size), "message");
  std::ofstream out(file, std::ios::binary | std::ios::app);
  out.write(static_cast<const char*>(message), static_cast<std::streamsize>(size));
  codes_handle_delete(h);
  if (!out) throw std::runtime_error(file.string() + ": write failed");
}

/// GFS-style: 10u/10v on a 30° global grid (latitude 90..-90, longitude 0..330), two
/// analysis times 2024-06-20T00Z and 06Z, the fixture wind; (lat 0, lon 90) missing.
inline void writeGfsWind(const std::filesystem::path& file) {
  std::filesystem::remove(file);
  for (int t = 0; t < 2; ++t)
    for (const char* name : {"10u", "10v"}) {
      GribField f;
      f.shortName = name;
      f.time = t * 600;
      f.bitmap = true;
      for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 12; ++i) {
          const double la = 90.0 - 30.0 * j;
          const double lo = 30.0 * i;
          const bool hole = la == 0.0 && lo == 90.0;
          f.values.push_back(hole ? 9999.0 : name[2] == 'u' ? fixtureU(la, lo, t) : fixtureV(la, lo, t));
        }
      appendGrib(file, f);
    }
}

}  // namespace og::test
