#pragma once
// Elevation layers: relief with bathymetry in metres above mean sea level (negative = depth).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "data/LatLonGrid.hpp"
#include "data/ShallowBanks.hpp"

namespace og::data {

/// The heights an elevation layer may hold, m: Earth's relief with a margin. Values outside
/// are refused (og::InputError) rather than drawn.
inline constexpr float kMinElevationM = -12000.0f;
inline constexpr float kMaxElevationM = 10000.0f;

/// Reads an elevation grid (metres above mean sea level, negative below) from a NetCDF file
/// (classic, 64-bit offset or NetCDF-4) or a GRIB file. Units m, km or ft are converted to
/// metres; no units is taken as metres; other units are refused, and so are values outside
/// [kMinElevationM, kMaxElevationM].
/// The latitude/longitude axes are found by CF units (degrees_north / degrees_east) or
/// standard_name, not by name. `variable` names the field; when empty the only 2-D field on
/// those axes is used (or one called ROSE / z / elevation / topo / altitude / height).
/// Throws og::InputError "FILE: problem" for anything unreadable, inconsistent or hostile.
LatLonGrid readElevationFile(const std::filesystem::path& file, const std::string& variable = {});

/// Same, from a NetCDF image in memory; `label` names it in error messages.
LatLonGrid readElevationMemory(std::string_view bytes, const std::string& label,
                               const std::string& variable = {});

/// An `--elevation-layer` spec "FILE[:VAR]": the embedded default when `spec` is empty;
/// `correction` as --elevation-correction says (data/ShallowBanks.hpp: Auto corrects the
/// default's shallow-bank placeholder only, None not even that).
LatLonGrid loadElevationLayer(const std::string& spec, ElevationCorrection correction = ElevationCorrection::Auto);
/// The same, shared: the embedded default (defaultElevation) without a copy of its 9.3 million
/// cells (start-up: one copy was ~40 ms, docs/performance.md).
std::shared_ptr<const LatLonGrid> loadSharedElevationLayer(const std::string& spec,
                                                           ElevationCorrection correction = ElevationCorrection::Auto);

/// Names elevation fields go by (ROSE, z, elevation, topo, ...), tried in order when a file
/// holds several fields and none is named.
const std::vector<std::string>& elevationVariableNames();

/// The default relief embedded in the binary (ETOPO5 at 5', see data/README.md) with its
/// shallow-bank placeholder corrected (correctShallowBanks; logged once).
const LatLonGrid& defaultElevation();
/// The same as the file has it, uncorrected.
LatLonGrid uncorrectedDefaultElevation();

}  // namespace og::data
