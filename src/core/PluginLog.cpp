// og::log inside a module (core/Plugin.hpp): its messages go to the program's log, at the
// program's level, through the host the entry point was handed. Linked into modules in place of
// core/Log.cpp.
#include "core/Log.hpp"
#include "core/Plugin.hpp"

#include <atomic>
#include <cstring>

namespace og {
namespace {
std::atomic<const plugin::Host*> gHost{nullptr};
}  // namespace

bool plugin::acceptHost(const Host* host) {
  if (host == nullptr || host->abi == nullptr || std::strcmp(host->abi, OG_PLUGIN_ABI) != 0) return false;
  gHost = host;
  return true;
}

void log::setLevel(Level) {}  // (the program's to set)
log::Level log::level() {
  const plugin::Host* host = gHost.load();
  return host != nullptr ? host->level() : Level::Warn;
}

void log::write(Level level, std::string_view message) {
  if (const plugin::Host* host = gHost.load(); host != nullptr) host->write(level, message);
}

}  // namespace og
