#pragma once
// Per-pass GPU times of a frame (`oceanglobe bench --breakdown`): the frame is cut at marks
// into named passes, and each pass's time measured either with GL timestamp queries (the GPU's
// own clock; nothing waits until the results are read) or, where the driver's queries do not
// reflect when work runs, by finishing the GL work at each mark and reading the CPU's clock.
//
// Mesa's llvmpipe bins a pass's draws and rasterises them only at the next flush, so its
// timestamps mark when commands are queued, not when pixels are shaded: `finish` mode is what
// measures it (docs/performance.md compares the two).
#include <string>
#include <utility>
#include <vector>

#include "gl/Objects.hpp"

namespace og::gl {

class PassTimer {
 public:
  /// Queries: GL timestamps. Finish: glFinish and the wall clock at each mark. ProcessCpu:
  /// glFinish and the process's CPU time at each mark (all its threads, so on a CPU renderer the
  /// work done whatever else the machine runs; wall time on an idle machine is about this over
  /// the number of cores).
  enum class Mode { Queries, Finish, ProcessCpu };

  explicit PassTimer(Mode mode) : mode_(mode) {}

  /// Starts a frame; the work from here to the first mark() belongs to no pass.
  void beginFrame();
  /// Ends the current pass (if any) and starts `pass` (a string literal or long-lived name).
  void mark(const char* pass);
  /// Ends the current pass.
  void endFrame();

  /// Milliseconds per pass of the last frame, in order (passes marked twice are summed). Waits
  /// for the GPU in Queries mode.
  [[nodiscard]] std::vector<std::pair<std::string, double>> results();

  [[nodiscard]] Mode mode() const { return mode_; }

 private:
  void stamp();

  Mode mode_;
  std::vector<const char*> names_;   // pass started at stamp i (nullptr: none)
  std::vector<Query> queries_;       // Queries mode: timestamps
  std::vector<double> cpuMs_;        // Finish mode: CPU clock at each stamp
  std::size_t used_ = 0;
};

}  // namespace og::gl
