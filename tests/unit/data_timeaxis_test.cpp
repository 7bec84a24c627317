// Time axes in every CF calendar, climatologies (cyclic through the year end), and wind layers
// that follow the clock (per-time sampling, quantised weights, the step cache).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "data/GridFile.hpp"
#include "data/TimeAxis.hpp"
#include "data/WindField.hpp"
#include "data/WindLayers.hpp"
#include "support/DataFixtures.hpp"
#include "support/ExpectError.hpp"

namespace fs = std::filesystem;
using og::UtcTime;
using og::data::WindLayers;
using og::data::WindVector;
using og::data::detail::AxisTimes;
using og::data::detail::decodeTimeAxis;
using og::test::expectInputError;

namespace {

UtcTime iso(const char* text) { return *UtcTime::parseIso8601(text); }

AxisTimes decode(const std::vector<double>& values, const std::string& units,
                 const std::string& calendar, bool flagged = false) {
  return decodeTimeAxis("f.nc", "time", values, units, calendar, flagged);
}

std::string isoOf(const AxisTimes& a, std::size_t i) { return a.times.at(i).toIso8601(); }

/// A uniform wind file: u = `speeds`[t] everywhere, v = 0, on a global 30° grid.
fs::path writeUniformWind(const fs::path& file, const std::vector<double>& times, const std::string& units,
                          const std::vector<double>& speeds, const std::string& calendar = "",
                          const std::string& timeAttribute = "") {
  og::test::TimedWind wind;
  wind.times = times;
  wind.units = units;
  wind.calendar = calendar;
  wind.flagAttribute = timeAttribute;
  wind.eastMs = speeds;
  return og::test::writeTimedWind(file, wind);
}

}  // namespace

TEST(DataCalendars, RealCalendarsAreExact) {
  // NCEP reanalysis: "hours since 1-1-1 00:00:0.0" in the standard (Julian before 1582-10-15)
  // calendar; 1948-01-01 is hour 17067072 there, two days later than proleptic Gregorian.
  EXPECT_EQ(isoOf(decode({17067072.0}, "hours since 1-1-1 00:00:0.0", "standard"), 0), "1948-01-01T00:00:00Z");
  EXPECT_EQ(isoOf(decode({17067072.0}, "hours since 1-1-1 00:00:0.0", ""), 0), "1948-01-01T00:00:00Z");
  EXPECT_EQ(isoOf(decode({17067024.0}, "hours since 1-1-1 00:00:0.0", "proleptic_gregorian"), 0),
            "1948-01-01T00:00:00Z");
  // Julian 2000-01-01 is Gregorian 2000-01-14; the switch: Julian 1582-10-04 + 1 day = 10-15.
  EXPECT_EQ(isoOf(decode({0.0}, "days since 2000-01-01", "julian"), 0), "2000-01-14T00:00:00Z");
  EXPECT_EQ(isoOf(decode({1.0}, "days since 1582-10-04", "gregorian"), 0), "1582-10-15T00:00:00Z");
  expectInputError("f.nc", "not understood", [] { (void)decode({0.0}, "days since 1582-10-10", "standard"); });
  // Real calendars agree in modern times when the epoch is recent.
  for (const char* c : {"standard", "gregorian", "proleptic_gregorian", "Gregorian"})
    EXPECT_EQ(isoOf(decode({36.0}, "hours since 2024-02-28 12:00", c), 0), "2024-03-01T00:00:00Z") << c;
}

