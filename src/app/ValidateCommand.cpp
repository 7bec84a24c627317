// oceanglobe validate: the filtered ocean and a constant-BRDF ocean against a brute-force
// reference, row by row (Bruneton et al. 2010 §7.2; method and numbers in docs/validation.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/Commands.hpp"
#include "core/Error.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/OceanValidation.hpp"

namespace og::app {
namespace {
struct ValidateOptions {
  render::ValidationSettings settings;
  std::string only;  // one view by name (empty: all)
  std::string out;
  bool json = false;
  bool rows = false;
};

nlohmann::json bandJson(const render::BandError& b) {
  return {{"rows", b.rows},           {"near_m", b.nearM},
          {"far_m", b.farM},          {"filtered_mean", b.meanFiltered},
          {"filtered_max", b.maxFiltered}, {"constant_mean", b.meanConstant},
          {"constant_max", b.maxConstant}};
}

void printText(const render::ValidationResult& r, bool rows) {
  std::printf("view %s: height %.0f m, heading %.0f, pitch %.0f, Sun %.0f deg high at %.0f\n",
              r.view.name.c_str(), r.view.heightM, r.view.headingDeg, r.view.pitchDeg,
              r.view.sunElevationDeg, r.view.sunAzimuthDeg);
  if (rows) {
    std::printf("  %4s %10s %11s %11s %11s %9s %9s\n", "row", "dist_m", "reference", "filtered",
                "constant", "err_filt", "err_const");
    for (const auto& e : r.rows)
      std::printf("  %4d %10.1f %11.5f %11.5f %11.5f %+8.1f%% %+8.1f%%\n", e.row, e.distanceM,
                  e.reference, e.filtered, e.constant, 100 * e.errorFiltered, 100 * e.errorConstant);
  }
  std::printf("  %-5s %5s %19s %17s %17s\n", "band", "rows", "distance_m", "filtered mean/max",
              "constant mean/max");
  auto line = [](const render::BandError& b) {
    std::printf("  %-5s %5d %9.1f-%-9.1f %7.1f%% %7.1f%% %7.1f%% %7.1f%%\n", b.name.c_str(), b.rows,
                b.nearM, b.farM, 100 * b.meanFiltered, 100 * b.maxFiltered, 100 * b.meanConstant,
                100 * b.maxConstant);
  };
  for (const auto& b : r.bands) line(b);
  line(r.all);
}
}  // namespace

Run addValidateCommand(CLI::App& parent) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "validate", "compare the filtered ocean and a constant-BRDF ocean with a supersampled reference");
  cmd->add_option("--width", o->settings.width, "image width")->check(CLI::Range(16, 1024));
  cmd->add_option("--height", o->settings.height, "image height")->check(CLI::Range(16, 1024));
  cmd->add_option("--supersample", o->settings.supersample, "reference samples per pixel along x and y")
      ->check(CLI::Range(1, 16));
  cmd->add_option("--cell", o->settings.cellPixels, "the models' grid cell in pixels")->check(CLI::Range(1, 64));
  cmd->add_option("--view", o->only, "run one view only (2m_sun, 2m_away, 20m_sun, ...)");
  cmd->add_option("--out", o->out, "write reference/filtered/constant PNGs per view into DIR");
  cmd->add_flag("--rows", o->rows, "print every row, not only the bands");
  cmd->add_flag("--json", o->json, "print JSON (rows included)");
  return [o]() {
    std::vector<render::ValidationView> views;
    for (const auto& v : render::defaultValidationViews())
      if (o->only.empty() || v.name == o->only) views.push_back(v);
    if (views.empty()) throw InputError("--view: no view named '" + o->only + "'");
    if (!o->out.empty()) std::filesystem::create_directories(o->out);
    const auto ctx = gl::createHeadlessContext();
    render::OceanValidator validator(o->settings);
    nlohmann::json j;
    const auto& s = validator.settings();
    j["settings"] = {{"width", s.width},           {"height", s.height},
                     {"supersample", s.supersample}, {"reference_cell_px", s.referenceCellPixels},
                     {"cell_px", s.cellPixels},     {"time_s", s.timeS},
                     {"wind_ms", s.windSpeedMs},    {"wind_towards_deg", s.windDirectionDeg},
                     {"seed", s.seed}};
    for (const auto& v : views) {
      const render::ValidationResult r = validator.run(v);
      if (!o->out.empty()) {
        const std::filesystem::path dir(o->out);
        const double exposure = render::validationExposure(r);
        io::writePng(dir / (v.name + "_reference.png"), render::validationPreview(r.reference, exposure));
        io::writePng(dir / (v.name + "_filtered.png"), render::validationPreview(r.filtered, exposure));
        io::writePng(dir / (v.name + "_constant.png"), render::validationPreview(r.constant, exposure));
        io::writePng(dir / (v.name + "_strip.png"), render::validationStrip(r, exposure));
      }
      if (o->json) {
        nlohmann::json jv = {{"name", v.name},          {"height_m", v.heightM},
                             {"heading_deg", v.headingDeg}, {"pitch_deg", v.pitchDeg},
                             {"sun_elevation_deg", v.sunElevationDeg},
                             {"sun_azimuth_deg", v.sunAzimuthDeg}};
        for (const auto& b : r.bands) jv["bands"][b.name] = bandJson(b);
        jv["bands"]["all"] = bandJson(r.all);
        for (const auto& e : r.rows)
          jv["rows"].push_back({{"row", e.row}, {"distance_m", e.distanceM}, {"reference", e.reference},
                                {"filtered", e.filtered}, {"constant", e.constant},
                                {"error_filtered", e.errorFiltered}, {"error_constant", e.errorConstant}});
        j["views"].push_back(jv);
      } else {
        printText(r, o->rows);
      }
      std::fflush(stdout);
    }
    if (o->json) std::printf("%s\n", j.dump(2).c_str());
    return 0;
  };
}

}  // namespace og::app
