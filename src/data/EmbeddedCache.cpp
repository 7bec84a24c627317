#include "data/EmbeddedCache.hpp"

#include <sys/stat.h>
#include <zlib.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include "core/AtomicFile.hpp"
#include "core/Log.hpp"

namespace og::data {
namespace {

constexpr std::array<char, 8> kMagic = {'O', 'G', 'E', 'M', 'B', '0', '0', '1'};

struct Header {
  std::array<char, 8> magic{};
  std::uint64_t key = 0;
  std::uint64_t size = 0;  ///< payload bytes
  std::uint32_t crc = 0;   ///< CRC-32 of the payload
  std::uint32_t reserved = 0;
};

std::uint32_t crc32Of(const std::uint8_t* data, std::size_t n) {
  uLong crc = crc32(0L, Z_NULL, 0);
  while (n > 0) {  // zlib takes uInt lengths
    const auto chunk = static_cast<uInt>(std::min<std::size_t>(n, 1u << 30));
    crc = crc32(crc, data, chunk);
    data += chunk;
    n -= chunk;
  }
  return static_cast<std::uint32_t>(crc);
}

std::string hex(std::uint64_t v) {
  char s[17];
  std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(v));
  return s;
}

std::filesystem::path fileOf(const std::string& name, std::uint64_t key) {
  return embeddedCacheDirectory() / ("embedded-" + name + "-" + hex(key) + ".bin");
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
  if (const char* d = std::getenv("OCEANGLOBE_CACHE_DIR"); d && *d) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "oceanglobe";
  if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "oceanglobe";
  return std::filesystem::temp_directory_path() / "oceanglobe-cache";
}

std::uint64_t embeddedCacheKey(const std::vector<std::string_view>& sources) {
  std::uint64_t key = executableIdentity();
  for (const std::string_view s : sources) {
    const std::uint32_t crc = crc32Of(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
    key = (key ^ (static_cast<std::uint64_t>(crc) << 32 | s.size())) * 1099511628211ull;
  }
  return key;
}

std::optional<std::vector<std::uint8_t>> loadEmbeddedCache(const std::string& name, std::uint64_t key) {
  if (embeddedCacheDirectory().empty()) return std::nullopt;
  const std::filesystem::path file = fileOf(name, key);
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;  // not cached yet (or stale: another key's file)
  Header h;
  std::vector<std::uint8_t> payload;
  std::error_code ec;
  const auto fileSize = std::filesystem::file_size(file, ec);
  if (in.read(reinterpret_cast<char*>(&h), sizeof h) && h.magic == kMagic && h.key == key &&
      !ec && fileSize == sizeof h + h.size) {
    payload.resize(h.size);
    if (in.read(reinterpret_cast<char*>(payload.data()), static_cast<std::streamsize>(h.size)) &&
        crc32Of(payload.data(), payload.size()) == h.crc)
      return payload;
  }
  log::info(file.string() + ": corrupt or truncated cache file; rebuilding it");
  return std::nullopt;
}

void storeEmbeddedCache(const std::string& name, std::uint64_t key, const std::vector<std::uint8_t>& payload) {
  const std::filesystem::path dir = embeddedCacheDirectory();
  if (dir.empty()) return;
  try {
    std::filesystem::create_directories(dir);
    const std::string prefix = "embedded-" + name + "-";
    for (const auto& e : std::filesystem::directory_iterator(dir)) {  // older builds' files
      const std::string f = e.path().filename().string();
      std::error_code ignored;
      if (f.rfind(prefix, 0) == 0 && f.size() == prefix.size() + 16 + 4) std::filesystem::remove(e.path(), ignored);
    }
    Header h;
    h.magic = kMagic;
    h.key = key;
    h.size = payload.size();
    h.crc = crc32Of(payload.data(), payload.size());
    writeFileAtomically(fileOf(name, key), [&](const std::filesystem::path& tmp) {
      std::ofstream out(tmp, std::ios::binary);
      out.write(reinterpret_cast<const char*>(&h), sizeof h);
      out.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
      if (!out.flush()) throw InputError(tmp.string() + ": cannot write");
    });
  } catch (const std::exception& e) {
    log::warn(std::string("embedded data not cached: ") + e.what());
  }
}

}  // namespace og::data
