#pragma once
// Inside og_data only: what the NetCDF sources share (NetcdfFile.cpp: the libnetcdf wrapper;
// NetcdfClassic.cpp: checks of the classic formats netCDF-C does not make; NetcdfGridFile.cpp:
// the file as lat/lon grid fields).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace og::data::detail {

/// netCDF-C's classic header parser allocates names and attribute values from header counts
/// before checking them against the file, so a 100-byte file can ask for gigabytes (found by
/// fuzzing). This walks the classic header first and refuses any count the bytes left cannot
/// hold: og::InputError "LABEL: malformed NetCDF header (...)". `read(offset, n, out)` returns
/// false past the end. Files that are not classic (NetCDF-4/HDF5) pass untouched.
void checkClassicHeader(const std::string& label, std::uint64_t size,
                        const std::function<bool(std::uint64_t, std::size_t, unsigned char*)>& read);

/// Whether a netCDF type (nc_type) holds numbers (not text, strings or compound types).
bool isNumericType(int type);

/// netCDF-C reads past the end of a truncated classic file as zeros without an error: throws
/// og::InputError "LABEL: file is truncated (...)" when `fileSize` is below what the open
/// file's header describes. HDF5-based files detect truncation themselves.
void checkComplete(int id, const std::string& label, std::uintmax_t fileSize);

}  // namespace og::data::detail
