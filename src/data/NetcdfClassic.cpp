// The classic formats (CDF-1, CDF-2, CDF-5) checked before and after netCDF-C reads them: the
// header's counts against the bytes there are, and the file's size against what its header
// describes (data/NetcdfClassic.hpp).
#include "data/NetcdfInternal.hpp"

#include <netcdf.h>


#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <utility>

#include "core/Error.hpp"
#include "data/GridLayout.hpp"
#include "data/TimeAxis.hpp"


namespace og::data::detail {


/// netCDF-C's classic header parser allocates names and attribute values from header counts
/// before checking them against the file, so a 100-byte file can ask for gigabytes (found by
/// fuzzing). This walks the classic header first and refuses any count the bytes left cannot
/// hold. `read(offset, n, out)` returns false past the end. NetCDF-4/HDF5 is not affected.
void checkClassicHeader(const std::string& label, std::uint64_t size,
                        const std::function<bool(std::uint64_t, std::size_t, unsigned char*)>& read) {
  std::array<unsigned char, 4> magic{};
  if (!read(0, 4, magic.data()) || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F') return;
  const int version = magic[3];
  if (version != 1 && version != 2 && version != 5) return;  // netCDF-C names the problem
  const std::size_t countBytes = version == 5 ? 8 : 4;
  const std::size_t offsetBytes = version == 1 ? 4 : 8;
  std::uint64_t pos = 4;
  const auto bad = [&](const std::string& what) {
    throw InputError(label + ": malformed NetCDF header (" + what + " at byte " +
                     std::to_string(pos) + ")");
  };
  const auto number = [&](std::size_t bytes) {
    std::array<unsigned char, 8> b{};
    if (!read(pos, bytes, b.data())) bad("header runs past the end of the file");
    pos += bytes;
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < bytes; ++i) v = (v << 8) | b[i];
    return v;
  };
  const auto left = [&] { return size > pos ? size - pos : 0; };
  const auto skip = [&](std::uint64_t bytes, const char* what) {
    if (bytes > left()) bad(std::string(what) + " longer than the file");
    pos += (bytes + 3) / 4 * 4;
  };
  const auto name = [&] {
    const std::uint64_t n = number(countBytes);
    if (n > NC_MAX_NAME) bad("name of " + std::to_string(n) + " bytes");
    skip(n, "name");
  };
  const auto typeSize = [&](std::uint64_t type) -> std::uint64_t {
    switch (type) {
      case 1: case 2: case 7: return 1;
      case 3: case 8: return 2;
      case 4: case 5: case 9: return 4;
      case 6: case 10: case 11: return 8;
      default:
        bad("unknown type " + std::to_string(type));
        return 1;  // not reached: bad() throws
    }
  };
  const auto list = [&](std::uint64_t expectedTag, std::uint64_t minElementBytes,
                        const std::function<void()>& element) {
    const std::uint64_t tag = number(4);
    const std::uint64_t n = number(countBytes);
    if (tag == 0 && n == 0) return;
    if (tag != expectedTag) bad("unexpected tag " + std::to_string(tag));
    if (n > left() / minElementBytes) bad("list of " + std::to_string(n) + " entries");
    for (std::uint64_t i = 0; i < n; ++i) element();
  };
  const auto attributes = [&] {
    list(0x0C, 12, [&] {
      name();
      const std::uint64_t size1 = typeSize(number(4));
      const std::uint64_t n = number(countBytes);
      if (n > left() / size1) bad("attribute of " + std::to_string(n) + " values");
      skip(n * size1, "attribute");
    });
  };
  (void)number(countBytes);  // numrecs
  list(0x0A, 8, [&] {
    name();
    (void)number(countBytes);
  });
  attributes();
  list(0x0B, 16, [&] {
    name();
    const std::uint64_t rank = number(countBytes);
    if (rank > NC_MAX_VAR_DIMS || rank > left() / countBytes)
      bad("variable of " + std::to_string(rank) + " dimensions");
    pos += rank * countBytes;
    attributes();
    (void)typeSize(number(4));
    (void)number(countBytes);  // vsize
    (void)number(offsetBytes);  // begin
  });
}

// ---------------------------------------------------------------------------------------------
// Truncation check for the classic formats. netCDF-C reads past the end of a truncated
// classic file as zeros without an error, so we compute the smallest size the header's
// contents require (the header as written without padding, then every variable's data) and
// compare. HDF5-based files detect truncation themselves.

namespace {

std::uintmax_t padded4(std::uintmax_t n) { return (n + 3) / 4 * 4; }

/// Sizes in bytes of the classic encoding, by format: CDF-1, CDF-2 (64-bit offset), CDF-5.
struct ClassicEncoding {
  std::uintmax_t count = 4;   ///< element counts, dimension lengths, vsize
  std::uintmax_t offset = 4;  ///< a variable's `begin`
};

std::uintmax_t typeSize(int id, nc_type type) {
  std::size_t size = 0;
  return nc_inq_type(id, type, nullptr, &size) == NC_NOERR ? size : 0;
}

std::uintmax_t nameBytes(const ClassicEncoding& e, const char* name) {
  return e.count + padded4(std::char_traits<char>::length(name));
}

std::uintmax_t attributeListBytes(int id, int varid, const ClassicEncoding& e) {
  int natts = 0;
  if (varid == NC_GLOBAL ? nc_inq_natts(id, &natts) != NC_NOERR
                         : nc_inq_varnatts(id, varid, &natts) != NC_NOERR)
    return 0;
  std::uintmax_t bytes = 4 + e.count;  // tag (or ZERO) and element count
  for (int a = 0; a < natts; ++a) {
    std::array<char, NC_MAX_NAME + 1> name{};
    nc_type type = NC_NAT;
    std::size_t length = 0;
    if (nc_inq_attname(id, varid, a, name.data()) != NC_NOERR ||
        nc_inq_att(id, varid, name.data(), &type, &length) != NC_NOERR)
      continue;
    bytes += nameBytes(e, name.data()) + 4 + e.count + padded4(length * typeSize(id, type));
  }
  return bytes;
}

}  // namespace

void checkComplete(int id, const std::string& label, std::uintmax_t fileSize) {
  int format = 0;
  if (nc_inq_format(id, &format) != NC_NOERR) return;
  ClassicEncoding e;
  if (format == NC_FORMAT_64BIT_OFFSET) {
    e.offset = 8;
  } else if (format == NC_FORMAT_CDF5) {
    e.count = 8;
    e.offset = 8;
  } else if (format != NC_FORMAT_CLASSIC) {
    return;
  }
  int ndims = 0;
  int nvars = 0;
  int unlimited = -1;
  if (nc_inq(id, &ndims, &nvars, nullptr, &unlimited) != NC_NOERR) return;

  std::uintmax_t header = 4 + e.count;  // magic, numrecs
  header += 4 + e.count;                // dimension list tag and count
  std::vector<std::uintmax_t> dimLength(static_cast<std::size_t>(std::max(ndims, 0)), 0);
  for (int d = 0; d < ndims; ++d) {
    std::array<char, NC_MAX_NAME + 1> name{};
    std::size_t length = 0;
    if (nc_inq_dim(id, d, name.data(), &length) != NC_NOERR) return;
    dimLength[static_cast<std::size_t>(d)] = length;
    header += nameBytes(e, name.data()) + e.count;
  }
  header += attributeListBytes(id, NC_GLOBAL, e);
  header += 4 + e.count;  // variable list tag and count

  // Data: fixed-size variables, then `numrecs` records of all record variables.
  std::uintmax_t fixedData = 0;
  std::uintmax_t recordSize = 0;
  int recordVars = 0;
  std::uintmax_t lastRecordVarSize = 0;
  const std::uintmax_t numrecs =
      unlimited >= 0 ? dimLength[static_cast<std::size_t>(unlimited)] : 0;
  for (int v = 0; v < nvars; ++v) {
    std::array<char, NC_MAX_NAME + 1> name{};
    std::array<int, NC_MAX_VAR_DIMS> dims{};
    nc_type type = NC_NAT;
    int rank = 0;
    if (nc_inq_var(id, v, name.data(), &type, &rank, dims.data(), nullptr) != NC_NOERR) return;
    header += nameBytes(e, name.data()) + e.count + static_cast<std::uintmax_t>(rank) * e.count;
    header += attributeListBytes(id, v, e) + 4 + e.count + e.offset;
    const bool isRecord = rank > 0 && dims[0] == unlimited;
    // Saturating product: a hostile header cannot wrap this around to a small number.
    std::uintmax_t size = typeSize(id, type);
    for (int d = isRecord ? 1 : 0; d < rank; ++d) {
      const std::uintmax_t n =
          dimLength[static_cast<std::size_t>(dims[static_cast<std::size_t>(d)])];
      size = (n != 0 && size > UINTMAX_MAX / n) ? UINTMAX_MAX : size * n;
    }
    if (isRecord) {
      ++recordVars;
      lastRecordVarSize = size;
      recordSize = std::min(UINTMAX_MAX - padded4(size), recordSize) + padded4(size);
    } else {
      fixedData = std::min(UINTMAX_MAX - padded4(size), fixedData) + padded4(size);
    }
  }
  // A lone record variable's records are not padded.
  if (recordVars == 1) recordSize = lastRecordVarSize;
  std::uintmax_t required = header;
  const auto add = [&](std::uintmax_t n) {
    required = required > UINTMAX_MAX - n ? UINTMAX_MAX : required + n;
  };
  add(fixedData);
  add(numrecs != 0 && recordSize > UINTMAX_MAX / numrecs ? UINTMAX_MAX : recordSize * numrecs);
  // The last variable's padding may legitimately be missing from the file.
  if (fileSize + 3 < required)
    throw InputError(label + ": file is truncated (" + std::to_string(fileSize) +
                     " bytes, the header describes at least " + std::to_string(required) + ")");
}

}  // namespace og::data::detail
