#pragma once
// Internal to og_data (exposed for unit tests): CF-style time coordinates in every CF calendar,
// and climatological axes (docs/data.md, "Time axes").
//
// A time axis becomes UTC instants (UtcTime). The real calendars (standard = mixed Julian /
// Gregorian, proleptic_gregorian, julian) name real days, so their instants are exact. The model
// calendars (noleap / 365_day, all_leap / 366_day, 360_day) have years of another length: a
// model date is placed at the same FRACTION of its year in the Gregorian year of the same
// number (model day d of an L-day year -> d / L of the real year), so seasons line up, the
// mapping is continuous and strictly increasing, and no model date (Feb 30) is refused.
//
// A climatology (CF `climatology` attribute, Ferret's `modulo`, or an axis counting from year 0
// whose steps fit in one year) repeats every year: its steps are kept as positions in the year
// (placed in kClimatologyYear) and a time is matched to them by its position in its own year,
// cyclically across the year end.
#include <optional>
#include <string>
#include <vector>

#include "core/Time.hpp"

namespace og::data {
struct StepChoice;
}

namespace og::data::detail {

/// The calendars of the CF conventions (section 4.4.1).
enum class Calendar { Standard, ProlepticGregorian, Julian, NoLeap, AllLeap, Day360 };

/// The calendar of a CF `calendar` attribute (case-insensitive): "" / standard / gregorian,
/// proleptic_gregorian, julian, noleap / 365_day, all_leap / 366_day, 360_day. nullopt for
/// anything else (e.g. "none" or a user-defined calendar).
std::optional<Calendar> parseCalendar(const std::string& name);

/// The names accepted by parseCalendar, for messages.
inline constexpr const char* kCalendarNames =
    "standard, gregorian, proleptic_gregorian, julian, noleap, 365_day, all_leap, 366_day, "
    "360_day";

/// A parsed CF time unit: instant = epoch + value * secondsPerUnit.
struct TimeUnits {
  double secondsPerUnit = 1.0;
  /// The epoch read as a proleptic Gregorian date (exact for proleptic_gregorian, and for the
  /// standard calendar after 1582-10-15; see epochIn for the others).
  UtcTime epoch;
  int year = 1970;               ///< the epoch as written, in the axis' calendar
  int month = 1;                 ///< 1..12
  int day = 1;                   ///< 1..31 (1..30 in 360_day)
  double secondsOfDay = 0.0;     ///< [0, 86400], after the zone offset
  double offsetSeconds = 0.0;    ///< the zone offset that was subtracted (information)
};

/// Parses "UNIT since DATE[ TIME][ ZONE]" (CF/UDUNITS): UNIT is seconds, minutes, hours or days
/// in the usual spellings (also singular and abbreviated); DATE is Y-M-D (no zero padding
/// needed); TIME is h:m[:s[.f]]; ZONE is Z, UTC or +hh[:mm]. The date must exist in the
/// proleptic Gregorian calendar. nullopt when not understood.
std::optional<TimeUnits> parseTimeUnits(const std::string& units);

/// Same, with the date checked against `calendar` (e.g. 2000-02-30 exists in 360_day).
std::optional<TimeUnits> parseTimeUnits(const std::string& units, Calendar calendar);

/// True for calendars whose dates are real UTC dates: standard, gregorian,
/// proleptic_gregorian (or none given).
bool isRealCalendar(const std::string& calendar);

/// Days in `year` of `calendar` (1582 has 355 in the standard calendar).
int daysInYear(Calendar calendar, long long year);

/// The instant of a date of `calendar` (month 1..12, day 1..31, seconds into the day), as
/// described at the top of this file.
UtcTime instantOf(Calendar calendar, int year, int month, int day, double secondsOfDay);

/// Converts raw axis values to instants (proleptic Gregorian epoch), checking they are finite
/// and strictly increasing. Throws og::InputError "LABEL: problem" naming `axisName`.
std::vector<UtcTime> toInstants(const std::string& label, const std::string& axisName,
                                const std::vector<double>& values, const TimeUnits& units);

/// A decoded time axis.
struct AxisTimes {
  std::vector<UtcTime> times;  ///< strictly increasing; in kClimatologyYear for a climatology
  bool climatology = false;
};

/// The year a climatology's steps are placed in (any non-leap year would do).
inline constexpr int kClimatologyYear = 2001;

/// Decodes a CF time axis: `unitsText` ("hours since ..."), `calendarText` (the attribute, ""
/// when absent), `flaggedClimatology` (the coordinate has a `climatology` or `modulo`
/// attribute). An axis flagged as a climatology, or whose epoch is year 0 and whose steps fit in
/// one year, is a climatology. Throws og::InputError "LABEL: time axis 'NAME' ..." for an unknown
/// calendar or units, unusable values, steps that are not increasing, or a flagged climatology
/// spanning more than a year.
AxisTimes decodeTimeAxis(const std::string& label, const std::string& axisName,
                         const std::vector<double>& values, const std::string& unitsText,
                         const std::string& calendarText, bool flaggedClimatology);

/// Where `time` falls in its (Gregorian, UTC) year, as the same position in kClimatologyYear.
UtcTime climatologyInstant(UtcTime time);

/// The two steps of a climatology (times in kClimatologyYear, strictly increasing) around the
/// position of `time` in its year, cyclically: between the last step and the first of the next
/// year the two are blended across the year end. nullopt time: step 0.
StepChoice chooseClimatologySteps(const std::vector<UtcTime>& times, std::optional<UtcTime> time);

}  // namespace og::data::detail
