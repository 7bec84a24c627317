#pragma once
// Wind fields: the 10 m wind's eastward (u) and northward (v) components in m/s on a regular
// latitude/longitude grid, at one instant, read from NetCDF or GRIB files.
#include <filesystem>
#include <memory>
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

/// A wind file to read any of its time steps from (a layer whose wind follows the clock).
/// The file is opened for each read and closed after it: an open NetCDF file holds netCDF-C's
/// process-wide lock (NetcdfFile), so a file kept open would block every other file.
class WindSeries {
 public:
  /// Over an open file that outlives the series (readWind). Chooses and validates the u/v
  /// pair as readWind does. Throws og::InputError.
  WindSeries(const GridFile& file, const std::vector<std::string>& variables);
  /// Opens a `--wind-layer` spec "FILE[:U,V]", validates it and closes it again.
  static std::shared_ptr<const WindSeries> open(const std::string& spec);

  [[nodiscard]] const std::string& label() const { return label_; }
  /// The u field's geometry and time axis (v has the same).
  [[nodiscard]] const FieldDescription& axis() const { return u_; }
  /// The steps and weight that make up `time` (clamped; cyclic for a climatology).
  [[nodiscard]] StepChoice choose(std::optional<UtcTime> time) const { return chooseFieldSteps(u_, time); }
  /// Step `step`, in m/s; NaN = no data. `time` is the step's instant (nullopt for a
  /// climatology or an untimed file). Throws og::InputError (e.g. the file changed).
  [[nodiscard]] WindGrid readStep(std::size_t step) const;
  /// The strongest wind of any step, m/s (the file opened once for all steps).
  [[nodiscard]] double maxSpeedMs() const;

 private:
  WindSeries() = default;
  void describe(const GridFile& file, const std::vector<std::string>& variables);
  [[nodiscard]] WindGrid readStep(const GridFile& file, std::size_t step) const;
  /// Calls f(file) with the borrowed file, or the file reopened for the call.
  template <class F>
  auto withFile(F&& f) const;

  const GridFile* borrowed_ = nullptr;
  std::filesystem::path path_;  ///< reopened for each read when nothing is borrowed
  std::string label_;
  WindVariables names_;
  FieldDescription u_;
  double uFactor_ = 1.0;
  double vFactor_ = 1.0;
};

/// `a` and `b` blended, (1 - weight)·a + weight·b per cell; NaN in either stays NaN (no data is
/// never blended into data). Same geometry required (WindSeries steps have it).
WindGrid blendWind(const WindGrid& a, const WindGrid& b, double weight);

/// A `--wind-layer` spec "FILE[:U,V]" (NetCDF or GRIB), read as by readWind.
WindGrid readWindLayer(const std::string& spec, std::optional<UtcTime> time);

/// The embedded default wind: one month of global monthly-mean winds, 2.5°, from the FNOC
/// (US Navy) monthly winds in ferret-datasets (see data/README.md).
const WindGrid& defaultWind();

}  // namespace og::data
