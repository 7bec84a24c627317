#pragma once
// The start-up report (`bench --startup`): the time from launching `oceanglobe render` to its
// first frame written, measured on fresh processes, with the stages of core/StartupTrace.hpp.
#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace og::app {

/// main() calls it first: the trace's origin becomes the launch time the parent passed in
/// $OCEANGLOBE_STARTUP_SPAWN_NS (steady clock, ns), with the loader's share (exec, shared
/// libraries, static initialisers) as the stage before main; else main()'s entry.
void noteMainEntry();

/// Writes the stages as JSON to $OCEANGLOBE_STARTUP_TRACE when it is set (bench --startup's
/// child processes); nothing otherwise. Never throws: a failure is logged.
void writeStartupTrace();

struct StartupBenchOptions {
  std::string gl = "auto";
  int width = 64, height = 36;  ///< the first frame's size, px
  int runs = 5;                 ///< timed (second and later) starts; the median is reported
};

/// Launches `oceanglobe render` (the sea-4m view) runs + 1 times, the first to fill the caches
/// (atmosphere, Mesa's shader cache), and reports the median wall time to the first frame
/// written and the median of every stage. Adds "startup" to `report`; prints a table unless
/// `json`. Throws og::InternalError when a child fails.
void benchStartup(const StartupBenchOptions& options, nlohmann::json& report, bool json);

}  // namespace og::app
