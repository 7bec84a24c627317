// oceanglobe bench: frame times of fixed views at fixed resolutions. Speed is measured here,
// never by timed tests. Output is one line per case (or JSON with --json).
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numeric>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/BenchLines.hpp"
#include "app/Commands.hpp"
#include "app/Recording.hpp"
#include "app/SceneOptions.hpp"
#include "app/Startup.hpp"
#include "core/Allocator.hpp"
#include "core/Error.hpp"
#include "core/ScratchDirectory.hpp"
#include "data/Elevation.hpp"
#include "data/SyntheticWind.hpp"
#include "data/WindLayers.hpp"
#include "geo/Sun.hpp"
#include "gl/Context.hpp"
#include "gl/PassTimer.hpp"
#include "render/Atmosphere.hpp"
#include "render/GlobeRenderer.hpp"
#include "terrain/Selection.hpp"
#include "terrain/TileCache.hpp"

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
          {"sea-2m-horizon", pose(36, -5.5, 2.0, 270, 2)},
          // The paper's altitude series (4 m, 1 km, 8 km): the grid's cost must fall as the
          // camera rises and fewer waves are resolved.
          {"sea-4m", pose(20, -40, 4.0, 270, -10)},
          {"sea-1km", pose(20, -40, 1000.0, 270, -20)},
          {"sea-8km", pose(20, -40, 8000.0, 270, -30)},
          // Coastal water (issue 15): 2 m over the Great Bahama Bank with the floor in view,
          // and the same view over deep water; their ratio is the water volume's cost.
          {"coast-2m-bank", pose(24.2, -78.2, 2.0, 270, -10)},
          {"coast-2m-deep", pose(20, -40, 2.0, 270, -10)},
          // Terrain: the Himalaya towards the horizon, and the Strait of Gibraltar's coasts.
          {"mountain-15km", pose(27.3, 86.9, 15000.0, 10, -2)},
          {"coast-30km", pose(35.6, -5.6, 30000.0, 0, -30)},
          // The demo flight's descent above the grid's ceiling (config/flythrough.toml): the
          // globe's deep sea off Portugal, within a degree of its shelf and seamounts.
          {"offshore-40km", pose(38.0, -12.0, 40000.0, 74, -30)}};
}

struct BenchOptions {
  std::string gl = "auto";
  int frames = 20;
  std::vector<std::string> sizes{"640x360", "1280x720"};
  bool json = false;
  std::string record;  // camera path for the record case (render + H.264 encode)
  std::vector<std::string> samples{"auto"};
  bool breakdown = false;
  std::string timer = "auto";  // how passes are timed: auto, queries, finish
  std::vector<std::string> views;  // only these views (all when empty)
  io::SceneSettings imagery;  // --imagery-layer and its cache budgets
  bool startup = false;  // --startup: time cached starts of `render` instead
  int startupRuns = 5;
};

/// The imagery tile caches' use (render::ImageryTileStats) for --json.
nlohmann::json imageryTilesJson(const render::ImageryTileStats& s) {
  return {{"cpu_tiles", s.cpuTiles}, {"cpu_bytes", s.cpuBytes}, {"gpu_tiles", s.gpuTiles},
          {"gpu_bytes", s.gpuBytes}, {"reads", s.reads}, {"finest_level", s.finestLevel}};
}

/// The same for the table: ", imagery N tiles, C MiB CPU + G MiB GPU", empty without tiles.
std::string imageryTilesLine(const render::ImageryTileStats& s) {
  if (s.reads == 0) return {};
  char line[120];
  std::snprintf(line, sizeof line, "; imagery %zu tiles, %.1f MiB CPU + %.1f MiB GPU", s.gpuTiles,
                static_cast<double>(s.cpuBytes) / 1048576.0, static_cast<double>(s.gpuBytes) / 1048576.0);
  return line;
}

