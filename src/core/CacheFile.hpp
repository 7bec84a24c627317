#pragma once
// One on-disk cache format for everything derived at start-up that a second start can read
// back: the embedded data's decoded arrays (data/EmbeddedCache), the atmosphere's tables and
// its sky maps (render/Atmosphere). docs/performance.md, "Start-up"; docs/atmosphere.md.
//
// A file is a 32-byte header (magic "OGCACHE1", the key, the payload's size in bytes, the
// payload's CRC-32, 4 reserved bytes) and the payload. A missing, truncated, over- or
// under-long, foreign (wrong magic), stale (wrong key) or corrupt (CRC) file is rejected with a
// reason, never trusted and never fatal; the size field is checked against the file's size
// before anything is allocated. Writes go to a temporary name and are renamed into place, after
// the directory's superseded files (the caller says which) are removed.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace og::core {

/// $OCEANGLOBE_CACHE_DIR, else $XDG_CACHE_HOME/oceanglobe, else ~/.cache/oceanglobe, else
/// <temp>/oceanglobe-cache.
std::filesystem::path cacheDirectory();

/// CRC-32 (zlib's, ISO 3309) of `n` bytes.
std::uint32_t crc32Of(const void* data, std::size_t n);

/// 64-bit hex, zero-padded to 16 digits (cache file names).
std::string hex16(std::uint64_t v);

/// A cache file's payload, read-only, mapped from the file rather than read into a buffer: the
/// pages are the page cache's, so reading a 37 MB relief costs neither a copy nor 9000 fresh
/// zeroed pages at start-up (its decoder still copies what it keeps; docs/performance.md,
/// "Twenty-sixth session"). Movable, not copyable; empty when default-constructed.
class CachePayload {
 public:
  CachePayload() = default;
  CachePayload(CachePayload&& other) noexcept;
  CachePayload& operator=(CachePayload&& other) noexcept;
  CachePayload(const CachePayload&) = delete;
  CachePayload& operator=(const CachePayload&) = delete;
  ~CachePayload();

  [[nodiscard]] const std::uint8_t* data() const { return data_; }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] std::span<const std::uint8_t> bytes() const { return {data_, size_}; }

 private:
  friend std::optional<CachePayload> readCacheFile(const std::filesystem::path&, std::uint64_t, std::string*);
  void* map_ = nullptr;  ///< the whole file (header too), mmap'ed
  std::size_t mapBytes_ = 0;
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
};

/// The payload of cache file `file` when it is intact and was written with `key`; nullopt
/// otherwise, with the reason in `*whyNot` when given ("missing" when there is no file).
std::optional<CachePayload> readCacheFile(const std::filesystem::path& file, std::uint64_t key,
                                          std::string* whyNot = nullptr);

/// Writes `payload` as cache file `file` (its directory created; temporary name, then rename)
/// with `key`, first removing the files of that directory for which `superseded(fileName)` is
/// true (never `file` itself). Throws og::InputError when the file cannot be written.
void writeCacheFile(const std::filesystem::path& file, std::uint64_t key, const std::vector<std::uint8_t>& payload,
                    const std::function<bool(const std::string& fileName)>& superseded);

}  // namespace og::core
