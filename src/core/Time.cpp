#include "core/Time.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace og {
namespace {
namespace chr = std::chrono;

// Reads exactly `n` digits; advances `pos`.
std::optional<int> digits(std::string_view s, std::size_t& pos, int n) {
  if (pos + static_cast<std::size_t>(n) > s.size()) return std::nullopt;
  int v = 0;
  for (int i = 0; i < n; ++i) {
    const char c = s[pos + static_cast<std::size_t>(i)];
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  pos += static_cast<std::size_t>(n);
  return v;
}

bool expect(std::string_view s, std::size_t& pos, char c) {
  if (pos < s.size() && s[pos] == c) {
    ++pos;
    return true;
  }
  return false;
}
}  // namespace

UtcTime UtcTime::fromCivil(int year, unsigned month, unsigned day, int hour, int minute,
                           double second) {
  const chr::sys_days d = chr::year{year} / chr::month{month} / chr::day{day};
  const double days = static_cast<double>(d.time_since_epoch().count());
  return UtcTime{days * 86400.0 + hour * 3600.0 + minute * 60.0 + second};
}

std::optional<UtcTime> UtcTime::parseIso8601(std::string_view s) {
  std::size_t p = 0;
  const auto y = digits(s, p, 4);
  if (!y || !expect(s, p, '-')) return std::nullopt;
  const auto mo = digits(s, p, 2);
  if (!mo || !expect(s, p, '-')) return std::nullopt;
  const auto d = digits(s, p, 2);
  if (!d) return std::nullopt;
  const chr::year_month_day ymd{chr::year{*y}, chr::month{static_cast<unsigned>(*mo)},
                                chr::day{static_cast<unsigned>(*d)}};
  if (!ymd.ok()) return std::nullopt;
  int hh = 0, mm = 0;
  double ss = 0.0, offset = 0.0;
  if (p < s.size()) {
    if (s[p] != 'T' && s[p] != 't' && s[p] != ' ') return std::nullopt;
    ++p;
    const auto h = digits(s, p, 2);
    if (!h || !expect(s, p, ':')) return std::nullopt;
    const auto m = digits(s, p, 2);
    if (!m) return std::nullopt;
    hh = *h;
    mm = *m;
    if (expect(s, p, ':')) {
      const auto sec = digits(s, p, 2);
      if (!sec) return std::nullopt;
      ss = *sec;
      if (expect(s, p, '.') || expect(s, p, ',')) {
        double scale = 0.1;
        const std::size_t start = p;
        while (p < s.size() && s[p] >= '0' && s[p] <= '9') {
          ss += (s[p] - '0') * scale;
          scale *= 0.1;
          ++p;
        }
        if (p == start) return std::nullopt;
      }
    }
    if (hh > 24 || mm > 59 || ss >= 61.0 || (hh == 24 && (mm != 0 || ss != 0.0)))
      return std::nullopt;
    if (p < s.size()) {
      if (s[p] == 'Z' || s[p] == 'z') {
        ++p;
      } else if (s[p] == '+' || s[p] == '-') {
        const double sign = s[p] == '+' ? 1.0 : -1.0;
        ++p;
        const auto oh = digits(s, p, 2);
        if (!oh) return std::nullopt;
        expect(s, p, ':');
        const auto om = digits(s, p, 2);
        if (!om || *oh > 23 || *om > 59) return std::nullopt;
        offset = sign * (*oh * 3600.0 + *om * 60.0);
      }
    }
    if (p != s.size()) return std::nullopt;
  }
  UtcTime t = fromCivil(*y, static_cast<unsigned>(*mo), static_cast<unsigned>(*d), hh, mm, ss);
  t.unixSeconds -= offset;
  return t;
}

std::string UtcTime::toIso8601() const {
  const double rounded = std::floor(unixSeconds + 0.5);
  const auto days = static_cast<long>(std::floor(rounded / 86400.0));
  const auto secOfDay = static_cast<long>(rounded - static_cast<double>(days) * 86400.0);
  const chr::year_month_day ymd{chr::sys_days{chr::days{days}}};
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02ld:%02ld:%02ldZ", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                secOfDay / 3600, (secOfDay / 60) % 60, secOfDay % 60);
  return buf;
}

}  // namespace og
