#include "data/TimeAxis.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

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

/// Instants outside years 1..9999 are certainly wrong and would overflow formatting.
constexpr double kMinUnixSeconds = -62135596800.0;  // 0001-01-01
constexpr double kMaxUnixSeconds = 253402300799.0;  // 9999-12-31T23:59:59

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
  const std::string s = lower(text);
  const std::size_t since = s.find(" since ");
  if (since == std::string::npos) return std::nullopt;
  std::string unit = s.substr(0, since);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front()))) unit.erase(0, 1);
  const auto perUnit = secondsPer(unit);
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
  const std::chrono::year_month_day ymd{std::chrono::year{*year},
                                        std::chrono::month{static_cast<unsigned>(*month)},
                                        std::chrono::day{static_cast<unsigned>(*day)}};
  if (!ymd.ok()) return std::nullopt;

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
  units.epoch = UtcTime::fromCivil(*year, static_cast<unsigned>(*month),
                                   static_cast<unsigned>(*day), hour, minute, second);
  units.epoch.unixSeconds -= offsetSeconds;
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

}  // namespace og::data::detail
