// oceanglobe validate: the filtered ocean, the paper's constant-BRDF ocean and a flat BRDF-only
// sea against a brute-force reference, row by row and per lighting term (Bruneton et al. 2010
// §7.2; method and numbers in docs/validation.md).
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

// One band: per model "<model>_mean" / "<model>_max" of the total, and the same per lighting
// term under "sun", "sky", "refracted".
nlohmann::json bandJson(const render::BandError& b) {
  auto models = [&](std::size_t t) {
    nlohmann::json j;
    for (std::size_t m = 0; m < render::kValidationModels; ++m) {
      j[std::string(render::kValidationModelNames[m]) + "_mean"] = b.mean[t][m];
      j[std::string(render::kValidationModelNames[m]) + "_max"] = b.max[t][m];
    }
    return j;
  };
  nlohmann::json j = models(0);
  j["rows"] = b.rows;
  j["near_m"] = b.nearM;
  j["far_m"] = b.farM;
  for (std::size_t t = 1; t < render::kValidationTerms; ++t) j[render::kValidationTermNames[t]] = models(t);
  return j;
}

nlohmann::json rowJson(const render::RowError& e) {
  nlohmann::json j = {{"row", e.row}, {"distance_m", e.distanceM}};
  for (std::size_t t = 0; t < render::kValidationTerms; ++t) {
    nlohmann::json& k = t == 0 ? j : j[render::kValidationTermNames[t]];
    k["reference"] = e.reference[t];
    for (std::size_t m = 0; m < render::kValidationModels; ++m) {
      k[render::kValidationModelNames[m]] = e.model[t][m];
      k[std::string("error_") + render::kValidationModelNames[m]] = e.error[t][m];
    }
  }
  return j;
}

void printText(const render::ValidationResult& r, bool rows) {
  std::printf("view %s: height %.0f m, heading %.0f, pitch %.0f, Sun %.0f deg high at %.0f\n",
              r.view.name.c_str(), r.view.heightM, r.view.headingDeg, r.view.pitchDeg,
              r.view.sunElevationDeg, r.view.sunAzimuthDeg);
  if (rows) {
    std::printf("  %4s %10s %11s %11s %11s %11s %9s %9s %9s\n", "row", "dist_m", "reference",
                "filtered", "constant", "brdf_only", "err_filt", "err_const", "err_brdf");
    for (const auto& e : r.rows)
      std::printf("  %4d %10.1f %11.5f %11.5f %11.5f %11.5f %+8.1f%% %+8.1f%% %+8.1f%%\n", e.row,
                  e.distanceM, e.reference[0], e.model[0][0], e.model[0][1], e.model[0][2],
                  100 * e.error[0][0], 100 * e.error[0][1], 100 * e.error[0][2]);
  }
  std::printf("  %-5s %-9s %5s %19s %17s %17s %17s\n", "band", "term", "rows", "distance_m",
              "filtered mean/max", "constant mean/max", "brdf_only mean/max");
  auto line = [](const render::BandError& b) {
    for (std::size_t t = 0; t < render::kValidationTerms; ++t)
      std::printf("  %-5s %-9s %5d %9.1f-%-9.1f %7.1f%% %7.1f%% %7.1f%% %7.1f%% %7.1f%% %7.1f%%\n",
                  b.name.c_str(), render::kValidationTermNames[t], b.rows, b.nearM, b.farM,
                  100 * b.mean[t][0], 100 * b.max[t][0], 100 * b.mean[t][1], 100 * b.max[t][1],
                  100 * b.mean[t][2], 100 * b.max[t][2]);
  };
  for (const auto& b : r.bands) line(b);
  line(r.all);
}
}  // namespace

Run addValidateCommand(CLI::App& parent) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "validate", "compare the filtered ocean, the paper's constant-BRDF ocean and a flat BRDF-only sea "
                  "with a supersampled reference, per lighting term (Bruneton 2010 7.2)");
  cmd->add_option("--width", o->settings.width, "image width")->check(CLI::Range(16, 1024));
  cmd->add_option("--height", o->settings.height, "image height")->check(CLI::Range(16, 1024));
  cmd->add_option("--supersample", o->settings.supersample, "reference samples per pixel along x and y")
      ->check(CLI::Range(1, 16));
  cmd->add_option("--cell", o->settings.cellPixels, "the models' grid cell in pixels")->check(CLI::Range(1, 64));
  cmd->add_option("--view", o->only, "run one view only (2m_sun, 2m_away, 20m_sun, ...)");
  cmd->add_option("--out", o->out, "write reference/filtered/constant/brdf_only PNGs per view into DIR");
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
        for (std::size_t m = 0; m < render::kValidationModels; ++m)
          io::writePng(dir / (v.name + "_" + render::kValidationModelNames[m] + ".png"),
                       render::validationPreview(r.models[m], exposure));
        io::writePng(dir / (v.name + "_strip.png"), render::validationStrip(r, exposure));
      }
      if (o->json) {
        nlohmann::json jv = {{"name", v.name},          {"height_m", v.heightM},
                             {"heading_deg", v.headingDeg}, {"pitch_deg", v.pitchDeg},
                             {"sun_elevation_deg", v.sunElevationDeg},
                             {"sun_azimuth_deg", v.sunAzimuthDeg}};
        for (const auto& b : r.bands) jv["bands"][b.name] = bandJson(b);
        jv["bands"]["all"] = bandJson(r.all);
        for (const auto& e : r.rows) jv["rows"].push_back(rowJson(e));
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
