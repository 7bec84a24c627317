#include "core/Plugin.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include "core/Error.hpp"

namespace og::plugin {
namespace {

const Host kHost{OG_PLUGIN_ABI, &log::write, &log::level};

std::vector<std::filesystem::path> searchDirs() {
  std::vector<std::filesystem::path> dirs;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(self.parent_path());
  const std::filesystem::path built(OG_PLUGIN_DIR);
  if (dirs.empty() || !std::filesystem::equivalent(dirs.front(), built, ec)) dirs.push_back(built);
  return dirs;
}

}  // namespace

void* load(std::string_view name, std::string_view purpose) {
  // Never destroyed: a helper thread may still ask while the process exits.
  static auto& mutex = *new std::mutex;
  static auto& loaded = *new std::map<std::string, void*, std::less<>>;  // name -> interface object
  std::lock_guard lock(mutex);
  if (const auto it = loaded.find(name); it != loaded.end()) return it->second;
  const std::string file = std::string(name) + ".so";
  std::string problems;
  for (const std::filesystem::path& dir : searchDirs()) {
    const std::filesystem::path path = dir / file;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    // RTLD_LOCAL: its symbols (and GDAL's or FFmpeg's) stay out of the program's lookups.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      problems += "; " + path.string() + ": " + (why != nullptr ? why : "unknown error");
      continue;
    }
    auto entry = reinterpret_cast<Entry>(dlsym(handle, kEntrySymbol));
    if (entry == nullptr) {
      problems += "; " + path.string() + ": no " + kEntrySymbol;
      continue;  // (left loaded: unloading modules is never worth the risk)
    }
    void* object = entry(&kHost);
    if (object == nullptr) {
      problems += "; " + path.string() + ": built by another build of oceanglobe (this one is " OG_PLUGIN_ABI ")";
      continue;
    }
    loaded.emplace(std::string(name), object);
    return object;
  }
  std::string looked;
  for (const std::filesystem::path& dir : searchDirs()) looked += (looked.empty() ? "" : ", ") + dir.string();
  throw InternalError("cannot load the module " + file + " for " + std::string(purpose) + " (looked in " + looked +
                      problems + "); rebuild or reinstall oceanglobe with its modules beside the executable");
}

}  // namespace og::plugin
