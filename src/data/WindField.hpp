#pragma once
// Wind fields: the 10 m wind's eastward (u) and northward (v) components in m/s on a regular
// latitude/longitude grid, at one instant, read from NetCDF or GRIB files.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Time.hpp"
#include "data/GridFile.hpp"
#include "data/LatLonGrid.hpp"

namespace og::data {

/// One wind layer at one instant. `u` and `v` share their geometry; NaN = no data.
struct WindGrid {
  std::string label;            ///< the file (or memory label) it came from
  LatLonGrid u;                 ///< eastward component, m/s (name = the file's variable)
  LatLonGrid v;                 ///< northward component, m/s
  std::optional<UtcTime> time;  ///< the instant it represents; nullopt for an untimed file
};

/// The file's u and v fields: `requested` ({} or {U, V}) if given, else by CF standard_name
/// (eastward_wind/northward_wind), else by the usual names (u10/v10, 10u/10v, UGRD/VGRD,
/// U10/V10, uwnd/vwnd, UWND/VWND, uas/vas, then u/v, U/V). Throws InputError naming what was found.
struct WindVariables {
  std::string u;
  std::string v;
};
WindVariables chooseWindVariables(const GridFile& file, const std::vector<std::string>& requested);

/// Metres per second per unit of `units` (m/s in its spellings: 1; knots: 0.514444...;
/// km/h: 1/3.6); nullopt for anything else. Empty units are not accepted here.
std::optional<double> metresPerSecondPerUnit(const std::string& units);

/// Reads u and v at `time`: with a time axis the two steps around it are interpolated linearly
/// (clamped to the first/last step outside the axis; the first step when `time` is nullopt).
/// Values are converted to m/s; fields without units are taken as m/s with a warning.
WindGrid readWind(const GridFile& file, const std::vector<std::string>& variables,
                  std::optional<UtcTime> time);

/// A `--wind-layer` spec "FILE[:U,V]" (NetCDF or GRIB), read as by readWind.
WindGrid readWindLayer(const std::string& spec, std::optional<UtcTime> time);

/// The embedded default wind: one month of global monthly-mean winds, 2.5°, from the FNOC
/// (US Navy) monthly winds in ferret-datasets (see data/README.md).
const WindGrid& defaultWind();

}  // namespace og::data
