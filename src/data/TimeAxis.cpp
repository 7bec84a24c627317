#include "data/TimeAxis.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.hpp"
#include "data/GridFile.hpp"

namespace og::data::detail {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// Reads an unsigned decimal integer of 1..maxDigits digits at `p`.
std::optional<int> integer(const std::string& s, std::size_t& p, std::size_t maxDigits) {
  std::size_t n = 0;
  int value = 0;
  while (p < s.size() && n < maxDigits && std::isdigit(static_cast<unsigned char>(s[p]))) {
    value = value * 10 + (s[p] - '0');
    ++p;
    ++n;
  }
  if (n == 0) return std::nullopt;
  return value;
}

bool accept(const std::string& s, std::size_t& p, char c) {
  if (p < s.size() && s[p] == c) {
    ++p;
    return true;
  }
  return false;
}

void skipSpaces(const std::string& s, std::size_t& p) {
  while (p < s.size() && std::isspace(static_cast<unsigned char>(s[p]))) ++p;
}

/// Instants outside years -1..9999 are certainly wrong and would overflow formatting (year 0
/// holds the climatologies that count from it).
constexpr double kMinUnixSeconds = -62198755200.0;  // -0001-01-01
constexpr double kMaxUnixSeconds = 253402300799.0;  // 9999-12-31T23:59:59

constexpr double kDayS = 86400.0;

bool gregorianLeap(long long y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

/// Days in `month` (1..12) of `year`: the Julian rule before 1583 in the standard calendar
/// (its 1582 October has days 1-4 and 15-31, which dateExists checks).
int daysInMonth(Calendar c, long long year, int month) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (c == Calendar::Day360) return 30;
  if (month != 2) return kDays[month - 1];
  bool leap = false;
  switch (c) {
    case Calendar::NoLeap: leap = false; break;
    case Calendar::AllLeap: leap = true; break;
    case Calendar::Julian: leap = year % 4 == 0; break;
    case Calendar::Standard: leap = year < 1583 ? year % 4 == 0 : gregorianLeap(year); break;
    default: leap = gregorianLeap(year); break;
  }
  return leap ? 29 : 28;
}

bool dateExists(Calendar c, long long year, int month, int day) {
  if (month < 1 || month > 12 || day < 1 || day > daysInMonth(c, year, month)) return false;
  // The standard calendar skips 1582-10-05 .. 1582-10-14 (Julian to Gregorian).
  return !(c == Calendar::Standard && year == 1582 && month == 10 && day > 4 && day < 15);
}

/// Days before `month` in `year` (0-based day of year of the month's first day).
int daysBeforeMonth(Calendar c, long long year, int month) {
  int days = 0;
  for (int m = 1; m < month; ++m) days += daysInMonth(c, year, m);
  return days;
}

/// Days from 1970-01-01 to a proleptic Gregorian date.
double gregorianUnixDays(long long year, int month, int day) {
  const std::chrono::sys_days d = std::chrono::year{static_cast<int>(year)} /
                                  std::chrono::month{static_cast<unsigned>(month)} /
                                  std::chrono::day{static_cast<unsigned>(day)};
  return static_cast<double>(d.time_since_epoch().count());
}

/// Days from 1970-01-01 to a Julian calendar date: counted from Julian 0000-01-01, then moved
/// to the switch date (Julian 1582-10-05 = Gregorian 1582-10-15).
double julianUnixDays(long long year, int month, int day) {
  const auto count = [](long long y, int m, int d) {
    // Years 0 .. y-1, of which those divisible by 4 are leap (y >= 0).
    return 365.0 * static_cast<double>(y) + static_cast<double>((y + 3) / 4) +
           daysBeforeMonth(Calendar::Julian, y, m) + (d - 1);
  };
  return count(year, month, day) - count(1582, 10, 5) + gregorianUnixDays(1582, 10, 15);
}

/// The instant at fraction `f` (0..1, may leave the range) of Gregorian year `year`.
double gregorianYearFraction(long long year, double f) {
  const double start = gregorianUnixDays(year, 1, 1) * kDayS;
  const double length = gregorianUnixDays(year + 1, 1, 1) * kDayS - start;
  return start + f * length;
}

bool isModelCalendar(Calendar c) {
  return c == Calendar::NoLeap || c == Calendar::AllLeap || c == Calendar::Day360;
}

/// Fraction of its Gregorian (UTC) year that `t` has reached, [0, 1).
double fractionOfYear(UtcTime t) {
  const auto days = static_cast<long>(std::floor(t.unixSeconds / kDayS));
  const std::chrono::year_month_day ymd{std::chrono::sys_days{std::chrono::days{days}}};
  const long long year = static_cast<int>(ymd.year());
  const double start = gregorianUnixDays(year, 1, 1) * kDayS;
  const double length = gregorianUnixDays(year + 1, 1, 1) * kDayS - start;
  return std::clamp((t.unixSeconds - start) / length, 0.0, std::nextafter(1.0, 0.0));
}

std::optional<double> secondsPer(const std::string& unit) {
  static const std::pair<const char*, double> units[] = {
      {"seconds", 1.0}, {"second", 1.0}, {"secs", 1.0},     {"sec", 1.0},     {"s", 1.0},
      {"minutes", 60.0}, {"minute", 60.0}, {"mins", 60.0},  {"min", 60.0},
      {"hours", 3600.0}, {"hour", 3600.0}, {"hrs", 3600.0}, {"hr", 3600.0},   {"h", 3600.0},
      {"days", 86400.0}, {"day", 86400.0}, {"d", 86400.0},
  };
  for (const auto& [name, seconds] : units)
    if (unit == name) return seconds;
  return std::nullopt;
}

}  // namespace

