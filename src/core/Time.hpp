#pragma once
// UTC instants. Leap seconds are ignored (POSIX time), which is far below the ~0.1° accuracy
// the Sun position needs (1 s of time = 0.004° of Earth rotation).
#include <optional>
#include <string>
#include <string_view>

namespace og {

/// A UTC instant as seconds since 1970-01-01T00:00:00Z (POSIX time, fractional).
struct UtcTime {
  double unixSeconds = 0.0;

  /// Julian Date (days since -4712-01-01T12:00 UTC). Uses UTC for UT1 (|UT1-UTC| < 0.9 s).
  [[nodiscard]] double julianDate() const { return unixSeconds / 86400.0 + 2440587.5; }
  /// Days since J2000.0 (2000-01-01T12:00Z).
  [[nodiscard]] double daysSinceJ2000() const { return julianDate() - 2451545.0; }

  /// Parses ISO-8601 UTC: "YYYY-MM-DDTHH:MM[:SS[.fff]][Z|+00:00]" or a date "YYYY-MM-DD"
  /// (midnight). A space may replace 'T'. Offsets other than zero are applied.
  /// Returns nullopt for anything malformed or out of range (month 13, Feb 30, hour 25...).
  static std::optional<UtcTime> parseIso8601(std::string_view text);

  /// Formats as "YYYY-MM-DDTHH:MM:SSZ" (rounded to the second).
  [[nodiscard]] std::string toIso8601() const;

  static UtcTime fromCivil(int year, unsigned month, unsigned day, int hour = 0, int minute = 0,
                           double second = 0.0);
};

}  // namespace og
