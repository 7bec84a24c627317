#pragma once
// A synthetic ERA5-like wind file for `oceanglobe bench`: the layout of a global 0.25° ERA5
// download (u10/v10 as packed shorts with scale_factor/add_offset/_FillValue, latitude 90…−90
// descending, longitude 0…359.75, one valid_time step), with a smooth made-up wind.
#include <filesystem>

namespace og::data {

enum class SyntheticFormat {
  kClassic64,      ///< NetCDF 64-bit offset (CDS's netCDF3 downloads)
  kNetcdf4Deflate  ///< NetCDF-4/HDF5, zlib level 1 with shuffle, one chunk per field
};

/// Writes u10/v10 on a global grid of `columns` x `rows` cells (1440 x 721 for 0.25°) to
/// `file`, replacing it. Throws og::InternalError on any netCDF-C error.
void writeSyntheticEra5Wind(const std::filesystem::path& file, SyntheticFormat format,
                            int columns = 1440, int rows = 721);

}  // namespace og::data
