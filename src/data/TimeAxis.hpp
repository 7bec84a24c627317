#pragma once
// Internal to og_data (exposed for unit tests): CF-style time coordinates.
#include <optional>
#include <string>
#include <vector>

#include "core/Time.hpp"

namespace og::data::detail {

/// A parsed CF time unit: instant = epoch + value * secondsPerUnit.
struct TimeUnits {
  double secondsPerUnit = 1.0;
  UtcTime epoch;
};

/// Parses "UNIT since DATE[ TIME][ ZONE]" (CF/UDUNITS): UNIT is seconds, minutes, hours or days
/// in the usual spellings (also singular and abbreviated); DATE is Y-M-D (no zero padding
/// needed); TIME is h:m[:s[.f]]; ZONE is Z, UTC or +hh[:mm]. nullopt when not understood.
std::optional<TimeUnits> parseTimeUnits(const std::string& units);

/// True for calendars whose dates are real UTC dates: standard, gregorian,
/// proleptic_gregorian (or none given). Dates before 1582 are read as proleptic Gregorian.
bool isRealCalendar(const std::string& calendar);

/// Converts raw axis values to instants, checking they are finite and strictly increasing.
/// Throws og::InputError "LABEL: problem" naming `axisName`.
std::vector<UtcTime> toInstants(const std::string& label, const std::string& axisName,
                                const std::vector<double>& values, const TimeUnits& units);

}  // namespace og::data::detail
