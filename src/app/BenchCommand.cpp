// oceanglobe bench: frame times of fixed views at fixed resolutions. Speed is measured here,
// never by timed tests. Output is one line per case (or JSON with --json).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/Commands.hpp"
#include "app/SceneOptions.hpp"
#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::app {
namespace {

struct BenchView {
  const char* name;
  geo::CameraPose pose;
};

std::vector<BenchView> benchViews() {
  auto pose = [](double lat, double lon, double h, double heading, double pitch) {
    geo::CameraPose p;
    p.position = {lat, lon, h};
    p.headingDeg = heading;
    p.pitchDeg = pitch;
    return p;
  };
  return {{"orbit-20000km", pose(10, -30, 2.0e7, 0, -90)},
          {"limb-400km", pose(20, -40, 4.0e5, 90, -15)},
          {"sea-2m-horizon", pose(36, -5.5, 2.0, 270, 2)}};
}

struct BenchOptions {
  std::string gl = "auto";
  int frames = 20;
  std::vector<std::string> sizes{"640x360", "1280x720"};
  bool json = false;
};

bool parseSize(const std::string& s, int& w, int& h) {
  return std::sscanf(s.c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0 && w <= 8192 && h <= 8192;
}

}  // namespace

Run addBenchCommand(CLI::App& parent) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = parent.add_subcommand("bench", "print frame times of fixed views and sizes");
  cmd->add_option("--gl", o->gl, "OpenGL backend: auto, egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  cmd->add_option("--frames", o->frames, "timed frames per case (after 2 warm-up frames)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--size", o->sizes, "image sizes WIDTHxHEIGHT (repeatable)");
  cmd->add_flag("--json", o->json, "print JSON instead of a table");
  return [o]() {
    std::vector<std::pair<int, int>> sizes;
    for (const auto& s : o->sizes) {
      int w = 0, h = 0;
      if (!parseSize(s, w, h)) throw InputError("--size: expected WIDTHxHEIGHT, got '" + s + "'");
      sizes.emplace_back(w, h);
    }
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    auto context = gl::createHeadlessContext(*gl::parseBackend(o->gl));
    const auto& elevation = data::defaultElevation();
    render::GlobeRenderer renderer(elevation);
    render::GlobeRenderer::finish();
    const double startupMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();

    nlohmann::json report;
    report["gl"] = {{"backend", context->info().backend},
                    {"renderer", context->info().renderer},
                    {"version", context->info().version}};
    report["startup_ms"] = startupMs;
    if (!o->json)
      std::printf("oceanglobe bench: %s, %s\nstartup (context + shaders + data): %.1f ms\n"
                  "%-16s %10s %9s %9s %9s\n",
                  context->info().renderer.c_str(), context->info().backend.c_str(), startupMs,
                  "view", "size", "median", "min", "max");
    for (const auto& view : benchViews()) {
      for (const auto& [w, h] : sizes) {
        render::FrameInput f;
        f.camera = view.pose;
        f.width = w;
        f.height = h;
        f.sunDirectionEcef = geo::sunDirectionFromHorizontal(view.pose.position, 20.0, 250.0);
        std::vector<double> ms;
        for (int i = 0; i < o->frames + 2; ++i) {
          const auto s = Clock::now();
          renderer.render(f);
          render::GlobeRenderer::finish();
          if (i >= 2) ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
        }
        std::sort(ms.begin(), ms.end());
        const double median = ms[ms.size() / 2];
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        report["cases"].push_back({{"view", view.name}, {"size", size}, {"median_ms", median},
                                   {"min_ms", ms.front()}, {"max_ms", ms.back()},
                                   {"frames", ms.size()}});
        if (!o->json)
          std::printf("%-16s %10s %7.2fms %7.2fms %7.2fms\n", view.name, size.c_str(), median,
                      ms.front(), ms.back());
      }
    }
    if (o->json) std::printf("%s\n", report.dump(2).c_str());
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