TEST(DataCalendars, ModelCalendarsKeepTheSeasons) {
  // noleap / 365_day: whole years land on 1 January; day 59 (1 March) of leap year 2000 is
  // 59/365 of the real 366-day year.
  for (const char* c : {"noleap", "365_day"}) {
    const AxisTimes a = decode({0.0, 59.0, 3650.0}, "days since 2000-01-01", c);
    EXPECT_EQ(isoOf(a, 0), "2000-01-01T00:00:00Z");
    EXPECT_NEAR(a.times[1].unixSeconds - iso("2000-01-01T00:00Z").unixSeconds, 59.0 / 365.0 * 366.0 * 86400.0, 1e-3);
    EXPECT_EQ(isoOf(a, 2), "2010-01-01T00:00:00Z");
  }
  for (const char* c : {"all_leap", "366_day"}) {
    const AxisTimes a = decode({366.0, 366.0 + 183.0}, "days since 2001-01-01", c);
    EXPECT_EQ(isoOf(a, 0), "2002-01-01T00:00:00Z");
    EXPECT_EQ(isoOf(a, 1), "2002-07-02T12:00:00Z");  // half of 2002's 365 days
  }
  // 360_day: half a model year is half the real year; 2000-02-30 exists; months are 30 days.
  EXPECT_EQ(isoOf(decode({180.0}, "days since 2000-01-01", "360_day"), 0), "2000-07-02T00:00:00Z");
  EXPECT_EQ(isoOf(decode({6.0}, "months since 2000-01-01", "360_day"), 0), "2000-07-02T00:00:00Z");
  EXPECT_EQ(isoOf(decode({1.0}, "years since 2000-01-01", "360_day"), 0), "2001-01-01T00:00:00Z");
  EXPECT_EQ(isoOf(decode({1.0}, "days since 2000-02-30", "360_day"), 0),
            UtcTime{iso("2000-01-01T00:00Z").unixSeconds + 60.0 / 360.0 * 366.0 * 86400.0}.toIso8601());
  // Strictly increasing across year ends, daily steps of a decade.
  std::vector<double> days(3650);
  for (std::size_t i = 0; i < days.size(); ++i) days[i] = static_cast<double>(i);
  for (const char* c : {"noleap", "all_leap", "360_day", "julian", "standard"})
    EXPECT_NO_THROW((void)decode(days, "days since 1999-06-01", c)) << c;
}

TEST(DataCalendars, UnsupportedCalendarsAndUnitsExitWithAClearMessage) {
  expectInputError("f.nc", "calendar 'none', which is not supported",
                   [] { (void)decode({0.0}, "days since 2000-01-01", "none"); });
  expectInputError("f.nc", "calendar 'lunar'", [] { (void)decode({0.0}, "days since 2000-01-01", "lunar"); });
  expectInputError("f.nc", "months and years are fixed spans only in calendar 360_day",
                   [] { (void)decode({0.0}, "months since 2000-01-01", "noleap"); });
  expectInputError("f.nc", "not understood", [] { (void)decode({0.0}, "days since 2001-02-29", "noleap"); });
  expectInputError("f.nc", "not strictly increasing", [] { (void)decode({2.0, 1.0}, "days since 2000-01-01", "360_day"); });
  expectInputError("f.nc", "unusable value", [] { (void)decode({1e300}, "days since 2000-01-01", "noleap"); });
  expectInputError("f.nc", "climatology but its steps span more than a year",
                   [] { (void)decode({0.0, 400.0}, "days since 2000-01-01", "", true); });
}

TEST(DataClimatology, YearZeroAxisRepeatsEveryYear) {
  // Ferret's COADS climatology: "hour since 0000-01-01", mid-month steps of year 0.
  const AxisTimes a = decode({366.0, 1096.485, 1826.97}, "hour since 0000-01-01 00:00:00", "");
  ASSERT_TRUE(a.climatology);
  EXPECT_EQ(a.times[0].toIso8601().substr(0, 10), "2001-01-16");
  // The same axis counted from a real year is a time series; a year-0 axis over many years too.
  EXPECT_FALSE(decode({366.0, 1096.485}, "hour since 1990-01-01", "").climatology);
  EXPECT_FALSE(decode({0.0, 400.0 * 24.0 * 10}, "hours since 0000-01-01", "").climatology);
  // A `climatology` attribute marks any year's axis.
  EXPECT_TRUE(decode({15.0, 45.0}, "days since 1961-01-01", "", true).climatology);

  // Cyclic choice: mid-January of any year is step 0; the year end blends December and January.
  std::vector<UtcTime> months;
  for (int m = 1; m <= 12; ++m) months.push_back(UtcTime::fromCivil(2001, static_cast<unsigned>(m), 16));
  const auto pick = [&](const char* t) { return og::data::detail::chooseClimatologySteps(months, iso(t)); };
  EXPECT_EQ(pick("1990-01-16T00:00Z").first, 0u);
  EXPECT_DOUBLE_EQ(pick("2030-01-16T00:00Z").weight, 0.0);
  for (const char* t : {"2024-12-31T23:00Z", "2025-01-01T01:00Z"}) {
    const og::data::StepChoice c = pick(t);
    EXPECT_EQ(c.first, 11u) << t;
    EXPECT_EQ(c.second, 0u) << t;
    EXPECT_NEAR(c.weight, 0.5, 0.03) << t;  // Dec 16 .. Jan 16: the year end is halfway
  }
  EXPECT_EQ(pick("2024-07-01T00:00Z").first, 5u);
  EXPECT_EQ(pick("2024-07-01T00:00Z").second, 6u);
}

