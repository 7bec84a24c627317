#pragma once
// Elevation layers: relief with bathymetry in metres above mean sea level (negative = depth).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "data/LatLonGrid.hpp"

namespace og::data {

/// Reads an elevation grid from a NetCDF file (classic, 64-bit offset or NetCDF-4).
/// The latitude/longitude axes are found by CF units (degrees_north / degrees_east) or
/// standard_name, not by name. `variable` names the field; when empty the only 2-D field on
/// those axes is used (or one called ROSE / z / elevation / topo / altitude / height).
/// Throws og::InputError "FILE: problem" for anything unreadable, inconsistent or hostile.
LatLonGrid readElevationFile(const std::filesystem::path& file, const std::string& variable = {});

/// Same, from a NetCDF image in memory; `label` names it in error messages.
LatLonGrid readElevationMemory(std::string_view bytes, const std::string& label,
                               const std::string& variable = {});

/// The default relief embedded in the binary (derived from ETOPO20, see data/README.md).
const LatLonGrid& defaultElevation();

}  // namespace og::data
