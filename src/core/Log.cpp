#include "core/Log.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace og::log {
namespace {
std::atomic<Level> gLevel{Level::Warn};
std::mutex gMutex;
}  // namespace

void setLevel(Level l) { gLevel = l; }
Level level() { return gLevel; }

void write(Level l, std::string_view message) {
  if (l < gLevel.load()) return;
  static constexpr const char* kTags[] = {"debug", "info", "warning", "error"};
  std::lock_guard lock(gMutex);
  std::fprintf(stderr, "oceanglobe: %s: %.*s\n", kTags[static_cast<int>(l)],
               static_cast<int>(message.size()), message.data());
}

}  // namespace og::log
