#pragma once
// Derived data of the embedded defaults (the corrected relief, the decoded land mask and
// imagery) cached on disk beside the atmosphere's tables, so that a second start reads a few
// flat arrays instead of parsing NetCDF, decoding PNG/JPEG through GDAL and re-running the
// shallow-bank correction (docs/performance.md, "Start-up").
//
// A file is `embedded-NAME-KEY.bin` in core/CacheFile's format (magic, key, payload size,
// CRC-32 of the payload, payload; the reader and writer are core's, shared with the
// atmosphere's tables and sky maps). The key hashes the embedded source bytes and this
// executable's identity (its size and modification time), so a rebuild or new data
// invalidates it. A missing, stale, truncated or corrupt file is rebuilt, never trusted and
// never fatal; writes go to a temporary name and are renamed into place.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/CacheFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"

namespace og::data {

/// core::cacheDirectory() (the atmosphere's too); empty when OCEANGLOBE_NO_DATA_CACHE=1 turns the data cache off.
std::filesystem::path embeddedCacheDirectory();

/// The cache key of data derived from `sources` (their bytes) by this executable.
std::uint64_t embeddedCacheKey(const std::vector<std::string_view>& sources);

/// The payload of `embedded-NAME-KEY.bin` when it is intact; nullopt when it is missing,
/// stale or corrupt (logged at info level; the caller rebuilds and stores it).
std::optional<core::CachePayload> loadEmbeddedCache(const std::string& name, std::uint64_t key);

/// Writes `payload` as `embedded-NAME-KEY.bin` (temporary name, then rename) and removes older
/// `embedded-NAME-*.bin`. Never throws: a failure is a warning, the next start rebuilds.
void storeEmbeddedCache(const std::string& name, std::uint64_t key, const std::vector<std::uint8_t>& payload);

/// `what` derived from embedded data, through the cache: the payload of `embedded-NAME-KEY.bin`
/// decoded (`decode(std::span<const std::uint8_t>)` -> std::optional<T>, nullopt when
/// inconsistent) when it is intact, else `build()`, stored (`encode(value)` -> bytes) for the
/// next start. The cached read is
/// timed in the start-up trace as "data: embedded WHAT (from the cache)".
template <class T, class Decode, class Encode, class Build>
T cachedEmbedded(const std::string& name, std::uint64_t key, const std::string& what, Decode decode,
                 Encode encode, Build build) {
  if (const auto bytes = loadEmbeddedCache(name, key)) {
    const core::startup::Scope timed("data: embedded " + what + " (from the cache)");
    if (std::optional<T> cached = decode(bytes->bytes())) return std::move(*cached);
    log::info("embedded " + what + ": the cached copy is inconsistent; rebuilding it");
  }
  T value = build();
  storeEmbeddedCache(name, key, encode(value));
  return value;
}

/// Flat little-endian serialisation for the cache payloads.
class ByteWriter {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  template <class T>
  void put(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(static_cast<std::uint64_t>(v.size()));
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
  }
  [[nodiscard]] std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

/// Reads what ByteWriter wrote; throws og::InputError past the end (a corrupt payload).
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  std::string getString() {
    const auto n = get<std::uint64_t>();
    const auto* p = take(n);
    return std::string(reinterpret_cast<const char*>(p), n);
  }
  template <class T>
  std::vector<T> getVector() {
    const auto n = get<std::uint64_t>();
    if (n > bytes_.size() / sizeof(T)) throw InputError("cache payload: vector longer than the file");
    std::vector<T> v(n);
    std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  [[nodiscard]] bool atEnd() const { return at_ == bytes_.size(); }

 private:
  const std::uint8_t* take(std::size_t n) {
    if (n > bytes_.size() - at_) throw InputError("cache payload: shorter than its contents");
    const std::uint8_t* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

}  // namespace og::data