std::optional<TimeUnits> parseTimeUnits(const std::string& text) {
  return parseTimeUnits(text, Calendar::ProlepticGregorian);
}

std::optional<TimeUnits> parseTimeUnits(const std::string& text, Calendar calendar) {
  const std::string s = lower(text);
  const std::size_t since = s.find(" since ");
  if (since == std::string::npos) return std::nullopt;
  std::string unit = s.substr(0, since);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front()))) unit.erase(0, 1);
  auto perUnit = secondsPer(unit);
  // Months and years are whole 30- and 360-day spans only in the 360_day calendar (CF 4.4:
  // elsewhere UDUNITS' month is a twelfth of a tropical year, never what a file means).
  if (!perUnit && calendar == Calendar::Day360) {
    if (unit == "months" || unit == "month") perUnit = 30.0 * 86400.0;
    if (unit == "years" || unit == "year") perUnit = 360.0 * 86400.0;
  }
  if (!perUnit) return std::nullopt;

  std::size_t p = since + 7;
  skipSpaces(s, p);
  const bool negativeYear = accept(s, p, '-');
  const auto year = integer(s, p, 4);
  if (!year || negativeYear || !accept(s, p, '-')) return std::nullopt;
  const auto month = integer(s, p, 2);
  if (!month || !accept(s, p, '-')) return std::nullopt;
  const auto day = integer(s, p, 2);
  if (!day) return std::nullopt;
  if (!dateExists(calendar, *year, *month, *day)) return std::nullopt;

  int hour = 0;
  int minute = 0;
  double second = 0.0;
  if (p < s.size() && (s[p] == 't' || s[p] == ' ')) {
    std::size_t q = p + 1;
    skipSpaces(s, q);
    if (const auto h = integer(s, q, 2); h && accept(s, q, ':')) {
      const auto m = integer(s, q, 2);
      if (!m) return std::nullopt;
      hour = *h;
      minute = *m;
      if (accept(s, q, ':')) {
        const auto sec = integer(s, q, 2);
        if (!sec) return std::nullopt;
        second = *sec;
        if (accept(s, q, '.')) {
          double scale = 0.1;
          while (q < s.size() && std::isdigit(static_cast<unsigned char>(s[q]))) {
            second += scale * (s[q] - '0');
            scale *= 0.1;
            ++q;
          }
        }
      }
      p = q;
    }
  }
  if (hour > 24 || minute > 59 || second >= 61.0) return std::nullopt;

  // Zone: Z, UTC/GMT, or a numeric offset; anything else left over is not understood.
  skipSpaces(s, p);
  double offsetSeconds = 0.0;
  if (s.compare(p, 3, "utc") == 0 || s.compare(p, 3, "gmt") == 0) {
    p += 3;
  } else if (accept(s, p, 'z')) {
  } else if (p < s.size() && (s[p] == '+' || s[p] == '-')) {
    const double sign = s[p] == '-' ? -1.0 : 1.0;
    ++p;
    const auto oh = integer(s, p, 2);
    if (!oh) return std::nullopt;
    int om = 0;
    if (accept(s, p, ':')) {
      const auto m = integer(s, p, 2);
      if (!m) return std::nullopt;
      om = *m;
    }
    offsetSeconds = sign * (*oh * 3600.0 + om * 60.0);
  }
  skipSpaces(s, p);
  if (p != s.size()) return std::nullopt;

  TimeUnits units;
  units.secondsPerUnit = *perUnit;
  // The proleptic Gregorian reading; a date that only the axis' calendar has (Feb 30) is
  // clamped to its month's end here (instantOf gives the real instant).
  const std::chrono::year_month_day ymd{std::chrono::year{*year},
                                        std::chrono::month{static_cast<unsigned>(*month)},
                                        std::chrono::day{static_cast<unsigned>(*day)}};
  const std::chrono::year_month_day valid =
      ymd.ok() ? ymd : std::chrono::year_month_day{std::chrono::year_month_day_last{
                           ymd.year(), std::chrono::month_day_last{ymd.month()}}};
  units.epoch = UtcTime::fromCivil(*year, static_cast<unsigned>(valid.month()),
                                   static_cast<unsigned>(valid.day()), hour, minute, second);
  units.epoch.unixSeconds -= offsetSeconds;
  units.year = *year;
  units.month = *month;
  units.day = *day;
  units.secondsOfDay = hour * 3600.0 + minute * 60.0 + second - offsetSeconds;
  units.offsetSeconds = offsetSeconds;
  return units;
}

