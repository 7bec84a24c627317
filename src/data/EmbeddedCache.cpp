#include "data/EmbeddedCache.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <system_error>

#include "core/CacheFile.hpp"
#include "core/Log.hpp"

namespace og::data {
namespace {

std::filesystem::path fileOf(const std::string& name, std::uint64_t key) {
  return embeddedCacheDirectory() / ("embedded-" + name + "-" + core::hex16(key) + ".bin");
}

/// This executable's identity: a rebuild changes the code that derived the data.
std::uint64_t executableIdentity() {
  struct stat st {};
  if (::stat("/proc/self/exe", &st) != 0) return 0;
  return static_cast<std::uint64_t>(st.st_size) * 1000003u ^
         (static_cast<std::uint64_t>(st.st_mtim.tv_sec) * 1000000000u + static_cast<std::uint64_t>(st.st_mtim.tv_nsec));
}

}  // namespace

std::filesystem::path embeddedCacheDirectory() {
  if (const char* off = std::getenv("OCEANGLOBE_NO_DATA_CACHE"); off && std::string(off) == "1") return {};
  return core::cacheDirectory();
}

std::uint64_t embeddedCacheKey(const std::vector<std::string_view>& sources) {
  std::uint64_t key = executableIdentity();
  for (const std::string_view s : sources) {
    const std::uint32_t crc = core::crc32Of(s.data(), s.size());
    key = (key ^ (static_cast<std::uint64_t>(crc) << 32 | s.size())) * 1099511628211ull;
  }
  return key;
}

std::optional<core::CachePayload> loadEmbeddedCache(const std::string& name, std::uint64_t key) {
  if (embeddedCacheDirectory().empty()) return std::nullopt;
  const std::filesystem::path file = fileOf(name, key);
  std::string why;
  auto payload = core::readCacheFile(file, key, &why);
  if (!payload && why != "missing") log::info(file.string() + ": " + why + "; rebuilding it");
  return payload;
}

void storeEmbeddedCache(const std::string& name, std::uint64_t key, const std::vector<std::uint8_t>& payload) {
  if (embeddedCacheDirectory().empty()) return;
  const std::string prefix = "embedded-" + name + "-";
  try {
    // Older builds' files of this name (not another name that merely starts the same).
    core::writeCacheFile(fileOf(name, key), key, payload, [&](const std::string& f) {
      return f.rfind(prefix, 0) == 0 && f.size() == prefix.size() + 16 + 4;
    });
  } catch (const std::exception& e) {
    log::warn(std::string("embedded data not cached: ") + e.what());
  }
}

}  // namespace og::data
