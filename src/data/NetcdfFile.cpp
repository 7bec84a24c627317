#include "data/NetcdfFile.hpp"

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

#include "data/NetcdfInternal.hpp"

namespace og::data::detail {
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// NetcdfFile: the libnetcdf wrapper

namespace {
std::mutex& libraryMutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

NetcdfFile::NetcdfFile(int id, std::string label, std::vector<char> memory,
                       std::unique_lock<std::mutex> lock)
    : lock_(std::move(lock)), id_(id), label_(std::move(label)), memory_(std::move(memory)) {}

NetcdfFile::NetcdfFile(NetcdfFile&& other) noexcept
    : lock_(std::move(other.lock_)),
      id_(std::exchange(other.id_, -1)),
      label_(std::move(other.label_)),
      memory_(std::move(other.memory_)) {}

NetcdfFile::~NetcdfFile() {
  if (id_ >= 0) nc_close(id_);
}

NetcdfFile NetcdfFile::open(const fs::path& file) {
  const std::string label = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(label + ": no such file");
  if (!fs::is_regular_file(file, ec)) throw InputError(label + ": not a regular file");
  {
    const std::uintmax_t size = fs::file_size(file, ec);
    std::ifstream in(file, std::ios::binary);
    checkClassicHeader(label, ec ? 0 : size,
                       [&](std::uint64_t offset, std::size_t n, unsigned char* out) {
                         if (ec || offset > size || n > size - offset) return false;
                         in.seekg(static_cast<std::streamoff>(offset));
                         in.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n));
                         return static_cast<std::size_t>(in.gcount()) == n;
                       });
  }
  std::unique_lock lock(libraryMutex());
  int id = -1;
  const int status = nc_open(file.c_str(), NC_NOWRITE, &id);
  if (status != NC_NOERR)
    throw InputError(label + ": not a readable NetCDF or GRIB file (" + nc_strerror(status) + ")");
  NetcdfFile opened(id, label, {}, std::move(lock));
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) opened.fail("cannot determine the file size: " + ec.message());
  checkComplete(id, label, size);
  return opened;
}

NetcdfFile NetcdfFile::openMemory(std::string_view bytes, const std::string& label) {
  if (bytes.empty()) throw InputError(label + ": empty NetCDF image");
  checkClassicHeader(label, bytes.size(), [&](std::uint64_t offset, std::size_t n, unsigned char* out) {
    if (offset > bytes.size() || n > bytes.size() - offset) return false;
    std::memcpy(out, bytes.data() + offset, n);
    return true;
  });
  // nc_open_mem wants a writable buffer that outlives the dataset; keep our own copy.
  std::vector<char> memory(bytes.begin(), bytes.end());
  std::unique_lock lock(libraryMutex());
  int id = -1;
  const int status = nc_open_mem(label.c_str(), NC_NOWRITE, memory.size(), memory.data(), &id);
  if (status != NC_NOERR)
    throw InputError(label + ": not a readable NetCDF image (" + nc_strerror(status) + ")");
  const std::size_t size = memory.size();
  NetcdfFile opened(id, label, std::move(memory), std::move(lock));
  checkComplete(id, label, size);
  return opened;
}

void NetcdfFile::fail(const std::string& problem) const {
  throw InputError(label_ + ": " + problem);
}

void NetcdfFile::check(int status, const std::string& doing) const {
  if (status != NC_NOERR) fail(doing + ": " + nc_strerror(status));
}

bool isNumericType(int type) {
  switch (type) {
    case NC_BYTE:
    case NC_UBYTE:
    case NC_SHORT:
    case NC_USHORT:
    case NC_INT:
    case NC_UINT:
    case NC_INT64:
    case NC_UINT64:
    case NC_FLOAT:
    case NC_DOUBLE:
      return true;
    default:
      return false;
  }
}

namespace {
/// Attributes longer than this are not metadata we want; refuse to allocate for them.
constexpr std::size_t kMaxAttributeLength = 65536;
constexpr std::size_t kMaxNumericAttributeLength = 64;

std::string trim(std::string text) {
  const auto blank = [](char c) {
    return c == '\0' || std::isspace(static_cast<unsigned char>(c));
  };
  while (!text.empty() && blank(text.back())) text.pop_back();
  std::size_t start = 0;
  while (start < text.size() && blank(text[start])) ++start;
  return text.substr(start);
}

}  // namespace

std::optional<std::string> NetcdfFile::textAttribute(int varid, const char* name) const {
  nc_type type = NC_NAT;
  std::size_t length = 0;
  if (nc_inq_att(id_, varid, name, &type, &length) != NC_NOERR) return std::nullopt;
  if (type == NC_CHAR) {
    if (length > kMaxAttributeLength) return std::nullopt;
    std::string text(length, '\0');
    if (length > 0)
      check(nc_get_att_text(id_, varid, name, text.data()),
            std::string("cannot read attribute '") + name + "'");
    return trim(std::move(text));
  }
  if (type == NC_STRING && length >= 1 && length <= kMaxNumericAttributeLength) {
    std::vector<char*> strings(length, nullptr);
    check(nc_get_att_string(id_, varid, name, strings.data()),
          std::string("cannot read attribute '") + name + "'");
    std::string text = strings[0] != nullptr ? strings[0] : "";
    nc_free_string(length, strings.data());
    return trim(std::move(text));
  }
  return std::nullopt;
}

std::optional<NetcdfFile::Numbers> NetcdfFile::numericAttribute(int varid, const char* name) const {
  nc_type type = NC_NAT;
  std::size_t length = 0;
  if (nc_inq_att(id_, varid, name, &type, &length) != NC_NOERR) return std::nullopt;
  if (!isNumericType(type) || length < 1 || length > kMaxNumericAttributeLength)
    fail(std::string("attribute '") + name + "' must hold 1 to " +
         std::to_string(kMaxNumericAttributeLength) + " numbers");
  Numbers numbers;
  numbers.type = type;
  numbers.values.resize(length);
  // netCDF reports NC_ERANGE for values that do not fit a double only in exotic cases.
  check(nc_get_att_double(id_, varid, name, numbers.values.data()),
        std::string("cannot read attribute '") + name + "'");
  return numbers;
}

}  // namespace og::data::detail