/// `--breakdown`: the share of the frame's pixels each named part shaded in the frame that
/// counted them (`frameSamples` = pixels x samples per pixel), as "    TITLE (% of pixels):
/// NAME 12.3 ..." and into `breakdown` under `key`; empty where nothing was counted.
std::string pixelSharesLine(const char* title, const char* key,
                            const std::vector<std::pair<std::string, std::uint64_t>>& samples, int frameSamples,
                            nlohmann::json& breakdown) {
  if (samples.empty()) return {};
  std::vector<std::pair<std::string, double>> percents;
  for (const auto& [name, count] : samples) percents.emplace_back(name, 100.0 * static_cast<double>(count) / frameSamples);
  nlohmann::json shares = nlohmann::json::object();
  const std::string line = std::string("    ") + title + " (% of pixels):" + namedValuesLine(percents, shares);
  breakdown[key] = shares;
  return line;
}

/// `--breakdown`: the globe's blocks of pixels (render/GlobeBlocks) by the class the CPU gave
/// them above the grid's ceiling, as "    globe blocks: per-pixel N ..." and into `breakdown`
/// ("globe_blocks"); empty where none were classed (below 20 km, or on a GPU).
std::string globeBlocksLine(const std::array<int, render::kGlobeBlockClasses>& counts, nlohmann::json& breakdown) {
  static constexpr std::array<const char*, render::kGlobeBlockClasses> kNames{"per-pixel", "land", "sea",
                                                                               "open sea",  "miss", "space"};
  if (std::all_of(counts.begin(), counts.end(), [](int n) { return n == 0; })) return {};
  std::string line = "    globe blocks:";
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    values[kNames.at(k)] = counts.at(k);
    line += std::string(" ") + kNames.at(k) + " " + std::to_string(counts.at(k));
  }
  breakdown["globe_blocks"] = values;
  return line;
}

/// The sea's classes (OceanRenderer::classSamples) named; none where the sea was not classified.
std::vector<std::pair<std::string, std::uint64_t>> seaClassSamples(const render::OceanRenderer& ocean) {
  if (ocean.classesDrawn() == 0) return {};
  static constexpr std::array<const char*, render::OceanRenderer::kSeaClasses> kNames{
      "open sea", "shadows", "floor", "floor shadows", "coast"};
  std::vector<std::pair<std::string, std::uint64_t>> named;
  for (std::size_t k = 0; k < kNames.size(); ++k) named.emplace_back(kNames.at(k), ocean.classSamples().at(k));
  return named;
}

bool wanted(const BenchOptions& o, const char* view) {
  return o.views.empty() || std::find(o.views.begin(), o.views.end(), view) != o.views.end();
}

/// How --breakdown times the passes: GL timestamp queries on a GPU; on a software renderer
/// (llvmpipe), whose queries mark when commands are queued rather than run, a glFinish and the
/// CPU clock at every pass boundary (gl/PassTimer.hpp).
gl::PassTimer::Mode timerMode(const std::string& choice) {
  if (choice == "queries") return gl::PassTimer::Mode::Queries;
  if (choice == "finish") return gl::PassTimer::Mode::Finish;
  if (choice == "cpu") return gl::PassTimer::Mode::ProcessCpu;
  return gl::driverProfile().timestampsTimeWork ? gl::PassTimer::Mode::Queries : gl::PassTimer::Mode::Finish;
}

/// Median of each pass over the frames, in the order the passes ran.
std::vector<std::pair<std::string, double>> medianPasses(
    const std::vector<std::vector<std::pair<std::string, double>>>& frames) {
  std::vector<std::pair<std::string, double>> out;
  if (frames.empty()) return out;
  for (const auto& [name, ignored] : frames.front()) {
    std::vector<double> v;
    for (const auto& frame : frames)
      for (const auto& [n, ms] : frame)
        if (n == name) v.push_back(ms);
    std::sort(v.begin(), v.end());
    out.emplace_back(name, v[v.size() / 2]);
  }
  return out;
}