bool isRealCalendar(const std::string& calendar) {
  const std::string c = lower(calendar);
  return c.empty() || c == "standard" || c == "gregorian" || c == "proleptic_gregorian";
}

std::vector<UtcTime> toInstants(const std::string& label, const std::string& axisName,
                                const std::vector<double>& values, const TimeUnits& units) {
  std::vector<UtcTime> times;
  times.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double t = units.epoch.unixSeconds + values[i] * units.secondsPerUnit;
    if (!std::isfinite(values[i]) || !(t >= kMinUnixSeconds && t <= kMaxUnixSeconds))
      throw InputError(label + ": time axis '" + axisName + "' has an unusable value at index " +
                       std::to_string(i));
    if (!times.empty() && !(t > times.back().unixSeconds))
      throw InputError(label + ": time axis '" + axisName +
                       "' is not strictly increasing (index " + std::to_string(i) + ")");
    times.push_back(UtcTime{t});
  }
  return times;
}

std::optional<Calendar> parseCalendar(const std::string& name) {
  const std::string c = lower(name);
  if (c.empty() || c == "standard" || c == "gregorian") return Calendar::Standard;
  if (c == "proleptic_gregorian") return Calendar::ProlepticGregorian;
  if (c == "julian") return Calendar::Julian;
  if (c == "noleap" || c == "365_day") return Calendar::NoLeap;
  if (c == "all_leap" || c == "366_day") return Calendar::AllLeap;
  if (c == "360_day") return Calendar::Day360;
  return std::nullopt;
}

int daysInYear(Calendar calendar, long long year) {
  if (calendar == Calendar::Standard && year == 1582) return 355;
  int days = 0;
  for (int m = 1; m <= 12; ++m) days += daysInMonth(calendar, year, m);
  return days;
}

UtcTime instantOf(Calendar calendar, int year, int month, int day, double secondsOfDay) {
  switch (calendar) {
    case Calendar::ProlepticGregorian:
      return UtcTime{gregorianUnixDays(year, month, day) * kDayS + secondsOfDay};
    case Calendar::Julian:
      return UtcTime{julianUnixDays(year, month, day) * kDayS + secondsOfDay};
    case Calendar::Standard: {
      const bool julian = year < 1582 || (year == 1582 && (month < 10 || (month == 10 && day < 15)));
      const double days = julian ? julianUnixDays(year, month, day) : gregorianUnixDays(year, month, day);
      return UtcTime{days * kDayS + secondsOfDay};
    }
    default: {
      const double length = daysInYear(calendar, year);
      const double dayOfYear = daysBeforeMonth(calendar, year, month) + (day - 1) + secondsOfDay / kDayS;
      return UtcTime{gregorianYearFraction(year, dayOfYear / length)};
    }
  }
}

UtcTime climatologyInstant(UtcTime time) {
  return UtcTime{gregorianYearFraction(kClimatologyYear, fractionOfYear(time))};
}

namespace {

/// The instant of axis value `value` (units since the epoch, in `calendar`).
double instantSeconds(Calendar calendar, const TimeUnits& u, double value) {
  if (!isModelCalendar(calendar))
    return instantOf(calendar, u.year, u.month, u.day, u.secondsOfDay).unixSeconds +
           value * u.secondsPerUnit;
  // Model calendars: count model days (every year has the same length), then place the model
  // date at the same fraction of the Gregorian year.
  const double length = daysInYear(calendar, u.year);
  const double epochDays = static_cast<double>(u.year) * length +
                           daysBeforeMonth(calendar, u.year, u.month) + (u.day - 1) +
                           u.secondsOfDay / kDayS;
  const double days = epochDays + value * u.secondsPerUnit / kDayS;
  const double year = std::floor(days / length);
  if (!(std::abs(year) < 1e5)) return std::numeric_limits<double>::infinity();
  return gregorianYearFraction(static_cast<long long>(year), (days - year * length) / length);
}

/// Where axis value `value` falls in its year of `calendar`, [0, 1): the climatology's
/// position (a year-0 epoch in the standard calendar is a Julian date, and its year begins
/// two days before the Gregorian one).
double calendarYearFraction(Calendar calendar, const TimeUnits& u, double value) {
  long long year = u.year;
  double day = daysBeforeMonth(calendar, year, u.month) + (u.day - 1) + u.secondsOfDay / kDayS +
               value * u.secondsPerUnit / kDayS;
  // A climatology spans at most a year or so from its epoch: a few turns of these loops.
  for (int turns = 0; turns < 8 && day >= daysInYear(calendar, year); ++turns) day -= daysInYear(calendar, year++);
  for (int turns = 0; turns < 8 && day < 0.0; ++turns) day += daysInYear(calendar, --year);
  return std::clamp(day / daysInYear(calendar, year), 0.0, std::nextafter(1.0, 0.0));
}

[[noreturn]] void axisError(const std::string& label, const std::string& axisName,
                            const std::string& problem) {
  throw InputError(label + ": time axis '" + axisName + "' " + problem);
}

}  // namespace

