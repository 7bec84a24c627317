#pragma once
// Progress of long jobs (recording) and a polite stop on Ctrl-C / SIGTERM.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace og {

/// Shows "label  [#####.....]  120/601 frames  4.1 frames/s  ETA 1m57s": redrawn in place on
/// a terminal (at most 10 times a second), as plain lines every `plainIntervalS` seconds
/// otherwise (logs, CI). Writes nothing when disabled.
class Progress {
 public:
  /// `total` >= 0 items; `out` is usually stderr.
  Progress(std::string label, std::int64_t total, bool enabled = true, std::FILE* out = stderr,
           double plainIntervalS = 5.0);
  /// Records that `count` more items are done and redraws when due.
  void advance(std::int64_t count = 1);
  /// Final line (with a newline on a terminal); called by the destructor if not before.
  void finish();
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  [[nodiscard]] double itemsPerSecond() const;
  [[nodiscard]] std::int64_t done() const { return done_; }

  /// "1h02m03s", "4m05s", "7s"; "--" for a negative or non-finite number of seconds.
  static std::string formatDuration(double seconds);

 private:
  void draw(bool final);
  using Clock = std::chrono::steady_clock;
  std::string label_;
  std::int64_t total_ = 0;
  std::int64_t done_ = 0;
  bool enabled_ = true;
  bool tty_ = false;
  bool finished_ = false;
  std::FILE* out_ = nullptr;
  double plainIntervalS_ = 5.0;
  Clock::time_point start_, lastDraw_;
};

/// Installs SIGINT and SIGTERM handlers that only set a flag, so a loop can stop after its
/// current item and close its files properly. A second signal of either kind gets the default
/// action (the process dies at once).
void installStopHandlers();
/// True once SIGINT or SIGTERM arrived after installStopHandlers().
bool stopRequested();
/// The signal that asked to stop (SIGINT, SIGTERM), 0 when none.
int stopSignal();

}  // namespace og