bool parseSize(const std::string& s, int& w, int& h) {
  return std::sscanf(s.c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0 && w <= 8192 && h <= 8192;
}

/// Load time of a global 0.25° two-variable wind field (1440 x 721, ERA5's layout) in two
/// containers, written once to a temporary directory: WindLayers::load (open, validate, unpack,
/// blend weights) and the rasterisation to the renderer's 720 x 360 wind texture (CPU part of
/// WindTextures::setLayers). Median of 3 runs each.
void benchWindData(nlohmann::json& report, bool json) {
  using Clock = std::chrono::steady_clock;
  auto msSince = [](Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  };
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const core::ScratchDirectory scratch("oceanglobe-bench-data-",
                                      std::to_string(Clock::now().time_since_epoch().count()));
  const std::filesystem::path& dir = scratch.path();
  constexpr int kColumns = 1440, kRows = 721, kTextureW = 720, kTextureH = 360;
  const std::pair<data::SyntheticFormat, const char*> formats[] = {
      {data::SyntheticFormat::kClassic64, "netcdf3-64bit"},
      {data::SyntheticFormat::kNetcdf4Deflate, "netcdf4-zlib"}};
  for (const auto& [format, name] : formats) {
    const std::filesystem::path file = dir / (std::string("era5_025_") + name + ".nc");
    const auto w0 = Clock::now();
    data::writeSyntheticEra5Wind(file, format, kColumns, kRows);
    const double writeMs = msSince(w0);
    std::vector<double> loadMs, rasterMs;
    for (int i = 0; i < 3; ++i) {
      const auto l0 = Clock::now();
      const data::WindLayers layers = data::WindLayers::load({file.string()}, {}, std::nullopt);
      loadMs.push_back(msSince(l0));
      const auto r0 = Clock::now();
      const data::WindRaster raster = layers.rasterize(kTextureW, kTextureH);
      rasterMs.push_back(msSince(r0));
      if (raster.uv.empty()) throw InternalError("bench: empty wind raster");
    }
    const auto bytes = std::filesystem::file_size(file);
    report["wind_data"].push_back(
        {{"format", name}, {"grid", std::to_string(kColumns) + "x" + std::to_string(kRows)},
         {"variables", "u10,v10"}, {"file_bytes", bytes}, {"write_ms", writeMs},
         {"load_ms", median(loadMs)}, {"load_min_ms", *std::min_element(loadMs.begin(), loadMs.end())},
         {"rasterize_ms", median(rasterMs)},
         {"texture", std::to_string(kTextureW) + "x" + std::to_string(kTextureH)}});
    if (!json)
      std::printf("wind layer 0.25° %dx%d u10/v10 %-14s %5.1f MiB: load %.1f ms (min %.1f), "
                  "rasterize to %dx%d %.1f ms\n",
                  kColumns, kRows, name, static_cast<double>(bytes) / 1048576.0, median(loadMs),
                  *std::min_element(loadMs.begin(), loadMs.end()), kTextureW, kTextureH,
                  median(rasterMs));
  }
}

/// CPU time of the terrain selection of a view's first frame with an empty tile cache (every
/// tile it visits is built), with one build thread and with the default pool.
void benchTerrainFirstFrame(const std::shared_ptr<const data::LatLonGrid>& elevation, const BenchView& view,
                            int w, int h, nlohmann::json& report, bool json) {
  using Clock = std::chrono::steady_clock;
  const auto heights = std::make_shared<const terrain::Heightfield>(elevation);
  const geo::CameraView camera = geo::makeCameraView(view.pose, w, h);
  terrain::SelectionParams params;
  params.widthPx = w;
  params.heightPx = h;
  for (const int workers : {1, 0}) {
    terrain::TileCache cache(heights, std::size_t{96} << 20, workers);
    terrain::SelectionStats stats;
    const auto t0 = Clock::now();
    const auto tiles = terrain::selectTiles(cache, camera, params, &stats);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    report["terrain_first_frame"].push_back(
        {{"view", view.name}, {"size", std::to_string(w) + "x" + std::to_string(h)},
         {"workers", cache.workerCount()}, {"tiles_built", cache.builtCount()},
         {"tiles_drawn", tiles.size()}, {"ms", ms}});
    if (!json)
      std::printf("terrain first frame %s %dx%d, cold cache: %llu tiles built, %zu drawn, "
                  "%.1f ms with %d build thread(s)\n",
                  view.name, w, h, static_cast<unsigned long long>(cache.builtCount()),
                  tiles.size(), ms, cache.workerCount());
  }
}

}  // namespace

