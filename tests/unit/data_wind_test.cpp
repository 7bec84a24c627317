// Wind layers: NetCDF and GRIB2 readers (axes, packing, fill, time axes, units), the layer
// stack's blending and rasterisation, CF time units, and the malformed-file corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "support/ExpectError.hpp"
#include "data/Elevation.hpp"
#include "data/GridFile.hpp"
#include "data/TimeAxis.hpp"
#include "data/WindField.hpp"
#include "data/WindLayers.hpp"
#include "support/DataFixtures.hpp"

namespace fs = std::filesystem;
using og::UtcTime;
using og::data::LatLonGrid;
using og::data::WindGrid;
using og::data::WindLayers;
using og::data::WindVector;
using og::test::expectInputError;
using og::test::fixtureU;
using og::test::fixtureV;
using og::test::NcWriter;
using og::test::steps;

namespace {

fs::path outDir() { return og::test::fixtureDir("data_wind"); }

UtcTime iso(const char* text) { return *UtcTime::parseIso8601(text); }


/// A simple wind file: `lat`, `lon` axes (as given), u/v named `uName`/`vName` with `units`,
/// values from the fixture wind at step 0; `edit` may add to the header.
fs::path writeWind(const std::string& name, const std::vector<double>& lat,
                   const std::vector<double>& lon, const std::string& uName = "u",
                   const std::string& vName = "v", const std::string& units = "m/s",
                   const std::function<void(NcWriter&, int, int)>& edit = {}) {
  const fs::path file = outDir() / name;
  NcWriter nc(file, NC_NETCDF4);
  const auto [latD, latV] = nc.axis("lat", lat, "degrees_north");
  const auto [lonD, lonV] = nc.axis("lon", lon, "degrees_east");
  const int u = nc.var(uName, NC_FLOAT, {latD, lonD});
  const int v = nc.var(vName, NC_FLOAT, {latD, lonD});
  if (!units.empty()) {
    nc.text(u, "units", units);
    nc.text(v, "units", units);
  }
  if (edit) edit(nc, u, v);
  std::vector<double> uv;
  std::vector<double> vv;
  for (double la : lat)
    for (double lo : lon) {
      uv.push_back(fixtureU(la, lo, 0));
      vv.push_back(fixtureV(la, lo, 0));
    }
  nc.values(u, uv);
  nc.values(v, vv);
  nc.close();
  return file;
}

/// A regional or global layer with constant wind over the given axes.
WindGrid constantLayer(const std::string& label, double lat0, double dLat, int rows, double lon0,
                       double dLon, int columns, double u, double v, bool wraps = false) {
  WindGrid g;
  g.label = label;
  LatLonGrid base;
  base.width = columns;
  base.height = rows;
  base.lat0Deg = lat0;
  base.dLatDeg = dLat;
  base.lon0Deg = lon0;
  base.dLonDeg = dLon;
  base.wrapsLongitude = wraps;
  g.u = base;
  g.v = base;
  g.u.values.assign(static_cast<std::size_t>(rows * columns), static_cast<float>(u));
  g.v.values.assign(static_cast<std::size_t>(rows * columns), static_cast<float>(v));
  return g;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Time axes

TEST(DataTimeAxis, CfUnits) {
  using og::data::detail::parseTimeUnits;
  const auto check = [](const char* units, double perUnit, const char* epoch) {
    SCOPED_TRACE(units);
    const auto u = parseTimeUnits(units);
    ASSERT_TRUE(u.has_value());
    EXPECT_DOUBLE_EQ(u->secondsPerUnit, perUnit);
    EXPECT_DOUBLE_EQ(u->epoch.unixSeconds, iso(epoch).unixSeconds);
  };
  check("hours since 1900-01-01 00:00:00.0", 3600.0, "1900-01-01T00:00Z");
  check("hour since 1980-01-14 14:00:00", 3600.0, "1980-01-14T14:00Z");
  check("seconds since 1970-01-01", 1.0, "1970-01-01T00:00Z");
  check("days since 1-1-1 0:0:0", 86400.0, "0001-01-01T00:00Z");
  check("minutes since 2024-06-20T12:00:00Z", 60.0, "2024-06-20T12:00Z");
  check("Hours Since 2000-01-01 06:00 +01:00", 3600.0, "2000-01-01T05:00Z");
  check("days since 2000-01-01 00:00:00 UTC", 86400.0, "2000-01-01T00:00Z");
  for (const char* bad : {"months since 2000-01-01", "hours after 2000-01-01", "hours since 2000-13-01",
                          "hours since 2001-02-29", "hours since 2000-01-01 25:00", "m/s", "",
                          "hours since 2000-01-01 junk"})
    EXPECT_FALSE(parseTimeUnits(bad).has_value()) << bad;
  EXPECT_TRUE(og::data::detail::isRealCalendar("proleptic_gregorian"));
  EXPECT_TRUE(og::data::detail::isRealCalendar("Gregorian"));
  EXPECT_TRUE(og::data::detail::isRealCalendar("standard"));
  EXPECT_FALSE(og::data::detail::isRealCalendar("noleap"));
  EXPECT_FALSE(og::data::detail::isRealCalendar("360_day"));
  const og::data::detail::TimeUnits hours{3600.0, iso("2000-01-01T00:00Z")};
  expectInputError("f", "not strictly increasing",
                   [&] { (void)og::data::detail::toInstants("f", "time", {0.0, 6.0, 6.0}, hours); });
  expectInputError("f", "unusable value", [&] {
    (void)og::data::detail::toInstants("f", "time", {0.0, 1e300}, hours);
  });
}

TEST(DataTimeAxis, StepChoice) {
  const std::vector<UtcTime> t = {iso("2024-06-20T00:00Z"), iso("2024-06-20T06:00Z"),
                                  iso("2024-06-20T12:00Z")};
  auto c = og::data::chooseSteps(t, std::nullopt);
  EXPECT_EQ(c.first, 0u);
  EXPECT_EQ(c.second, 0u);
  c = og::data::chooseSteps(t, iso("2024-06-19T00:00Z"));  // before: first step
  EXPECT_EQ(c.first, 0u);
  EXPECT_EQ(c.second, 0u);
  c = og::data::chooseSteps(t, iso("2024-06-21T00:00Z"));  // after: last step
  EXPECT_EQ(c.first, 2u);
  EXPECT_EQ(c.second, 2u);
  c = og::data::chooseSteps(t, iso("2024-06-20T09:00Z"));
  EXPECT_EQ(c.first, 1u);
  EXPECT_EQ(c.second, 2u);
  EXPECT_DOUBLE_EQ(c.weight, 0.5);
  c = og::data::chooseSteps(t, iso("2024-06-20T06:00Z"));  // exactly on a step
  EXPECT_EQ(c.first, 1u);
  EXPECT_EQ(c.second, 1u);
  EXPECT_EQ(og::data::chooseSteps({}, iso("2024-06-20T06:00Z")).first, 0u);
}

TEST(DataLayerSpec, Parsing) {
  auto s = og::data::parseLayerSpec("winds.nc");
  EXPECT_EQ(s.file, "winds.nc");
  EXPECT_TRUE(s.variables.empty());
  s = og::data::parseLayerSpec("dir/winds.nc:U,V");
  EXPECT_EQ(s.file, "dir/winds.nc");
  ASSERT_EQ(s.variables.size(), 2u);
  EXPECT_EQ(s.variables[1], "V");
  s = og::data::parseLayerSpec("relief.nc:ROSE");
  ASSERT_EQ(s.variables.size(), 1u);
  s = og::data::parseLayerSpec("a:b/winds.nc");  // the colon is part of a directory name
  EXPECT_EQ(s.file, "a:b/winds.nc");
  EXPECT_THROW((void)og::data::parseLayerSpec("winds.nc:U,"), og::InputError);
  EXPECT_THROW((void)og::data::parseLayerSpec(""), og::InputError);
  EXPECT_THROW((void)og::data::parseLayerSpec(":U,V"), og::InputError);
}

// ---------------------------------------------------------------------------------------------
// NetCDF wind files

TEST(DataWind, Era5StylePackedDescendingValidTimeInterpolated) {
  for (const int mode : {NC_NETCDF4, NC_CLASSIC_MODEL, NC_64BIT_DATA}) {
    SCOPED_TRACE(mode);
    const fs::path file = outDir() / ("era5_" + std::to_string(mode) + ".nc");
    og::test::writeEra5Wind(file, mode);
    const auto grid = og::data::openGridFile(file);
    const auto d = grid->describe("u10");
    ASSERT_EQ(d.times.size(), 3u);
    EXPECT_EQ(d.timeAxisName, "valid_time");
    EXPECT_EQ(d.times[1].toIso8601(), "2024-06-20T06:00:00Z");
    EXPECT_EQ(d.geometry.width, 12);
    EXPECT_TRUE(d.geometry.wrapsLongitude);
    EXPECT_DOUBLE_EQ(d.geometry.lat0Deg, -90.0);

    // Between steps 1 and 2, a quarter of the way: values interpolate linearly.
    const WindGrid w = og::data::readWind(*grid, {}, iso("2024-06-20T07:30Z"));
    EXPECT_EQ(w.u.name, "u10");
    EXPECT_EQ(w.v.name, "v10");
    ASSERT_TRUE(w.time.has_value());
    EXPECT_EQ(w.time->toIso8601(), "2024-06-20T07:30:00Z");
    EXPECT_NEAR(w.u.sample(30.0, 60.0), fixtureU(30.0, 60.0, 1) * 0.75 + fixtureU(30.0, 60.0, 2) * 0.25,
                2e-3);
    EXPECT_NEAR(w.v.sample(-60.0, 300.0), fixtureV(-60.0, 300.0, 1) * 0.75 + fixtureV(-60.0, 300.0, 2) * 0.25,
                2e-3);
    EXPECT_NEAR(w.u.sample(0.0, -60.0), fixtureU(0.0, 300.0, 1) * 0.75 + fixtureU(0.0, 300.0, 2) * 0.25,
                2e-3);  // -60° = 300°
    EXPECT_TRUE(std::isnan(w.u.at(3, 3)));  // lat 0 (row 3 from the south), lon 90 (column 3)
    // No time: the first step; after the end: the last.
    EXPECT_NEAR(og::data::readWind(*grid, {}, std::nullopt).u.sample(30.0, 60.0),
                fixtureU(30.0, 60.0, 0), 2e-3);
    EXPECT_NEAR(og::data::readWind(*grid, {}, iso("2030-01-01T00:00Z")).u.sample(30.0, 60.0),
                fixtureU(30.0, 60.0, 2), 2e-3);
  }
}

TEST(DataWind, VariablesByStandardNameNamesAndUser) {
  const auto lat = steps(-10.0, 5.0, 5);
  const auto lon = steps(-20.0, 5.0, 6);
  // standard_name wins over names.
  const fs::path standard = writeWind("standard.nc", lat, lon, "east", "north", "m s-1",
                                      [](NcWriter& nc, int u, int v) {
                                        nc.text(u, "standard_name", "eastward_wind");
                                        nc.text(v, "standard_name", "northward_wind");
                                      });
  auto w = og::data::readWindLayer(standard.string(), std::nullopt);
  EXPECT_EQ(w.u.name, "east");
  EXPECT_NEAR(w.u.sample(0.0, 0.0), fixtureU(0.0, 0.0, 0), 1e-5);
  for (const auto& [u, v] : std::vector<std::pair<std::string, std::string>>{
           {"UGRD", "VGRD"}, {"U10", "V10"}, {"uwnd", "vwnd"}, {"UWND", "VWND"}, {"uas", "vas"}}) {
    const fs::path file = writeWind("named_" + u + ".nc", lat, lon, u, v);
    w = og::data::readWindLayer(file.string(), std::nullopt);
    EXPECT_EQ(w.u.name, u);
    EXPECT_EQ(w.v.name, v);
  }
  // User-named, even swapped; one name only is refused; unknown names are refused.
  const fs::path odd = writeWind("odd.nc", lat, lon, "a", "b");
  expectInputError(odd.string(), "no wind components found among a, b",
                   [&] { (void)og::data::readWindLayer(odd.string(), std::nullopt); });
  w = og::data::readWindLayer(odd.string() + ":b,a", std::nullopt);
  EXPECT_EQ(w.u.name, "b");
  EXPECT_NEAR(w.u.sample(0.0, 0.0), fixtureV(0.0, 0.0, 0), 1e-5);
  expectInputError(odd.string(), "two variables",
                   [&] { (void)og::data::readWindLayer(odd.string() + ":a", std::nullopt); });
  expectInputError(odd.string(), "no variable 'c'",
                   [&] { (void)og::data::readWindLayer(odd.string() + ":a,c", std::nullopt); });
}

TEST(DataWind, UnitsKnotsConvertedUnknownRefused) {
  const auto lat = steps(-10.0, 5.0, 5);
  const auto lon = steps(0.0, 5.0, 6);
  const fs::path knots = writeWind("knots.nc", lat, lon, "u", "v", "knots");
  const WindGrid w = og::data::readWindLayer(knots.string(), std::nullopt);
  EXPECT_NEAR(w.u.sample(0.0, 10.0), fixtureU(0.0, 10.0, 0) * 1852.0 / 3600.0, 1e-5);
  const fs::path furlongs = writeWind("furlongs.nc", lat, lon, "u", "v", "furlongs/fortnight");
  expectInputError(furlongs.string(), "units 'furlongs/fortnight'",
                   [&] { (void)og::data::readWindLayer(furlongs.string(), std::nullopt); });
  const fs::path none = writeWind("no_units.nc", lat, lon, "u", "v", "");
  EXPECT_NO_THROW((void)og::data::readWindLayer(none.string(), std::nullopt));  // taken as m/s
  for (const char* u : {"m/s", "m s-1", "m s**-1", "M/S", "m.s-1", "meters/second", "m s^-1"})
    EXPECT_EQ(og::data::metresPerSecondPerUnit(u), 1.0) << u;
  EXPECT_FALSE(og::data::metresPerSecondPerUnit("K").has_value());
}

TEST(DataWind, LongitudeConventionsAndRegionalSubsets) {
  // -180..180 with a seam column, 0..360 starting at 20°E with a seam, and a regional subset.
  const auto lat = steps(-90.0, 30.0, 7);
  const fs::path signedLon = writeWind("signed.nc", lat, steps(-180.0, 30.0, 13));
  const fs::path from20 = writeWind("from20.nc", lat, steps(20.0, 30.0, 13));
  const fs::path regional = writeWind("regional.nc", steps(30.0, 1.0, 11), steps(-20.0, 1.0, 21));
  for (const fs::path& file : {signedLon, from20}) {
    SCOPED_TRACE(file.string());
    const WindGrid w = og::data::readWindLayer(file.string(), std::nullopt);
    EXPECT_EQ(w.u.width, 12);  // seam dropped
    EXPECT_TRUE(w.u.wrapsLongitude);
    const double lon = file == signedLon ? -150.0 : 50.0;
    EXPECT_NEAR(w.u.sample(30.0, lon), fixtureU(30.0, lon, 0), 1e-5);
    EXPECT_NEAR(w.u.sample(30.0, lon + 360.0), fixtureU(30.0, lon, 0), 1e-5);
  }
  const WindGrid r = og::data::readWindLayer(regional.string(), std::nullopt);
  EXPECT_FALSE(r.u.wrapsLongitude);
  EXPECT_NEAR(r.v.sample(35.0, -10.0), fixtureV(35.0, -10.0, 0), 1e-5);
  EXPECT_TRUE(std::isnan(r.u.sample(0.0, 0.0)));
}

TEST(DataWind, TimeAxisVariantsAndRefusals) {
  const auto lat = steps(0.0, 10.0, 3);
  const auto lon = steps(0.0, 10.0, 4);
  const auto write = [&](const std::string& name, const std::string& units,
                         const std::string& calendar, const std::vector<double>& times) {
    const fs::path file = outDir() / name;
    NcWriter nc(file, NC_NETCDF4);
    const auto [td, tv] = nc.axis("time", times, units);
    if (!calendar.empty()) nc.text(tv, "calendar", calendar);
    const auto [latD, latV] = nc.axis("lat", lat, "degrees_north");
    const auto [lonD, lonV] = nc.axis("lon", lon, "degrees_east");
    const auto [levD, levV] = nc.axis("height", {10.0}, "m");  // a single level is fine
    for (const char* n : {"uwnd", "vwnd"}) {
      const int v = nc.var(n, NC_FLOAT, {td, levD, latD, lonD});
      nc.text(v, "units", "m/s");
      std::vector<double> values;
      for (std::size_t t = 0; t < times.size(); ++t)
        for (std::size_t i = 0; i < lat.size() * lon.size(); ++i)
          values.push_back(10.0 * static_cast<double>(t));
      nc.values(v, values);
    }
    nc.close();
    return file;
  };
  const fs::path days = write("days.nc", "days since 2024-01-01", "gregorian", {0.0, 1.0});
  const WindGrid w = og::data::readWindLayer(days.string(), iso("2024-01-01T18:00Z"));
  EXPECT_NEAR(w.u.at(1, 1), 7.5f, 1e-5);
  // A model calendar: day 1 of a 365-day year is 366/365 real days into leap year 2024.
  const fs::path noleap = write("noleap.nc", "days since 2024-01-01", "noleap", {0.0, 1.0});
  EXPECT_NEAR(og::data::readWindLayer(noleap.string(), iso("2024-01-01T18:00Z")).u.at(1, 1),
              10.0 * 0.75 * 365.0 / 366.0, 1e-4);
  const fs::path none = write("none.nc", "days since 2024-01-01", "none", {0.0, 1.0});
  expectInputError(none.string(), "calendar 'none'",
                   [&] { (void)og::data::readWindLayer(none.string(), std::nullopt); });
  const fs::path months = write("months.nc", "months since 2024-01-01", "", {0.0, 1.0});
  expectInputError(months.string(), "only in calendar 360_day",
                   [&] { (void)og::data::readWindLayer(months.string(), std::nullopt); });
  const fs::path months360 = write("months360.nc", "months since 2024-01-01", "360_day", {0.0, 1.0});
  EXPECT_NEAR(og::data::readWindLayer(months360.string(), iso("2024-01-16T12:00Z")).u.at(1, 1),
              10.0 * 15.5 / (30.0 * 366.0 / 360.0), 1e-4);
  const fs::path backwards = write("backwards.nc", "hours since 2024-01-01", "", {6.0, 0.0});
  expectInputError(backwards.string(), "not strictly increasing",
                   [&] { (void)og::data::readWindLayer(backwards.string(), std::nullopt); });
}

// ---------------------------------------------------------------------------------------------
// GRIB2

TEST(DataWind, GfsStyleGrib2) {
  const fs::path file = outDir() / "gfs.grib2";
  og::test::writeGfsWind(file);
  const auto grid = og::data::openGridFile(file);
  EXPECT_EQ(grid->format(), "GRIB2");
  const auto fields = grid->fields();
  ASSERT_EQ(fields.size(), 2u);
  const auto d = grid->describe("10u");
  ASSERT_EQ(d.times.size(), 2u);
  EXPECT_EQ(d.times[1].toIso8601(), "2024-06-20T06:00:00Z");
  EXPECT_TRUE(d.geometry.wrapsLongitude);
  const WindGrid w = og::data::readWind(*grid, {}, iso("2024-06-20T03:00Z"));
  EXPECT_EQ(w.u.name, "10u");
  EXPECT_NEAR(w.u.sample(60.0, 240.0), 0.5 * (fixtureU(60.0, 240.0, 0) + fixtureU(60.0, 240.0, 1)),
              2e-3);
  EXPECT_NEAR(w.v.sample(-30.0, 30.0), 0.5 * (fixtureV(-30.0, 30.0, 0) + fixtureV(-30.0, 30.0, 1)),
              2e-3);
  EXPECT_TRUE(std::isnan(w.u.at(3, 3)));  // the bitmap's missing point

  // From memory, and as an elevation-style single field.
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto memory = og::data::openGridMemory(bytes, "gfs-memory");
  EXPECT_EQ(memory->describe("10v").times.size(), 2u);
}

TEST(DataWind, GribRegionalSouthToNorthAndCrossingZero) {
  const fs::path file = outDir() / "regional.grib2";
  fs::remove(file);
  for (const char* name : {"10u", "10v"}) {
    og::test::GribField f;
    f.shortName = name;
    f.ni = 9;
    f.nj = 5;
    f.lat1 = 40.0;
    f.lat2 = 44.0;
    f.lon1 = 356.0;  // crosses the prime meridian: 356..4
    f.lon2 = 4.0;
    for (int j = 0; j < f.nj; ++j)
      for (int i = 0; i < f.ni; ++i) f.values.push_back(name[2] == 'u' ? 40.0 + j : i - 4.0);
    og::test::appendGrib(file, f);
  }
  const WindGrid w = og::data::readWindLayer(file.string(), std::nullopt);
  EXPECT_FALSE(w.u.wrapsLongitude);
  EXPECT_NEAR(w.u.sample(42.0, 0.0), 42.0f, 1e-2);
  EXPECT_NEAR(w.v.sample(42.0, -2.0), -2.0f, 1e-2);
  EXPECT_NEAR(w.v.sample(43.0, 3.0), 3.0f, 1e-2);
  EXPECT_TRUE(w.time.has_value() == false || w.time->toIso8601() == "2024-06-20T00:00:00Z");
}

TEST(DataWind, GribGarbageTruncatedAndHostileLengthsAreRefused) {
  const fs::path good = outDir() / "good.grib2";
  og::test::writeGfsWind(good);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto refuse = [](const std::string& image, const std::string& label) {
    expectInputError(label, "", [&] {
      const auto g = og::data::openGridMemory(image, label);
      (void)og::data::readWind(*g, {}, std::nullopt);
    });
  };
  refuse(bytes.substr(0, bytes.size() / 3), "truncated");
  refuse(bytes.substr(0, 20), "header-only");
  refuse(std::string("GRIB") + std::string(200, '\x5a'), "garbage");
  std::string huge = "GRIB";
  huge += std::string("\0\0\0\2", 4);
  huge += std::string("\0\0\1\0\0\0\0\0", 8);  // 2^40 bytes
  huge += std::string(64, '\0');
  refuse(huge, "huge-length");
  std::string noTrailer = bytes.substr(0, bytes.size() / 4);
  refuse(noTrailer + std::string(1000, '\0'), "no-trailer");
  std::string corrupted = bytes;
  for (std::size_t i = 16; i < corrupted.size(); i += 7) corrupted[i] = static_cast<char>(i * 31);
  refuse(corrupted, "corrupted");
}

// ---------------------------------------------------------------------------------------------
// Layer stack

TEST(DataWindLayers, FallbackAndSpeedDirection) {
  const WindVector east = og::geo::Wind::blowingTowards(10.0, 90.0).vector();
  EXPECT_NEAR(east.uMs, 10.0, 1e-12);
  EXPECT_NEAR(east.vMs, 0.0, 1e-12);
  const WindVector north = og::geo::Wind::blowingTowards(4.0, 0.0).vector();
  EXPECT_NEAR(north.vMs, 4.0, 1e-12);
  const WindLayers none(east);
  EXPECT_DOUBLE_EQ(none.sample(12.0, 34.0).uMs, 10.0);
}

TEST(DataWindLayers, RegionalOverGlobalBlendsWithoutSeam) {
  WindLayers stack(WindVector{1.0, 1.0});
  stack.push(constantLayer("global", -90.0, 2.5, 73, 0.0, 2.5, 144, 5.0, -2.0, true));
  // Regional 1° layer, 30..50°N, 10°W..20°E, calm.
  stack.push(constantLayer("regional", 30.0, 1.0, 21, -10.0, 1.0, 31, 0.5, 0.25));
  EXPECT_NEAR(stack.sample(40.0, 5.0).uMs, 0.5, 1e-6);  // deep inside
  EXPECT_NEAR(stack.sample(40.0, 5.0).vMs, 0.25, 1e-6);
  EXPECT_NEAR(stack.sample(0.0, 5.0).uMs, 5.0, 1e-6);   // outside: the global layer
  EXPECT_NEAR(stack.sample(40.0, -10.0).uMs, 5.0, 1e-6);  // on the edge: weight 0
  // Along a line across the western edge, consecutive samples 0.001° apart never jump: the
  // largest step is bounded by the blend's slope (4.5 m/s over 3 cells, smoothstep ×1.5).
  double worst = 0.0;
  WindVector previous = stack.sample(40.3, -14.0);
  for (double lon = -14.0; lon <= -3.0; lon += 0.001) {
    const WindVector w = stack.sample(40.3, lon);
    worst = std::max(worst, std::hypot(w.uMs - previous.uMs, w.vMs - previous.vMs));
    previous = w;
  }
  EXPECT_LT(worst, 4.5 * 1.5 / 3.0 * 0.001 * 1.5);
  EXPECT_NEAR(previous.uMs, 0.5, 1e-6);  // ended inside at full weight
  // Same across the northern edge and a corner.
  worst = 0.0;
  previous = stack.sample(47.0, 19.0);
  for (double t = 0.0; t <= 1.0; t += 1e-4) {
    const WindVector w = stack.sample(47.0 + 6.0 * t, 19.0 + 4.0 * t);
    worst = std::max(worst, std::hypot(w.uMs - previous.uMs, w.vMs - previous.vMs));
    previous = w;
  }
  EXPECT_LT(worst, 0.01);
}

TEST(DataWindLayers, HolesBlendIntoTheLayerBeneathAndTinyLayersAreRefused) {
  WindLayers stack(WindVector{3.0, 0.0});
  WindGrid layer = constantLayer("holey", 0.0, 1.0, 21, 0.0, 1.0, 21, 9.0, 0.0);
  layer.u.values[10 * 21 + 10] = std::numeric_limits<float>::quiet_NaN();  // (10°N, 10°E)
  stack.push(layer);
  EXPECT_NEAR(stack.sample(10.0, 10.0).uMs, 3.0, 1e-6);  // the hole shows the fallback
  EXPECT_NEAR(stack.sample(3.0, 3.0).uMs, 9.0, 1e-6);
  double worst = 0.0;
  double previous = stack.sample(10.0, 6.0).uMs;
  for (double lon = 6.0; lon <= 14.0; lon += 0.001) {
    const double u = stack.sample(10.0, lon).uMs;
    worst = std::max(worst, std::abs(u - previous));
    previous = u;
  }
  EXPECT_LT(worst, 0.01);
  WindLayers other;
  expectInputError("tiny", "too small",
                   [&] { other.push(constantLayer("tiny", 0.0, 1.0, 2, 0.0, 1.0, 2, 1.0, 1.0)); });
}

TEST(DataWindLayers, RasterizeMatchesSamplesAtCellCentres) {
  WindLayers stack(WindVector{1.0, -1.0});
  stack.push(constantLayer("regional", 30.0, 1.0, 21, -10.0, 1.0, 31, 7.0, 2.0));
  const og::data::WindRaster r = stack.rasterize(360, 180);
  ASSERT_EQ(r.uv.size(), 2u * 360u * 180u);
  for (const auto& [row, column] : std::vector<std::pair<int, int>>{{0, 0}, {129, 175}, {125, 170}, {179, 359}}) {
    const double lat = -90.0 + (row + 0.5);
    const double lon = -180.0 + (column + 0.5);
    const WindVector w = stack.sample(lat, lon);
    const std::size_t i = 2 * (static_cast<std::size_t>(row) * 360 + static_cast<std::size_t>(column));
    EXPECT_FLOAT_EQ(r.uv[i], static_cast<float>(w.uMs));
    EXPECT_FLOAT_EQ(r.uv[i + 1], static_cast<float>(w.vMs));
  }
  EXPECT_FLOAT_EQ(r.uv[2 * (130 * 360 + 185)], 7.0f);  // 40.5°N 5.5°E: inside
  EXPECT_THROW((void)stack.rasterize(0, 10), og::InputError);
}

TEST(DataWindLayers, LoadsSpecsBottomFirst) {
  const fs::path era5 = outDir() / "stack_era5.nc";
  og::test::writeEra5Wind(era5);
  const fs::path regional = writeWind("stack_regional.nc", steps(30.0, 1.0, 11), steps(-20.0, 1.0, 21));
  const WindLayers stack = WindLayers::load({era5.string(), regional.string() + ":u,v"},
                                            WindVector{}, iso("2024-06-20T06:00Z"));
  ASSERT_EQ(stack.size(), 2u);
  EXPECT_EQ(stack.layer(0).u.name, "u10");
  EXPECT_NEAR(stack.sample(35.0, -10.0).uMs, fixtureU(35.0, -10.0, 0), 1e-4);  // regional on top
  EXPECT_NEAR(stack.sample(-60.0, 270.0).uMs, fixtureU(-60.0, 270.0, 1), 2e-3);  // ERA5 at 06Z
  // Next to ERA5's missing cell (0°N 90°E) the layer fades out to the constant wind beneath.
  EXPECT_NEAR(stack.sample(0.0, 90.0).uMs, 0.0, 1e-6);
  expectInputError((outDir() / "absent.nc").string(), "no such file", [&] {
    (void)WindLayers::load({(outDir() / "absent.nc").string()}, WindVector{}, std::nullopt);
  });
}

// ---------------------------------------------------------------------------------------------
// Real data and defaults

TEST(DataWind, DefaultWindIsNavyJanuary1992) {
  const WindGrid& w = og::data::defaultWind();
  EXPECT_EQ(w.u.width, 144);
  EXPECT_EQ(w.u.height, 73);
  EXPECT_TRUE(w.u.wrapsLongitude);
  ASSERT_TRUE(w.time.has_value());
  EXPECT_EQ(w.time->toIso8601().substr(0, 7), "1992-01");
  const auto [lo, hi] = std::minmax_element(w.u.values.begin(), w.u.values.end());
  EXPECT_GT(*lo, -40.0f);
  EXPECT_LT(*hi, 40.0f);
  EXPECT_GT(w.u.sample(-50.0, 90.0), 3.0f);  // southern ocean westerlies
  EXPECT_LT(w.u.sample(15.0, -40.0), 0.0f);  // north-east trades blow towards the west
}

TEST(DataWind, MonthlyNavyWindsFromFerretDatasets) {
  const fs::path file = "/usr/share/ferret-vis/data/monthly_navy_winds.cdf";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not installed (package ferret-datasets)";
  const auto grid = og::data::openGridFile(file);
  EXPECT_EQ(grid->describe("UWND").times.size(), 132u);
  const WindGrid w = og::data::readWind(*grid, {}, iso("1985-07-01T00:00Z"));
  EXPECT_EQ(w.u.name, "UWND");
  ASSERT_TRUE(w.time.has_value());
  EXPECT_EQ(w.time->toIso8601(), "1985-07-01T00:00:00Z");
  // Interpolated between June and July 1985: between the two months' values.
  const WindGrid june = og::data::readWind(*grid, {}, iso("1985-06-16T00:00Z"));
  const WindGrid july = og::data::readWind(*grid, {}, iso("1985-07-16T12:00Z"));
  const float a = june.u.sample(10.0, -140.0);
  const float b = july.u.sample(10.0, -140.0);
  const float m = w.u.sample(10.0, -140.0);
  EXPECT_GE(m, std::min(a, b) - 0.05f);
  EXPECT_LE(m, std::max(a, b) + 0.05f);
}

TEST(DataElevation, LayerSpecDefaultUnitsAndGrib) {
  EXPECT_EQ(og::data::loadElevationLayer("").width, og::data::defaultElevation().width);
  const fs::path km = outDir() / "relief_km.nc";
  {
    NcWriter nc(km, NC_NETCDF4);
    const auto [latD, latV] = nc.axis("y", steps(-80.0, 20.0, 9), "degrees_north");
    const auto [lonD, lonV] = nc.axis("x", steps(-180.0, 20.0, 18), "degrees_east");
    const int z = nc.var("height_km", NC_FLOAT, {latD, lonD});
    nc.text(z, "units", "km");
    nc.values(z, std::vector<double>(9 * 18, -1.5));
    const int t = nc.var("temperature", NC_FLOAT, {latD, lonD});
    nc.text(t, "units", "K");
    nc.values(t, std::vector<double>(9 * 18, 280.0));
    nc.close();
  }
  EXPECT_FLOAT_EQ(og::data::loadElevationLayer(km.string() + ":height_km").sample(0.0, 0.0), -1500.0f);
  expectInputError(km.string(), "units 'K'",
                   [&] { (void)og::data::loadElevationLayer(km.string() + ":temperature"); });
  expectInputError(km.string(), "several fields",
                   [&] { (void)og::data::loadElevationLayer(km.string()); });
  expectInputError(km.string(), "one variable",
                   [&] { (void)og::data::loadElevationLayer(km.string() + ":a,b"); });
}

// ---------------------------------------------------------------------------------------------
// Malformed-file corpus: every file in tests/data/corpus must either load or be refused with
// one "FILE: problem" line; files named bad_* must be refused.

namespace {
/// Everything a user command could do with a file: list, describe, read every step of every
/// field, and read it as a wind layer and as an elevation layer.
void exercise(const fs::path& file) {
  const auto grid = og::data::openGridFile(file);
  for (const auto& f : grid->fields()) {
    const auto d = grid->describe(f.name);
    for (std::size_t s = 0; s < std::min<std::size_t>(d.steps(), 4); ++s)
      (void)grid->read(f.name, s);
  }
  try {
    (void)og::data::readWind(*grid, {}, std::nullopt);
  } catch (const og::InputError&) {
  }
}
}  // namespace

TEST(DataCorpus, MalformedFilesAreRefusedCleanly) {
  const fs::path dir = fs::path(OG_TEST_DATA_DIR) / "data" / "corpus";
  ASSERT_TRUE(fs::is_directory(dir)) << dir;
  std::size_t bad = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const fs::path file = entry.path();
    if (file.extension() == ".md") continue;
    SCOPED_TRACE(file.string());
    const bool mustFail = file.filename().string().rfind("bad_", 0) == 0;
    try {
      exercise(file);
      EXPECT_FALSE(mustFail) << "accepted";
    } catch (const og::InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_TRUE(mustFail) << message;
      bad += mustFail ? 1 : 0;
    }
  }
  EXPECT_GE(bad, 10u);
}