TEST(DataClimatology, FerretCoadsWindsWrapAtTheYearEnd) {
  const fs::path file = "/usr/share/ferret-vis/data/coads_climatology.cdf";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not installed (package ferret-datasets)";
  const auto grid = og::data::openGridFile(file);
  const og::data::FieldDescription d = grid->describe("UWND");
  ASSERT_TRUE(d.climatology);
  ASSERT_EQ(d.times.size(), 12u);
  const auto u = [&](const char* t) { return og::data::readWind(*grid, {"UWND", "VWND"}, iso(t)).u; };
  // Any year: the same day of year gives the same wind.
  const auto a = u("1990-03-01T00:00Z");
  const auto b = u("2024-03-01T00:00Z");
  const auto c = u("2023-03-01T00:00Z");
  EXPECT_NEAR(a.sample(40.0, -40.0), c.sample(40.0, -40.0), 1e-4);
  EXPECT_NEAR(b.sample(40.0, -40.0), c.sample(40.0, -40.0), 0.2);  // leap year: a day apart
  // Continuous through the year end: 31 Dec and 1 Jan nearly agree, and lie between the
  // December and January fields.
  const auto dec = u("2023-12-16T12:00Z");
  const auto jan = u("2024-01-16T00:00Z");
  const auto before = u("2023-12-31T23:00Z");
  const auto after = u("2024-01-01T01:00Z");
  int checked = 0;
  for (double lat = -40.0; lat <= 40.0; lat += 20.0)
    for (double lon = -170.0; lon < 180.0; lon += 40.0) {
      const float x = before.sample(lat, lon), y = after.sample(lat, lon);
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      ++checked;
      EXPECT_NEAR(x, y, 0.02f * std::max(1.0f, std::abs(dec.sample(lat, lon) - jan.sample(lat, lon))) + 0.05f);
      EXPECT_GE(x, std::min(dec.sample(lat, lon), jan.sample(lat, lon)) - 0.05f);
      EXPECT_LE(x, std::max(dec.sample(lat, lon), jan.sample(lat, lon)) + 0.05f);
    }
  EXPECT_GT(checked, 20);
}

TEST(DataWindLayers, FollowTheClockWithQuantisedCachedSteps) {
  const fs::path file = writeUniformWind(og::test::fixtureDir("data_timeaxis") / "two.nc", {0.0, 6.0},
                                         "hours since 2024-06-20 00:00", {3.0, 20.0});
  const WindLayers stack = WindLayers::load({file.string()}, WindVector{}, iso("2024-06-20T00:00Z"));
  ASSERT_TRUE(stack.timeVarying());
  EXPECT_NEAR(stack.sample(10.0, 20.0).uMs, 3.0, 1e-5);
  EXPECT_NEAR(stack.maxSpeedMs(), 20.0, 1e-5);
  // Linear in time between the two steps, clamped outside.
  EXPECT_NEAR(stack.at(iso("2024-06-20T03:00Z")).sample(10.0, 20.0).uMs, 11.5, 1e-4);
  EXPECT_NEAR(stack.at(iso("2024-06-20T04:30Z")).sample(-30.0, 200.0).uMs, 3.0 + 0.75 * 17.0, 1e-4);
  EXPECT_NEAR(stack.at(iso("2024-06-19T00:00Z")).sample(10.0, 20.0).uMs, 3.0, 1e-5);
  EXPECT_NEAR(stack.at(iso("2024-06-21T00:00Z")).sample(10.0, 20.0).uMs, 20.0, 1e-5);
  // Weights in steps of 1/kWeightSteps: 6 h / 100 = 216 s; nearby times share a key and a layer.
  const UtcTime t = iso("2024-06-20T03:00Z");
  EXPECT_EQ(stack.timeKey(t), stack.timeKey(UtcTime{t.unixSeconds + 60.0}));
  EXPECT_NE(stack.timeKey(t), stack.timeKey(UtcTime{t.unixSeconds + 300.0}));
  EXPECT_EQ(&stack.at(t).layer(0), &stack.at(UtcTime{t.unixSeconds + 60.0}).layer(0));
  EXPECT_EQ(stack.at(t).timeKey(), stack.timeKey(t));
  // A one-step file is fixed.
  const fs::path one = writeUniformWind(og::test::fixtureDir("data_timeaxis") / "one.nc", {0.0},
                                        "hours since 2024-06-20 00:00", {5.0});
  EXPECT_FALSE(WindLayers::load({one.string()}, WindVector{}, std::nullopt).timeVarying());
}

