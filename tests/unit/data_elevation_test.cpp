// Elevation/NetCDF reader and LatLonGrid sampling. Fixture files are written here with
// netCDF-C into OG_TEST_OUT_DIR, so the odd layouts real files have (ERA5-style packing,
// descending latitude, 0..360 longitude, seam columns) and malformed files are all covered
// without committing binaries.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/GridLayout.hpp"
#include "data/LatLonGrid.hpp"
#include "support/DataFixtures.hpp"
#include "support/ExpectError.hpp"

namespace fs = std::filesystem;
using og::data::LatLonGrid;

namespace {

fs::path outDir() { return og::test::fixtureDir("data_elevation"); }

using og::test::NcWriter;
using og::test::expectInputError;

/// Field value used by the fixtures: distinct everywhere, metres.
double relief(double latDeg, double lonDeg) { return 100.0 * latDeg + lonDeg; }

/// Values in file order for the given axes.
std::vector<double> fieldValues(const std::vector<double>& lat, const std::vector<double>& lon,
                                const std::function<double(double, double)>& f = relief) {
  std::vector<double> values;
  for (double la : lat)
    for (double lo : lon) values.push_back(f(la, lo));
  return values;
}

/// Writes a plain float field `z` on ascending lat/lon axes; `edit` may add to the header.
fs::path writeSimple(const std::string& name, const std::vector<double>& lat,
                     const std::vector<double>& lon, const std::vector<double>& values,
                     nc_type type = NC_FLOAT, int mode = NC_CLASSIC_MODEL | NC_NETCDF4,
                     const std::function<void(NcWriter&, int)>& edit = {}) {
  const fs::path file = outDir() / name;
  NcWriter nc(file, mode);
  nc.axis("lat", lat, "degrees_north");
  nc.axis("lon", lon, "degrees_east");
  const int z = nc.var("z", type, {0, 1});
  if (edit) edit(nc, z);
  nc.data({{z, values}});
  nc.close();
  return file;
}


std::string readAll(const fs::path& file) {
  std::string bytes(static_cast<std::size_t>(fs::file_size(file)), '\0');
  std::ifstream in(file, std::ios::binary);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

/// ERA5-like: packed shorts with scale/offset, _FillValue and missing_value, a valid_time
/// axis of length 1, latitude 90..-90 descending, longitude 0..315 (eight 45° columns).
fs::path writeEra5Like(const std::string& name, int mode) {
  const fs::path file = outDir() / name;
  NcWriter nc(file, mode);
  const int time = nc.dim("valid_time", 1);
  const int tv = nc.var("valid_time", NC_INT64, {time});
  nc.text(tv, "units", "seconds since 1970-01-01");
  const int lat = nc.axis("latitude", og::test::steps(90.0, -45.0, 5), "degrees_north", NC_FLOAT).second;
  nc.text(lat, "standard_name", "latitude");
  nc.axis("longitude", og::test::steps(0.0, 45.0, 8), "degrees_east", NC_FLOAT);
  const int z = nc.var("z", NC_SHORT, {time, 1, 2});
  nc.number(z, "scale_factor", NC_DOUBLE, 0.5);
  nc.number(z, "add_offset", NC_DOUBLE, 1000.0);
  nc.number(z, "_FillValue", NC_SHORT, -32767);
  nc.number(z, "missing_value", NC_SHORT, -32767);
  nc.text(z, "units", "m");
  std::vector<double> packed;
  for (double la : og::test::steps(90.0, -45.0, 5))
    for (double lo : og::test::steps(0.0, 45.0, 8)) packed.push_back((relief(la, lo) - 1000.0) / 0.5);
  packed[2 * 8 + 3] = -32767;  // latitude 0, longitude 135: no data
  nc.data({{z, packed}, {tv, {1.7e9}}});
  nc.close();
  return file;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Files that must load

TEST(DataElevation, Era5LikePackedDescendingLatitudeLoads) {
  {
    const fs::path file = writeEra5Like("era5_like.nc", NC_NETCDF4);
    const LatLonGrid grid = og::data::readElevationFile(file);
    EXPECT_EQ(grid.name, "z");
    EXPECT_EQ(grid.units, "m");
    ASSERT_EQ(grid.width, 8);
    ASSERT_EQ(grid.height, 5);
    EXPECT_DOUBLE_EQ(grid.lat0Deg, -90.0);
    EXPECT_DOUBLE_EQ(grid.dLatDeg, 45.0);
    EXPECT_DOUBLE_EQ(grid.lon0Deg, 0.0);
    EXPECT_DOUBLE_EQ(grid.dLonDeg, 45.0);
    EXPECT_TRUE(grid.wrapsLongitude);
    // Row 0 is the south pole after the flip; values unpacked exactly (0.5 m steps).
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 8; ++c) {
        const double la = -90.0 + 45.0 * r;
        const double lo = 45.0 * c;
        if (r == 2 && c == 3) {
          EXPECT_TRUE(std::isnan(grid.at(c, r)));
        } else {
          EXPECT_FLOAT_EQ(grid.at(c, r), static_cast<float>(relief(la, lo))) << r << "," << c;
        }
      }
    // Samples: on a cell centre, between centres, across the 315 -> 360 seam, by -180..180.
    EXPECT_FLOAT_EQ(grid.sample(45.0, 90.0), static_cast<float>(relief(45.0, 90.0)));
    EXPECT_FLOAT_EQ(grid.sample(22.5, 67.5), static_cast<float>(relief(22.5, 67.5)));
    const float seam = static_cast<float>((relief(45.0, 315.0) + relief(45.0, 0.0)) / 2.0);
    EXPECT_FLOAT_EQ(grid.sample(45.0, 337.5), seam);
    EXPECT_FLOAT_EQ(grid.sample(45.0, -22.5), seam);
    EXPECT_FLOAT_EQ(grid.sample(45.0, 337.5 + 720.0), seam);
    // Any neighbour without data gives NaN; cells away from it do not.
    EXPECT_TRUE(std::isnan(grid.sample(10.0, 120.0)));
    EXPECT_FALSE(std::isnan(grid.sample(10.0, 200.0)));
  }
}

TEST(DataElevation, MemoryImageMatchesFile) {
  const fs::path file = writeEra5Like("era5_memory.nc", NC_NETCDF4);
  const LatLonGrid fromFile = og::data::readElevationFile(file);
  const std::string bytes = readAll(file);
  const LatLonGrid fromMemory = og::data::readElevationMemory(bytes, "era5 in memory");
  EXPECT_EQ(fromMemory.width, fromFile.width);
  EXPECT_EQ(fromMemory.height, fromFile.height);
  ASSERT_EQ(fromMemory.values.size(), fromFile.values.size());
  for (std::size_t i = 0; i < fromFile.values.size(); ++i)
    if (!std::isnan(fromFile.values[i])) {
      EXPECT_EQ(fromMemory.values[i], fromFile.values[i]);
    }
  expectInputError("garbage", "not a readable NetCDF",
                   [] { (void)og::data::readElevationMemory("garbage bytes", "garbage"); });
  expectInputError("nothing", "empty", [] { (void)og::data::readElevationMemory({}, "nothing"); });
}

TEST(DataElevation, ClassicFileWithSeamColumnAndSignedLongitudes) {
  // -180..180 inclusive: the last column repeats the first and must be dropped.
  const auto lat = og::test::steps(-45.0, 30.0, 4);
  const auto lon = og::test::steps(-180.0, 45.0, 9);
  const fs::path file = writeSimple(
      "seam.nc", lat, lon,
      fieldValues(lat, lon,
                  [](double la, double lo) { return relief(la, lo == 180.0 ? -180.0 : lo); }),
      NC_DOUBLE, NC_CLASSIC_MODEL);
  const LatLonGrid grid = og::data::readElevationFile(file);
  EXPECT_EQ(grid.width, 8);
  EXPECT_TRUE(grid.wrapsLongitude);
  EXPECT_DOUBLE_EQ(grid.lon0Deg, -180.0);
  EXPECT_FLOAT_EQ(grid.sample(0.0, 135.0), static_cast<float>(relief(0.0, 135.0)));
  EXPECT_FLOAT_EQ(grid.sample(0.0, 157.5),
                  static_cast<float>((relief(0.0, 135.0) + relief(0.0, -180.0)) / 2.0));
  // Not global (cells cover -60..60): NaN beyond half a cell past the outer rows, the outer
  // row's value within it.
  EXPECT_TRUE(std::isnan(grid.sample(61.0, 0.0)));
  EXPECT_TRUE(std::isnan(grid.sample(-80.0, 0.0)));
  EXPECT_FLOAT_EQ(grid.sample(55.0, 0.0), static_cast<float>(relief(45.0, 0.0)));
}

TEST(DataElevation, AxesFoundByStandardNameAndOddNamesAndDescendingLongitude) {
  const fs::path file = outDir() / "odd_axes.nc";
  const auto lat = og::test::steps(10.0, 1.0, 4);
  const auto lon = og::test::steps(25.0, -1.0, 6);  // descending: 25..20
  {
    NcWriter nc(file, NC_NETCDF4);
    const int y = nc.axis("YY", lat, "").second;
    nc.text(y, "standard_name", "latitude");
    const int x = nc.axis("XX", lon, "").second;
    nc.text(x, "standard_name", "longitude");
    const int t = nc.var("other", NC_FLOAT, {0});  // a 1-D field: never a candidate
    const int z = nc.var("foo", NC_INT, {0, 1});
    nc.data({{z, fieldValues(lat, lon)}, {t, {1, 2, 3, 4}}});
    nc.close();
  }
  const LatLonGrid grid = og::data::readElevationFile(file);
  EXPECT_EQ(grid.name, "foo");
  EXPECT_FALSE(grid.wrapsLongitude);
  EXPECT_DOUBLE_EQ(grid.lon0Deg, 20.0);
  EXPECT_FLOAT_EQ(grid.at(0, 0), static_cast<float>(relief(10.0, 20.0)));
  EXPECT_FLOAT_EQ(grid.at(5, 3), static_cast<float>(relief(13.0, 25.0)));
  EXPECT_FLOAT_EQ(grid.sample(11.5, 22.5), static_cast<float>(relief(11.5, 22.5)));
  EXPECT_FLOAT_EQ(grid.sample(11.5, 22.5 - 360.0), static_cast<float>(relief(11.5, 22.5)));
  EXPECT_TRUE(std::isnan(grid.sample(11.5, 30.0)));
  EXPECT_TRUE(std::isnan(grid.sample(11.5, 19.0)));
  EXPECT_FLOAT_EQ(grid.sample(11.5, 19.6), static_cast<float>(relief(11.5, 20.0)));
}

TEST(DataElevation, FillNanAndUnpackedMissingValue) {
  const auto lat = og::test::steps(0.0, 1.0, 3);
  const auto lon = og::test::steps(0.0, 1.0, 3);
  // Float field: NaN and the netCDF default fill count as no data.
  std::vector<double> values = fieldValues(lat, lon);
  values[0] = std::numeric_limits<double>::quiet_NaN();
  values[1] = static_cast<double>(9.9692099683868690e+36f);
  const LatLonGrid grid = og::data::readElevationFile(writeSimple("nan.nc", lat, lon, values));
  EXPECT_TRUE(std::isnan(grid.at(0, 0)));
  EXPECT_TRUE(std::isnan(grid.at(1, 0)));
  EXPECT_FLOAT_EQ(grid.at(2, 0), 2.0f);

  // Packed shorts with a float missing_value in unpacked units.
  std::vector<double> packed = {0, 1, 2, 3, 4, 5, 6, 7, -9000};  // unpacked: -10 m .. ; -9999
  const fs::path file = writeSimple("unpacked_missing.nc", lat, lon, packed, NC_SHORT, NC_NETCDF4,
                                    [](NcWriter& nc, int z) {
                                      nc.number(z, "scale_factor", NC_FLOAT, 0.1);
                                      nc.number(z, "add_offset", NC_FLOAT, -9099.0);
                                      nc.number(z, "missing_value", NC_FLOAT, -9999.0);
                                    });
  const LatLonGrid p = og::data::readElevationFile(file);
  EXPECT_NEAR(p.at(1, 0), -9098.9f, 1e-3f);
  EXPECT_TRUE(std::isnan(p.at(2, 2)));
}

TEST(DataElevation, ConcurrentReadsAreSerialisedSafely) {
  // netCDF-C is not thread-safe; the reader must serialise access itself.
  const fs::path file = writeEra5Like("era5_threads.nc", NC_NETCDF4);
  const std::string bytes = readAll(file);
  std::vector<int> widths(8, 0);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < widths.size(); ++i)
    threads.emplace_back([&, i] {
      widths[i] = i % 3 == 0   ? og::data::defaultElevation().width
                  : i % 3 == 1 ? og::data::readElevationFile(file).width
                               : og::data::readElevationMemory(bytes, "mem").width;
    });
  for (auto& t : threads) t.join();
  for (std::size_t i = 0; i < widths.size(); ++i) EXPECT_EQ(widths[i], i % 3 == 0 ? 4320 : 8);
}

// ---------------------------------------------------------------------------------------------
// Files that must be refused with "FILE: problem"

TEST(DataElevation, HeightsOutsideEarthsReliefAreRejected) {
  // An undeclared fill value and heights in the wrong units are refused, not drawn (the
  // terrain's detail, culling and bounds assume Earth's relief).
  const auto lat = og::test::steps(0.0, 1.0, 3);
  const auto lon = og::test::steps(0.0, 1.0, 3);
  std::vector<double> values = fieldValues(lat, lon);
  values[4] = -32768.0;
  const fs::path fill = writeSimple("undeclared_fill.nc", lat, lon, values);
  expectInputError(fill.string(), "-32768 m at latitude 1, longitude 1, outside Earth's relief",
                   [&] { (void)og::data::readElevationFile(fill); });
  const fs::path km = writeSimple("km_as_m.nc", lat, lon, std::vector<double>(9, 12.0), NC_FLOAT,
                                  NC_NETCDF4, [](NcWriter& nc, int z) { nc.text(z, "units", "km"); });
  expectInputError(km.string(), "12000 m", [&] { (void)og::data::readElevationFile(km); });
  // Everest and the Challenger Deep are fine.
  const fs::path earth = writeSimple("extremes.nc", lat, lon,
                                     {8849, -10994, 0, 1, 2, 3, 4, 5, 6});
  EXPECT_NO_THROW((void)og::data::readElevationFile(earth));
}

TEST(DataElevation, NonMonotonicLatitudeIsRejected) {
  const std::vector<double> lat = {0.0, 1.0, 3.0, 2.0};
  const auto lon = og::test::steps(0.0, 1.0, 4);
  const fs::path file = writeSimple("nonmonotonic.nc", lat, lon, fieldValues(lat, lon));
  expectInputError(file.string(), "not strictly monotonic",
                   [&] { (void)og::data::readElevationFile(file); });
}

TEST(DataElevation, IrregularLatitudeIsRejected) {
  const std::vector<double> lat = {-80.0, -40.0, 0.0, 41.0, 80.0};  // Gaussian-like
  const auto lon = og::test::steps(0.0, 90.0, 4);
  const fs::path file = writeSimple("irregular.nc", lat, lon, fieldValues(lat, lon));
  expectInputError(file.string(), "not regularly spaced",
                   [&] { (void)og::data::readElevationFile(file); });
}

TEST(DataElevation, AllFillIsRejected) {
  const auto lat = og::test::steps(0.0, 1.0, 3);
  const auto lon = og::test::steps(0.0, 1.0, 4);
  const fs::path file =
      writeSimple("all_fill.nc", lat, lon, std::vector<double>(12, -999.0), NC_FLOAT, NC_NETCDF4,
                  [](NcWriter& nc, int z) { nc.number(z, "_FillValue", NC_FLOAT, -999.0); });
  expectInputError(file.string(), "holds no data",
                   [&] { (void)og::data::readElevationFile(file); });
}

TEST(DataElevation, CharVariableIsRejected) {
  const fs::path file = outDir() / "char_field.nc";
  {
    NcWriter nc(file, NC_CLASSIC_MODEL);
    nc.axis("lat", og::test::steps(0.0, 1.0, 2), "degrees_north");
    nc.axis("lon", og::test::steps(0.0, 1.0, 3), "degrees_east");
    const int z = nc.var("z", NC_CHAR, {0, 1});
    nc.noFill(z);
    nc.data({});
    nc.close();
  }
  expectInputError(file.string(), "has type char",
                   [&] { (void)og::data::readElevationFile(file); });
  expectInputError(file.string(), "has type char",
                   [&] { (void)og::data::readElevationFile(file, "z"); });
}

TEST(DataElevation, NonFiniteValueIsRejected) {
  const auto lat = og::test::steps(0.0, 1.0, 2);
  const auto lon = og::test::steps(0.0, 1.0, 2);
  for (const double bad : {std::numeric_limits<double>::infinity(), 1e300}) {
    const std::vector<double> values = {1.0, bad, 2.0, 3.0};
    const fs::path file = writeSimple("infinite.nc", lat, lon, values, NC_DOUBLE);
    expectInputError(file.string(), "non-finite or out-of-range",
                     [&] { (void)og::data::readElevationFile(file); });
  }
}

TEST(DataElevation, TruncatedFilesAreRejected) {
  const auto lat = og::test::steps(-45.0, 1.0, 50);
  const auto lon = og::test::steps(0.0, 1.0, 60);
  for (const int mode : {NC_CLASSIC_MODEL, NC_NETCDF4}) {
    SCOPED_TRACE(mode);
    const std::string name = mode == NC_NETCDF4 ? "truncated4.nc" : "truncated3.nc";
    const fs::path file = writeSimple(name, lat, lon, fieldValues(lat, lon), NC_DOUBLE, mode);
    const auto size = fs::file_size(file);
    EXPECT_NO_THROW((void)og::data::readElevationFile(file));
    fs::resize_file(file, size - 8);  // one double short
    expectInputError(file.string(), "", [&] { (void)og::data::readElevationFile(file); });
    fs::resize_file(file, size / 2);
    expectInputError(file.string(), "", [&] { (void)og::data::readElevationFile(file); });
    const std::string bytes = readAll(file);
    expectInputError("image", "", [&] { (void)og::data::readElevationMemory(bytes, "image"); });
  }
}

TEST(DataElevation, NonNetcdfAndMissingFilesAreRejected) {
  const fs::path text = outDir() / "notes.nc";
  {
    std::ofstream out(text);
    out << "netcdf? no, just text\n";
  }
  expectInputError(text.string(), "not a readable NetCDF or GRIB file",
                   [&] { (void)og::data::readElevationFile(text); });
  const fs::path missing = outDir() / "absent.nc";
  expectInputError(missing.string(), "no such file",
                   [&] { (void)og::data::readElevationFile(missing); });
}

TEST(DataElevation, SeveralTimeStepsAreRejected) {
  const fs::path file = outDir() / "three_steps.nc";
  const auto lat = og::test::steps(0.0, 1.0, 2);
  const auto lon = og::test::steps(0.0, 1.0, 2);
  {
    NcWriter nc(file, NC_NETCDF4);
    const int time = nc.dim("time", 3);
    const int latDim = nc.dim("lat", 2);
    const int lonDim = nc.dim("lon", 2);
    const int la = nc.var("lat", NC_DOUBLE, {latDim});
    nc.text(la, "units", "degrees_north");
    const int lo = nc.var("lon", NC_DOUBLE, {lonDim});
    nc.text(lo, "units", "degrees_east");
    const int z = nc.var("z", NC_FLOAT, {time, latDim, lonDim});
    nc.data({{la, lat}, {lo, lon}, {z, std::vector<double>(12, 1.0)}});
    nc.close();
  }
  expectInputError(file.string(), "3 steps along 'time'",
                   [&] { (void)og::data::readElevationFile(file); });
}

TEST(DataElevation, VariableSelection) {
  const auto lat = og::test::steps(0.0, 1.0, 2);
  const auto lon = og::test::steps(0.0, 1.0, 2);
  const auto write = [&](const std::string& name, const std::vector<std::string>& fields) {
    const fs::path file = outDir() / name;
    NcWriter nc(file, NC_NETCDF4);
    nc.axis("lat", lat, "degrees_north");
    nc.axis("lon", lon, "degrees_east");
    std::vector<std::pair<int, std::vector<double>>> data;
    double value = 1.0;
    for (const auto& f : fields) {
      data.emplace_back(nc.var(f, NC_FLOAT, {0, 1}), std::vector<double>(4, value));
      value += 1.0;
    }
    nc.data(data);
    nc.close();
    return file;
  };
  const fs::path named = write("two_fields_named.nc", {"foo", "topo", "elevation"});
  EXPECT_EQ(og::data::readElevationFile(named).name, "elevation");  // earlier in the list
  EXPECT_EQ(og::data::readElevationFile(named, "foo").name, "foo");
  EXPECT_FLOAT_EQ(og::data::readElevationFile(named, "foo").at(0, 0), 1.0f);
  expectInputError(named.string(), "no variable 'bar'",
                   [&] { (void)og::data::readElevationFile(named, "bar"); });
  expectInputError(named.string(), "not a field on (latitude, longitude)",
                   [&] { (void)og::data::readElevationFile(named, "lat"); });
  const fs::path ambiguous = write("two_fields.nc", {"foo", "bar"});
  expectInputError(ambiguous.string(), "several fields",
                   [&] { (void)og::data::readElevationFile(ambiguous); });

  const fs::path transposed = outDir() / "transposed.nc";
  {
    NcWriter nc(transposed, NC_NETCDF4);
    nc.axis("lat", lat, "degrees_north");
    nc.axis("lon", lon, "degrees_east");
    const int z = nc.var("z", NC_FLOAT, {1, 0});
    nc.data({{z, std::vector<double>(4, 1.0)}});
    nc.close();
  }
  expectInputError(transposed.string(), "(longitude, latitude)",
                   [&] { (void)og::data::readElevationFile(transposed); });

  const fs::path noAxes = outDir() / "no_axes.nc";
  {
    NcWriter nc(noAxes, NC_NETCDF4);
    nc.axis("lat", lat, "degrees");  // not a CF latitude unit: no axis
    nc.axis("lon", lon, "degrees_east");
    const int z = nc.var("z", NC_FLOAT, {0, 1});
    nc.data({{z, std::vector<double>(4, 1.0)}});
    nc.close();
  }
  expectInputError(noAxes.string(), "no latitude axis",
                   [&] { (void)og::data::readElevationFile(noAxes); });
}

// ---------------------------------------------------------------------------------------------
// Shape and axis validation without files (sizes netCDF cannot fake cheaply)

TEST(DataGridLayout, ShapeLimits) {
  using og::data::detail::checkGridShape;
  EXPECT_NO_THROW(checkGridShape("f", 2, 2));
  EXPECT_NO_THROW(checkGridShape("f", 20000, 20000));  // exactly 400 million cells
  expectInputError("f", "latitude axis has 1 values", [] { checkGridShape("f", 1, 10); });
  expectInputError("f", "longitude axis has 0", [] { checkGridShape("f", 10, 0); });
  expectInputError("f", "100001", [] { checkGridShape("f", 100001, 10); });
  expectInputError("f", "exceeds the limit", [] { checkGridShape("f", 20000, 20001); });
  expectInputError("f", "exceeds the limit", [] { checkGridShape("f", 100000, 100000); });
  const std::size_t huge = std::numeric_limits<std::size_t>::max();
  expectInputError("f", "latitude axis", [&] { checkGridShape("f", huge, huge); });
}

TEST(DataGridLayout, AxisValidation) {
  using og::data::detail::planGridLayout;
  const auto plan = [](const std::vector<double>& lat, const std::vector<double>& lon,
                       bool isFloat = false) {
    return planGridLayout("f", lat, "lat", isFloat, lon, "lon", isFloat);
  };
  const auto lon = og::test::steps(0.0, 1.0, 4);
  expectInputError("f", "outside [-90, 90]", [&] { (void)plan(og::test::steps(-95.0, 5.0, 5), lon); });
  expectInputError("f", "non-finite", [&] {
    (void)plan({0.0, std::numeric_limits<double>::quiet_NaN(), 2.0}, lon);
  });
  expectInputError("f", "not strictly monotonic", [&] { (void)plan({0.0, 1.0, 1.0}, lon); });
  expectInputError("f", "more than 360", [&] { (void)plan({0.0, 1.0}, og::test::steps(0.0, 10.0, 40)); });

  // 0.01° float-stored longitudes near 360 carry rounding of ~1e-3 of a step: accepted.
  std::vector<double> fine;
  for (int i = 0; i < 1000; ++i)
    fine.push_back(static_cast<double>(static_cast<float>(350.0 + 0.01 * i)));
  EXPECT_NO_THROW((void)plan({0.0, 1.0}, fine, true));

  // Longitudes starting anywhere: 20..380 with a seam (the ETOPO20 layout).
  const auto layout = plan(og::test::steps(-89.75, 0.5, 360), og::test::steps(20.25, 0.5, 721));
  EXPECT_TRUE(layout.dropSeam);
  EXPECT_EQ(layout.width, 720);
  EXPECT_TRUE(layout.wrapsLongitude);
  EXPECT_DOUBLE_EQ(layout.lon0Deg, 20.25);
  EXPECT_DOUBLE_EQ(layout.dLonDeg, 0.5);
  const auto shifted = plan({0.0, 1.0}, og::test::steps(-400.0, 1.0, 10));
  EXPECT_DOUBLE_EQ(shifted.lon0Deg, 320.0);
  EXPECT_FALSE(shifted.wrapsLongitude);
}

// ---------------------------------------------------------------------------------------------
// Sampling on hand-made grids

TEST(DataLatLonGrid, GlobalGridClampsToPolarRows) {
  LatLonGrid grid;
  grid.width = 4;
  grid.height = 3;
  grid.lon0Deg = 0.0;
  grid.dLonDeg = 90.0;
  grid.lat0Deg = -60.0;
  grid.dLatDeg = 60.0;
  grid.wrapsLongitude = true;
  grid.values = {0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23};
  EXPECT_FLOAT_EQ(grid.sample(-90.0, 0.0), 0.0f);
  EXPECT_FLOAT_EQ(grid.sample(90.0, 90.0), 21.0f);
  EXPECT_FLOAT_EQ(grid.sample(89.9, 315.0), 21.5f);  // between column 3 and column 0
  EXPECT_FLOAT_EQ(grid.sample(0.0, 45.0), 10.5f);
  EXPECT_FLOAT_EQ(grid.sample(-30.0, 0.0), 5.0f);
  EXPECT_TRUE(std::isnan(grid.sample(std::numeric_limits<double>::quiet_NaN(), 0.0)));
  grid.values[5] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isnan(grid.sample(0.0, 45.0)));
  EXPECT_FLOAT_EQ(grid.sample(0.0, 225.0), 12.5f);
}

