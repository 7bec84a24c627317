#include "app/Startup.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/ScratchDirectory.hpp"
#include "core/StartupTrace.hpp"

extern char** environ;

namespace og::app {
namespace {

using Clock = core::startup::Clock;
constexpr const char* kSpawnVar = "OCEANGLOBE_STARTUP_SPAWN_NS";
constexpr const char* kTraceVar = "OCEANGLOBE_STARTUP_TRACE";
constexpr const char* kBeforeMain = "exec + shared libraries (before main)";

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// One child's run: wall time from launch to exit, ms, and the stages it wrote.
struct ChildRun {
  double wallMs = 0.0;
  nlohmann::json trace;
};

ChildRun runChild(const std::vector<std::string>& args, const std::filesystem::path& traceFile) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string v = *e;
    if (v.rfind(kSpawnVar, 0) != 0 && v.rfind(kTraceVar, 0) != 0) env.push_back(v);
  }
  const auto start = Clock::now();
  env.push_back(std::string(kSpawnVar) + "=" +
                std::to_string(std::chrono::duration_cast<std::chrono::nanoseconds>(start.time_since_epoch()).count()));
  env.push_back(std::string(kTraceVar) + "=" + traceFile.string());
  std::vector<char*> argv, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  argv.push_back(nullptr);
  envp.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), envp.data()) != 0)
    throw InternalError("bench --startup: cannot launch " + args[0]);
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InternalError("bench --startup: `oceanglobe render` failed (status " + std::to_string(status) + ")");
  ChildRun run;
  run.wallMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::ifstream in(traceFile);
  run.trace = nlohmann::json::parse(in, nullptr, false);
  if (run.trace.is_discarded() || !run.trace.contains("stages"))
    throw InternalError("bench --startup: " + traceFile.string() + ": no stage trace written");
  return run;
}

/// Median duration, start and count of each stage over the runs, in the order they began.
nlohmann::json medianStages(const std::vector<ChildRun>& runs) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> ms, cpu, start;
  std::map<std::string, int> count;
  std::map<std::string, bool> onMain;
  for (const ChildRun& r : runs)
    for (const auto& s : r.trace["stages"]) {
      const std::string name = s["name"];
      if (!ms.count(name)) order.push_back(name);
      ms[name].push_back(s["ms"]);
      cpu[name].push_back(s["cpu_ms"]);
      start[name].push_back(s["start_ms"]);
      count[name] = s["count"];
      onMain[name] = s["main_thread"];
    }
  std::stable_sort(order.begin(), order.end(),
                   [&](const std::string& a, const std::string& b) { return median(start[a]) < median(start[b]); });
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& n : order)
    out.push_back({{"stage", n}, {"start_ms", median(start[n])}, {"ms", median(ms[n])}, {"cpu_ms", median(cpu[n])},
                   {"count", count[n]}, {"main_thread", onMain[n]}});
  return out;
}

std::string selfExecutable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw InternalError("bench --startup: cannot find the running executable: " + ec.message());
  return self.string();
}

}  // namespace

void noteMainEntry() {
  const auto now = Clock::now();
  const char* spawn = std::getenv(kSpawnVar);
  if (spawn == nullptr || *spawn == '\0') {
    core::startup::setOrigin(now);
    return;
  }
  const Clock::time_point launched{std::chrono::nanoseconds(std::strtoll(spawn, nullptr, 10))};
  if (launched > now || now - launched > std::chrono::minutes(1)) {
    core::startup::setOrigin(now);  // not our parent's clock: ignore it
    return;
  }
  core::startup::setOrigin(launched);
  core::startup::add(kBeforeMain, launched, std::chrono::duration<double, std::milli>(now - launched).count(),
                     core::startup::threadCpuMs());
}

void writeStartupTrace() {
  const char* file = std::getenv(kTraceVar);
  if (file == nullptr || *file == '\0') return;
  try {
    nlohmann::json j;
    j["end_ms"] = std::chrono::duration<double, std::milli>(Clock::now() - core::startup::origin()).count();
    j["stages"] = nlohmann::json::array();
    for (const auto& s : core::startup::stages())
      j["stages"].push_back({{"name", s.name}, {"ms", s.ms}, {"cpu_ms", s.cpuMs}, {"start_ms", s.firstMs},
                             {"count", s.count}, {"main_thread", s.mainThread}});
    writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
      std::ofstream out(tmp);
      out << j.dump() << '\n';
      if (!out) throw InputError(tmp.string() + ": cannot write the start-up trace");
    });
  } catch (const std::exception& e) {
    log::warn(std::string("start-up trace not written: ") + e.what());
  }
}

void benchStartup(const StartupBenchOptions& o, nlohmann::json& report, bool json) {
  const core::ScratchDirectory scratch("oceanglobe-bench-startup-", std::to_string(::getpid()));
  const std::filesystem::path& dir = scratch.path();
  // The sea-4m view of `bench` (docs/performance.md).
  const std::vector<std::string> args = {
      selfExecutable(), "-q", "render", "--lat", "20", "--lon", "-40", "--alt", "4", "--heading", "270",
      "--pitch", "-10", "--width", std::to_string(o.width), "--height", std::to_string(o.height),
      "--gl", o.gl, "--output", (dir / "first-frame.png").string()};
  const ChildRun first = runChild(args, dir / "trace-first.json");
  std::vector<ChildRun> runs;
  for (int i = 0; i < o.runs; ++i) runs.push_back(runChild(args, dir / ("trace-" + std::to_string(i) + ".json")));
  std::vector<double> wall, firstFrame;
  for (const ChildRun& r : runs) {
    wall.push_back(r.wallMs);
    firstFrame.push_back(r.trace["end_ms"]);
  }
  const nlohmann::json stages = medianStages(runs);
  report["startup"] = {{"view", "sea-4m"}, {"size", std::to_string(o.width) + "x" + std::to_string(o.height)},
                       {"runs", o.runs}, {"first_run_ms", first.wallMs},
                       {"first_frame_written_ms", median(firstFrame)}, {"exit_ms", median(wall)},
                       {"stages", stages}};
  if (json) return;
  std::printf("start-up, `render` sea-4m %dx%d, cached second start, median of %d runs (first run %.0f ms):\n"
              "  %.1f ms to the first frame written, %.1f ms to the process's exit\n"
              "  %-52s %9s %9s %9s %6s\n",
              o.width, o.height, o.runs, first.wallMs, median(firstFrame), median(wall), "stage (stages nest; * = on a helper thread)",
              "start ms", "ms", "CPU ms", "count");
  std::string programs;
  for (const auto& s : stages) {
    const std::string name = s["stage"];
    if (name.rfind("program: ", 0) == 0) {
      char line[300];
      std::snprintf(line, sizeof line, "    %7.1f ms  %s\n", s["ms"].get<double>(), name.substr(9).c_str());
      programs += line;
      continue;
    }
    std::printf("  %-52s %9.1f %9.1f %9.1f %6d\n",
                (std::string(s["main_thread"] ? "" : "* ") + s["stage"].get<std::string>()).c_str(),
                s["start_ms"].get<double>(), s["ms"].get<double>(), s["cpu_ms"].get<double>(),
                s["count"].get<int>());
  }
  std::printf("  programs compiled and linked, in order:\n%s", programs.c_str());
}

}  // namespace og::app