TEST(DataWindLayers, ClimatologyLayerWrapsAtTheYearEnd) {
  // Twelve mid-month steps of year 0 with u = month number (1 .. 12).
  std::vector<double> hours, speeds;
  for (int m = 0; m < 12; ++m) {
    hours.push_back((m * 30.5 + 15.0) * 24.0);
    speeds.push_back(m + 1.0);
  }
  const fs::path file = writeUniformWind(og::test::fixtureDir("data_timeaxis") / "clim.nc", hours,
                                         "hours since 0000-01-01 00:00:00", speeds);
  const WindLayers stack = WindLayers::load({file.string()}, WindVector{}, iso("2024-06-20T00:00Z"));
  const double endOfYear = stack.at(iso("2024-12-31T23:59Z")).sample(0.0, 0.0).uMs;
  const double newYear = stack.at(iso("2025-01-01T00:01Z")).sample(0.0, 0.0).uMs;
  EXPECT_NEAR(endOfYear, newYear, 0.15);  // no jump from 12 back to 1
  EXPECT_GT(endOfYear, 5.0);               // halfway between December (12) and January (1)
  EXPECT_LT(endOfYear, 8.0);
  EXPECT_NEAR(stack.at(iso("1987-07-16T00:00Z")).sample(0.0, 0.0).uMs, 7.0, 0.2);
}

TEST(DataCalendars, EveryCalendarLoadsFromANetcdfFile) {
  // Steps one model day apart from 2000-03-01 (after any leap day, so every calendar's day 1
  // is within a day of the real one); noon of the first day lies between the two winds.
  for (const char* c : {"standard", "gregorian", "proleptic_gregorian", "julian", "noleap", "365_day",
                        "all_leap", "366_day", "360_day", ""}) {
    const fs::path file = writeUniformWind(og::test::fixtureDir("data_timeaxis") / (std::string("cal_") + c + ".nc"),
                                           {0.0, 1.0}, "days since 2000-03-01", {4.0, 8.0}, c);
    const auto grid = og::data::openGridFile(file);
    const og::data::FieldDescription d = grid->describe("uwnd");
    ASSERT_EQ(d.times.size(), 2u) << c;
    EXPECT_FALSE(d.climatology) << c;
    const double t0 = d.times[0].unixSeconds;
    const double dayS = d.times[1].unixSeconds - t0;
    EXPECT_NEAR(dayS, 86400.0, 86400.0 * 0.02) << c;  // model days are real days within 2 %
    const auto w = og::data::readWind(*grid, {}, UtcTime{t0 + 0.5 * dayS});
    EXPECT_NEAR(w.u.sample(0.0, 0.0), 6.0, 1e-4) << c;
  }
}

TEST(DataClimatology, CfClimatologyAttributeMarksAnyYear) {
  // CF 7.4: mid-January and mid-February of a 1961-1990 climatology, `climatology` attribute.
  const fs::path file = writeUniformWind(og::test::fixtureDir("data_timeaxis") / "cf_clim.nc", {15.0, 45.0},
                                         "days since 1961-01-01", {2.0, 10.0}, "", "climatology");
  const auto grid = og::data::openGridFile(file);
  EXPECT_TRUE(grid->describe("uwnd").climatology);
  // 31 January of any year: halfway between the two steps, not clamped to 1961's last step.
  for (const char* t : {"1975-01-31T00:00Z", "2024-01-31T00:00Z"})
    EXPECT_NEAR(og::data::readWind(*grid, {}, iso(t)).u.sample(0.0, 0.0), 6.0, 0.3) << t;
}