AxisTimes decodeTimeAxis(const std::string& label, const std::string& axisName,
                         const std::vector<double>& values, const std::string& unitsText,
                         const std::string& calendarText, bool flaggedClimatology) {
  const std::optional<Calendar> calendar = parseCalendar(calendarText);
  if (!calendar)
    axisError(label, axisName, "uses calendar '" + calendarText + "', which is not supported (use one of " +
                                   kCalendarNames + ")");
  const std::optional<TimeUnits> units = parseTimeUnits(unitsText, *calendar);
  if (!units) {
    const std::string l = lower(unitsText);
    const bool months = l.rfind("month", 0) == 0 || l.rfind("year", 0) == 0;
    axisError(label, axisName,
              "has units '" + unitsText + "' that are not understood (expected e.g. 'hours since 1900-01-01 00:00:00'" +
                  (months ? "; months and years are fixed spans only in calendar 360_day" : "") + ")");
  }
  AxisTimes out;
  out.times.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double t = std::isfinite(values[i]) ? instantSeconds(*calendar, *units, values[i])
                                               : std::numeric_limits<double>::quiet_NaN();
    if (!(t >= kMinUnixSeconds && t <= kMaxUnixSeconds))
      axisError(label, axisName, "has an unusable value at index " + std::to_string(i));
    if (!out.times.empty() && !(t > out.times.back().unixSeconds))
      axisError(label, axisName, "is not strictly increasing (index " + std::to_string(i) + ")");
    out.times.push_back(UtcTime{t});
  }
  // A climatology's steps lie within one year: 366 days and a little for rounding.
  const bool fitsInYear =
      out.times.empty() || out.times.back().unixSeconds - out.times.front().unixSeconds < 367.0 * kDayS;
  if (flaggedClimatology && !fitsInYear)
    axisError(label, axisName, "is marked as a climatology but its steps span more than a year");
  out.climatology = fitsInYear && (flaggedClimatology || units->year == 0);
  if (out.climatology) {
    for (std::size_t i = 0; i < values.size(); ++i)
      out.times[i] = UtcTime{gregorianYearFraction(kClimatologyYear, calendarYearFraction(*calendar, *units, values[i]))};
    for (std::size_t i = 0; i < out.times.size(); ++i)
      for (std::size_t j = i + 1; j < out.times.size(); ++j)
        if (std::abs(out.times[i].unixSeconds - out.times[j].unixSeconds) < 1.0)
          axisError(label, axisName, "is a climatology with two steps at the same time of year (indices " +
                                         std::to_string(i) + " and " + std::to_string(j) + ")");
  }
  return out;
}

StepChoice chooseClimatologySteps(const std::vector<UtcTime>& times, std::optional<UtcTime> time) {
  StepChoice c;
  if (times.size() < 2 || !time) return c;
  // The steps in order of their position in the year (a climatology may start mid-year).
  std::vector<std::size_t> order(times.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return times[a].unixSeconds < times[b].unixSeconds;
  });
  const double yearS = gregorianYearFraction(kClimatologyYear, 1.0) - gregorianYearFraction(kClimatologyYear, 0.0);
  const double t = climatologyInstant(*time).unixSeconds;
  std::size_t k = 0;  // first step (in year order) strictly after t
  while (k < order.size() && times[order[k]].unixSeconds <= t) ++k;
  // Before the first step or after the last: between the last and the first, across the year end.
  const std::size_t before = order[k == 0 ? order.size() - 1 : k - 1];
  const std::size_t after = order[k == order.size() ? 0 : k];
  double t0 = times[before].unixSeconds;
  double t1 = times[after].unixSeconds;
  if (k == 0) t0 -= yearS;
  if (k == order.size()) t1 += yearS;
  c.first = before;
  c.second = after;
  c.weight = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  if (c.weight == 0.0) c.second = c.first;
  return c;
}

}  // namespace og::data::detail
