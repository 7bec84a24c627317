#pragma once
// Where start-up time goes: named stages timed on the steady clock, accumulated per name (a
// stage run several times, e.g. one shader program after another, adds up and counts). Always
// on (a mutex and a vector: nanoseconds against the milliseconds timed); `bench --startup`
// prints the table (docs/performance.md, "Start-up").
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace og::core::startup {

using Clock = std::chrono::steady_clock;

struct Stage {
  std::string name;
  double ms = 0.0;       ///< summed duration, ms (stages on other threads overlap the main one)
  double cpuMs = 0.0;    ///< CPU time of the thread that ran it, ms (not the GL driver's threads)
  double firstMs = 0.0;  ///< when it first began, ms after the trace's origin
  int count = 0;         ///< how many times it ran
  bool mainThread = true;  ///< false: it ran on a helper thread, overlapping the others
};

/// The instant the trace's times count from: main()'s entry unless set (setOrigin).
Clock::time_point origin();
/// Sets the origin (main() calls it first thing).
void setOrigin(Clock::time_point t);

/// CPU time of the calling thread so far, ms.
double threadCpuMs();

/// Adds `ms` (and `cpuMs` of the calling thread's CPU time) to stage `name`, begun at `begin`.
void add(const std::string& name, Clock::time_point begin, double ms, double cpuMs = 0.0);

/// The stages in the order they first began.
std::vector<Stage> stages();

/// Forgets every stage (bench, between measured starts).
void clear();

/// Times its own lifetime as stage `name`: `core::startup::Scope s("data: elevation");`.
class Scope {
 public:
  explicit Scope(std::string name) : name_(std::move(name)), begin_(Clock::now()), cpu_(threadCpuMs()) {}
  ~Scope() {
    add(name_, begin_, std::chrono::duration<double, std::milli>(Clock::now() - begin_).count(),
        threadCpuMs() - cpu_);
  }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

 private:
  std::string name_;
  Clock::time_point begin_;
  double cpu_;
};

}  // namespace og::core::startup
