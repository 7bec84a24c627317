#include "core/CacheFile.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <system_error>
#include <utility>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace og::core {
namespace {

constexpr std::array<char, 8> kMagic = {'O', 'G', 'C', 'A', 'C', 'H', 'E', '1'};

struct Header {
  std::array<char, 8> magic{};
  std::uint64_t key = 0;
  std::uint64_t size = 0;  ///< payload bytes
  std::uint32_t crc = 0;   ///< CRC-32 of the payload
  std::uint32_t reserved = 0;
};
static_assert(sizeof(Header) == 32);

void removeSuperseded(const std::filesystem::path& file,
                      const std::function<bool(const std::string& fileName)>& superseded) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it(file.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code ignored;
    if (name != file.filename().string() && superseded(name)) std::filesystem::remove(it->path(), ignored);
  }
}

}  // namespace

std::filesystem::path cacheDirectory() {
  if (const char* d = std::getenv("OCEANGLOBE_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "oceanglobe";
  if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "oceanglobe";
  return std::filesystem::temp_directory_path() / "oceanglobe-cache";
}

std::uint32_t crc32Of(const void* data, std::size_t n) {
  const auto* p = static_cast<const Bytef*>(data);
  uLong crc = crc32(0L, Z_NULL, 0);
  while (n > 0) {  // zlib takes uInt lengths
    const auto chunk = static_cast<uInt>(std::min<std::size_t>(n, std::size_t{1} << 30));
    crc = crc32(crc, p, chunk);
    p += chunk;
    n -= chunk;
  }
  return static_cast<std::uint32_t>(crc);
}

std::string hex16(std::uint64_t v) {
  char s[17];
  std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(v));
  return s;
}

CachePayload::CachePayload(CachePayload&& o) noexcept
    : map_(std::exchange(o.map_, nullptr)), mapBytes_(std::exchange(o.mapBytes_, 0)),
      data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}

CachePayload& CachePayload::operator=(CachePayload&& o) noexcept {
  if (this != &o) {
    CachePayload gone(std::move(*this));
    map_ = std::exchange(o.map_, nullptr);
    mapBytes_ = std::exchange(o.mapBytes_, 0);
    data_ = std::exchange(o.data_, nullptr);
    size_ = std::exchange(o.size_, 0);
  }
  return *this;
}

CachePayload::~CachePayload() {
  if (map_ != nullptr) ::munmap(map_, mapBytes_);
}

std::optional<CachePayload> readCacheFile(const std::filesystem::path& file, std::uint64_t key, std::string* whyNot) {
  auto reject = [&](const char* why) -> std::optional<CachePayload> {
    if (whyNot != nullptr) *whyNot = why;
    return std::nullopt;
  };
  // Non-blocking: a FIFO in the file's place must not hang the open (it is rejected below).
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return reject("missing");
  struct stat st {};
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const auto fileSize = regular ? static_cast<std::uintmax_t>(st.st_size) : 0;
  if (!regular || fileSize < sizeof(Header) || fileSize > SIZE_MAX) {
    ::close(fd);
    return reject(!regular ? "not a regular file" : fileSize < sizeof(Header) ? "truncated header" : "too large");
  }
  // Mapped, not read: the pages are the page cache's own (no copy into fresh zeroed pages;
  // MAP_POPULATE maps them all at once). Our writer replaces a file by renaming a new one over
  // it, which leaves this mapping's file intact; another program truncating the file in place
  // while it is mapped would make the reads fault (SIGBUS), a race this cache accepts.
  void* map = ::mmap(nullptr, fileSize, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  ::close(fd);
  if (map == MAP_FAILED) return reject("cannot be mapped");
  CachePayload payload;
  payload.map_ = map;
  payload.mapBytes_ = fileSize;
  Header h;
  std::memcpy(&h, map, sizeof h);
  if (h.magic != kMagic) return reject("not an oceanglobe cache file");
  if (h.key != key) return reject("stale key");
  if (h.size != fileSize - sizeof h) return reject("size field disagrees with the file's size");
  payload.data_ = static_cast<const std::uint8_t*>(map) + sizeof h;
  payload.size_ = static_cast<std::size_t>(h.size);
  if (crc32Of(payload.data_, payload.size_) != h.crc) return reject("CRC mismatch");
  return payload;
}

void writeCacheFile(const std::filesystem::path& file, std::uint64_t key, const std::vector<std::uint8_t>& payload,
                    const std::function<bool(const std::string& fileName)>& superseded) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) throw InputError(file.parent_path().string() + ": cannot create the cache directory: " + ec.message());
  removeSuperseded(file, superseded);
  Header h;
  h.magic = kMagic;
  h.key = key;
  h.size = payload.size();
  h.crc = crc32Of(payload.data(), payload.size());
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
    if (!out.flush()) throw InputError(tmp.string() + ": cannot write");
  });
}

}  // namespace og::core