// ---------------------------------------------------------------------------------------------
// Real data

TEST(DataElevation, DefaultElevationIsEtopo5AtFiveArcMinutes) {
  // data/etopo5_relief.nc: ETOPO5 on its own 5' grid, 4320 columns (wrapping) x 2161 rows from
  // pole to pole (data/README.md).
  const LatLonGrid& grid = og::data::defaultElevation();
  EXPECT_EQ(&grid, &og::data::defaultElevation());  // parsed once
  EXPECT_EQ(grid.name, "ROSE");
  EXPECT_EQ(grid.width, 4320);
  EXPECT_EQ(grid.height, 2161);
  EXPECT_TRUE(grid.wrapsLongitude);
  EXPECT_NEAR(grid.dLonDeg, 1.0 / 12.0, 1e-9);
  EXPECT_NEAR(grid.dLatDeg, 1.0 / 12.0, 1e-9);
  const auto [lo, hi] = std::minmax_element(grid.values.begin(), grid.values.end());
  EXPECT_GE(*lo, -11000.0f);
  EXPECT_LE(*hi, 9000.0f);
  EXPECT_TRUE(
      std::none_of(grid.values.begin(), grid.values.end(), [](float v) { return std::isnan(v); }));
  EXPECT_GT(grid.sample(27.99, 86.93), 5000.0f);  // Everest massif (5' cells)
  EXPECT_LT(grid.sample(0.0, -150.0), -3000.0f);  // central Pacific
  EXPECT_GT(grid.sample(23.0, 10.0), 0.0f);       // Sahara
  EXPECT_LT(grid.sample(-89.9, 0.0), 4500.0f);    // Antarctic plateau, clamped row
  EXPECT_GT(grid.sample(-89.9, 0.0), 1500.0f);
  EXPECT_LT(grid.sample(89.9, 0.0), 0.0f);  // Arctic Ocean
  // Longitude wraps across the file's own seam at 0°E/360°E and the antimeridian.
  EXPECT_FLOAT_EQ(grid.sample(10.0, 20.0), grid.sample(10.0, 380.0));
  EXPECT_FLOAT_EQ(grid.sample(-10.0, 180.0), grid.sample(-10.0, -180.0));
}

TEST(DataElevation, Etopo5FromFerretDatasets) {
  const fs::path file = "/usr/share/ferret-vis/data/etopo5.cdf";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not installed (package ferret-datasets)";
  const LatLonGrid grid = og::data::readElevationFile(file);
  EXPECT_EQ(grid.name, "ROSE");
  EXPECT_EQ(grid.width, 4320);
  EXPECT_EQ(grid.height, 2161);
  EXPECT_TRUE(grid.wrapsLongitude);
  EXPECT_GT(grid.sample(27.99, 86.93), 5000.0f);
  EXPECT_LT(grid.sample(11.35, 142.2), -8000.0f);  // Mariana Trench
  EXPECT_GT(grid.sample(23.0, 10.0), 0.0f);
  // The default relief agrees with its source to within what 20' averaging changes.
  const LatLonGrid& coarse = og::data::defaultElevation();
  EXPECT_NEAR(coarse.sample(40.0, -100.0), grid.sample(40.0, -100.0), 400.0f);
}