Run addBenchCommand(CLI::App& parent) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = parent.add_subcommand("bench", "print frame times of fixed views and sizes");
  cmd->add_option("--gl", o->gl, "OpenGL backend: auto, egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  cmd->add_option("--frames", o->frames,
                  "timed frames per case (after 2 warm-up frames; default 20); with --record, frames "
                  "sampled evenly along the path (default: every frame, as `record` renders it)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--size", o->sizes, "image sizes WIDTHxHEIGHT (repeatable)");
  cmd->add_option("--view", o->views, "only these views (repeatable; default: all)")
      ->check(CLI::IsMember({"orbit-20000km", "limb-400km", "sea-2m-horizon", "sea-4m", "sea-1km",
                             "sea-8km", "coast-2m-bank", "coast-2m-deep", "mountain-15km",
                             "coast-30km", "offshore-40km"}));
  cmd->add_option("--samples", o->samples,
                  "samples per pixel: auto (default), 1, 2, 4 or 8; several (--samples 1 4) time each "
                  "case at each count, frames interleaved so that machine load hits all alike");
  cmd->add_option("--imagery-layer", o->imagery.imageryLayers, "imagery FILE over the land (repeatable)");
  cmd->add_option("--imagery-cache-cpu-mib", o->imagery.imageryCacheCpuMib, "imagery tile cache, MiB")->check(CLI::Range(1, 65536));
  cmd->add_option("--imagery-cache-gpu-mib", o->imagery.imageryCacheGpuMib, "imagery tile slots, MiB")->check(CLI::Range(1, 65536));
  cmd->add_flag("--json", o->json, "print JSON instead of a table");
  cmd->add_flag("--breakdown", o->breakdown,
                "also time every pass (globe, terrain shadows, terrain, ocean waves, ocean, tone "
                "mapping) and the read-back, per view; with --record, per band of camera height (its "
                "render-only run is then timed pass by pass, which slows it)");
  cmd->add_option("--timer", o->timer,
                  "how --breakdown times passes: auto (queries on a GPU, finish on llvmpipe and with --record), "
                  "queries (GL timestamps), finish (glFinish + wall clock) or cpu (glFinish + the "
                  "process's CPU time: llvmpipe's work whatever the machine's load)")
      ->check(CLI::IsMember({"auto", "queries", "finish", "cpu"}));
  cmd->add_flag("--startup", o->startup,
                "instead: time cached starts of `render` (sea-4m at the first --size, else 64x36) to "
                "the first frame written, stage by stage (median; one start first to fill the caches)");
  cmd->add_option("--startup-runs", o->startupRuns, "timed starts for --startup (default 5)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--record", o->record,
                  "instead: frames/s recording this camera path (e.g. config/flythrough.toml) to "
                  "MP4 at each --size, encoding included");
  return [o, cmd]() {
    std::vector<int> samples;
    for (const std::string& n : o->samples) samples.push_back(parseSampleCount(n));
    std::vector<std::pair<int, int>> sizes;
    for (const auto& s : o->sizes) {
      int w = 0, h = 0;
      if (!parseSize(s, w, h)) throw InputError("--size: expected WIDTHxHEIGHT, got '" + s + "'");
      sizes.emplace_back(w, h);
    }
    if (!o->record.empty()) {
      // `auto` times by glFinish and the clock here: the recording makes its context later, and
      // that is right on any driver.
      const gl::PassTimer::Mode mode = o->timer == "auto" ? gl::PassTimer::Mode::Finish : timerMode(o->timer);
      return benchRecord(o->record, sizes, cmd->count("--frames") > 0 ? o->frames : 0, o->gl, samples, o->json,
                         o->breakdown ? std::optional(mode) : std::nullopt);
    }
    if (o->startup) {
      StartupBenchOptions s{.gl = o->gl, .runs = o->startupRuns};
      if (cmd->count("--size") > 0) std::tie(s.width, s.height) = sizes.front();
      nlohmann::json report;
      benchStartup(s, report, o->json);
      if (o->json) std::printf("%s\n", report.dump(2).c_str());
      return static_cast<int>(kExitOk);
    }
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const std::vector<data::GeoImage> imagery = loadImageryLayers(o->imagery);
    auto context = gl::createHeadlessContext(*gl::parseBackend(o->gl));
    const std::shared_ptr<const data::LatLonGrid> elevation = data::loadSharedElevationLayer("");
    // Atmosphere start-up: cold (empty cache directory: precomputation on this GL device),
    // then a second, cached start (tables loaded from the file). Both include the sky maps.
    const std::filesystem::path atmoCache =
        std::filesystem::temp_directory_path() /
        ("oceanglobe-bench-cache-" + std::to_string(Clock::now().time_since_epoch().count()));
    render::AtmosphereOptions atmoOptions;
    atmoOptions.cacheDirectory = atmoCache;
    auto msSince = [](Clock::time_point t) {
      return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    };
    const auto a0 = Clock::now();
    auto cold = std::make_shared<const render::Atmosphere>(atmosphere::earth(), atmoOptions);
    const double atmoColdMs = msSince(a0);
    const auto a1 = Clock::now();
    auto cached = std::make_shared<const render::Atmosphere>(atmosphere::earth(), atmoOptions);
    const double atmoCachedMs = msSince(a1);
    std::error_code ignored;
    std::filesystem::remove_all(atmoCache, ignored);
    cold.reset();
    // One renderer per sample count: switching one renderer's count would rebuild its targets.
    std::vector<std::unique_ptr<render::GlobeRenderer>> renderers;
    renderers.push_back(std::make_unique<render::GlobeRenderer>(elevation, cached));
    render::GlobeRenderer::finish();
    const double startupMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    while (renderers.size() < samples.size())
      renderers.push_back(std::make_unique<render::GlobeRenderer>(elevation, cached));

    nlohmann::json report;
    report["gl"] = {{"backend", context->info().backend},
                    {"renderer", context->info().renderer},
                    {"version", context->info().version}};
    const std::string allocator = core::allocatorSummary();
    report["allocator"] = allocator;
    report["startup_ms"] = startupMs;
    report["atmosphere"] = {{"cold_ms", atmoColdMs},
                            {"cached_ms", atmoCachedMs},
                            {"cached_hit", cached->timing().fromCache},
                            {"sky_maps_ms", cached->timing().skyMapsMs}};
    if (!o->json)
      std::printf("oceanglobe bench: %s, %s, %s\nstartup (context + shaders + data): %.1f ms\n"
                  "atmosphere precompute: cold %.1f ms, cached second run %.1f ms%s "
                  "(sky maps %.1f ms of it)\n"
                  "%-16s %10s %7s %9s %9s %9s\n",
                  context->info().renderer.c_str(), context->info().backend.c_str(),
                  allocator.c_str(), startupMs,
                  atmoColdMs, atmoCachedMs, cached->timing().fromCache ? "" : " (cache MISSED)",
                  cached->timing().skyMapsMs, "view", "size", "samples", "median", "min", "max");
    for (auto& r : renderers) setImageryLayers(r->imagery(), o->imagery, imagery);
    std::vector<gl::PassTimer> timers;
    for (std::size_t k = 0; k < renderers.size(); ++k) timers.emplace_back(timerMode(o->timer));
    for (std::size_t k = 0; k < renderers.size(); ++k) renderers[k]->setPassTimer(o->breakdown ? &timers[k] : nullptr);
    for (const auto& view : benchViews()) {
      if (!wanted(*o, view.name)) continue;
      for (const auto& [w, h] : sizes) {
        render::FrameInput f = frameInputOf(io::SceneSettings{});  // the default scene's settings
        f.camera = view.pose;
        f.width = w;
        f.height = h;
        f.sunDirectionEcef = geo::sunDirectionFromHorizontal(view.pose.position, 20.0, 250.0);
        f.displayOnly = true;  // (as `record` to MP4 or PNG renders)
        std::vector<std::vector<double>> ms(renderers.size());
        std::vector<std::vector<std::vector<std::pair<std::string, double>>>> passes(renderers.size());
        for (int i = 0; i < o->frames + 2; ++i)
          for (std::size_t k = 0; k < renderers.size(); ++k) {
            f.samples = samples[k];
            f.simulationTimeS = i / 30.0;  // the waves move as in a 30 fps recording
            // The classes' and parts' shares in the second warm-up frame only: their queries
            // wait for the GPU, which the timed frames must not.
            renderers[k]->ocean().setCountClassSamples(o->breakdown && i == 1);
            renderers[k]->setCountPartSamples(o->breakdown && i == 1);
            const auto s = Clock::now();
            renderers[k]->render(f);
            render::GlobeRenderer::finish();
            if (i < 2) continue;
            ms[k].push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
            if (!o->breakdown) continue;
            auto frame = timers[k].results();
            const auto r0 = Clock::now();
            const io::ImageRgba8 shown = renderers[k]->display();
            frame.emplace_back("read-back", std::chrono::duration<double, std::milli>(Clock::now() - r0).count());
            if (shown.pixels.empty()) throw InternalError("bench: empty read-back");
            passes[k].push_back(std::move(frame));
          }
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        for (std::size_t k = 0; k < renderers.size(); ++k) {
          std::vector<double>& t = ms[k];
          std::sort(t.begin(), t.end());
          const double median = t[t.size() / 2];
          const render::TerrainStats& ts = renderers[k]->terrain().stats();
          report["cases"].push_back({{"view", view.name}, {"size", size},
                                     {"samples", renderers[k]->samples()}, {"median_ms", median},
                                     {"min_ms", t.front()}, {"max_ms", t.back()},
                                     {"frames", t.size()}, {"terrain_tiles", ts.tiles},
                                     {"terrain_coarse_tiles", ts.coarseTiles},
                                     {"shadow_tile_draws", ts.shadowTileDraws},
                                     {"shadow_coarse_tile_draws", ts.shadowCoarseTileDraws},
                                     {"terrain_cpu_bytes", ts.cpuBytes},
                                     {"terrain_gpu_bytes", ts.gpuBytes},
                                     {"imagery_gpu_bytes", renderers[k]->imagery().gpuBytes() +
                                                               renderers[k]->landMask().gpuBytes()},
                                     {"imagery_tiles", imageryTilesJson(renderers[k]->imagery().tileStats())}});
          // The shadow maps' tile draws, and those from the coarser mesh (TerrainRenderer::shadowStride).
          const std::string shadows = ts.shadowTileDraws == 0 ? std::string()
                                                              : ", shadows " + std::to_string(ts.shadowTileDraws) + " casters (" +
                                                                    std::to_string(ts.shadowCoarseTileDraws) + " coarse)";
          if (!o->json)
            std::printf("%-16s %10s %7d %7.2fms %7.2fms %7.2fms  terrain %d tiles (%d coarse), %.1f MiB CPU + %.1f MiB GPU%s%s\n",
                        view.name, size.c_str(), renderers[k]->samples(), median, t.front(),
                        t.back(), ts.tiles, ts.coarseTiles, static_cast<double>(ts.cpuBytes) / 1048576.0,
                        static_cast<double>(ts.gpuBytes) / 1048576.0, shadows.c_str(),
                        imageryTilesLine(renderers[k]->imagery().tileStats()).c_str());
          if (!o->breakdown) continue;
          nlohmann::json breakdown = nlohmann::json::object();
          const gl::PassTimer::Mode mode = timers[k].mode();
          std::string line = std::string("    passes (") +
                             (mode == gl::PassTimer::Mode::Queries ? "queries" : mode == gl::PassTimer::Mode::Finish ? "finish" : "process CPU") + "):" +
                             namedValuesLine(medianPasses(passes[k]), breakdown);
          report["cases"].back()["passes_ms"] = breakdown;
          if (!o->json) std::printf("%s ms\n", line.c_str());
          const int pixelSamples = w * h * renderers[k]->samples();
          for (const std::string& shares :
               {pixelSharesLine("sea classes", "sea_class_pixels_percent", seaClassSamples(renderers[k]->ocean()),
                                pixelSamples, report["cases"].back()),
                pixelSharesLine("globe parts", "globe_part_pixels_percent", renderers[k]->partSamples(), pixelSamples,
                                report["cases"].back())})
            if (!o->json && !shares.empty()) std::printf("%s\n", shares.c_str());
          const std::string blocks = globeBlocksLine(renderers[k]->globeBlockCounts(), report["cases"].back());
          if (!o->json && !blocks.empty()) std::printf("%s\n", blocks.c_str());
        }
      }
    }
    for (const auto& view : benchViews())
      if (std::string(view.name) == "mountain-15km" && wanted(*o, view.name) && !sizes.empty())
        benchTerrainFirstFrame(elevation, view, sizes.front().first, sizes.front().second, report,
                               o->json);
    if (o->views.empty()) benchWindData(report, o->json);
    if (o->json) std::printf("%s\n", report.dump(2).c_str());
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
