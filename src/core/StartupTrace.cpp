#include "core/StartupTrace.hpp"

#include <time.h>

#include <algorithm>
#include <mutex>
#include <thread>

namespace og::core::startup {
namespace {

struct Trace {
  std::mutex mutex;
  Clock::time_point origin = Clock::now();
  std::thread::id mainThread = std::this_thread::get_id();
  std::vector<Stage> stages;
};

Trace& trace() {
  static Trace t;
  return t;
}

}  // namespace

Clock::time_point origin() {
  Trace& t = trace();
  std::lock_guard lock(t.mutex);
  return t.origin;
}

void setOrigin(Clock::time_point when) {
  Trace& t = trace();
  std::lock_guard lock(t.mutex);
  t.origin = when;
  t.mainThread = std::this_thread::get_id();
}

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

void add(const std::string& name, Clock::time_point begin, double ms, double cpuMs) {
  Trace& t = trace();
  std::lock_guard lock(t.mutex);
  const bool onMain = std::this_thread::get_id() == t.mainThread;
  const double at = std::chrono::duration<double, std::milli>(begin - t.origin).count();
  auto it = std::find_if(t.stages.begin(), t.stages.end(), [&](const Stage& s) { return s.name == name; });
  if (it == t.stages.end()) {
    t.stages.push_back({name, ms, cpuMs, at, 1, onMain});
    return;
  }
  it->ms += ms;
  it->cpuMs += cpuMs;
  it->firstMs = std::min(it->firstMs, at);
  ++it->count;
  it->mainThread = it->mainThread && onMain;
}

std::vector<Stage> stages() {
  Trace& t = trace();
  std::lock_guard lock(t.mutex);
  std::vector<Stage> out = t.stages;
  std::stable_sort(out.begin(), out.end(), [](const Stage& a, const Stage& b) { return a.firstMs < b.firstMs; });
  return out;
}

void clear() {
  Trace& t = trace();
  std::lock_guard lock(t.mutex);
  t.stages.clear();
}

}  // namespace og::core::startup
