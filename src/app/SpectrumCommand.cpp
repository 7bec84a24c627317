// oceanglobe spectrum: the wave patterns, slope and whitecap statistics for a wind, as text or JSON.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/Commands.hpp"
#include "core/Error.hpp"
#include "geo/Wind.hpp"
#include "ocean/WavePatterns.hpp"

namespace og::app {
namespace {
struct SpectrumOptions {
  std::string wind = "7";
  unsigned long long seed = 1;
  bool json = false;
};

void printJson(const ocean::WavePatterns& w, const ocean::PatternTables& t, double u, double fromDeg) {
  const auto speed = static_cast<int>(std::lround(std::clamp(u, 0.0, 50.0)));
  const ocean::SlopeVariance tail = t.tail[static_cast<std::size_t>(speed)];
  ocean::SlopeVariance resolved;
  double height = 0.0, jacobian = 0.0;
  nlohmann::json patterns = nlohmann::json::array();
  for (int i = 0; i < ocean::kPatternCount; ++i) {
    const auto& s = w.stats[0][static_cast<std::size_t>(i)];
    resolved.up += s.slope.up;
    resolved.cross += s.slope.cross;
    height += s.heightVarianceM2;
    for (int set = 0; set < ocean::kPatternSets; ++set)
      jacobian += w.stats[static_cast<std::size_t>(set)][static_cast<std::size_t>(i)].jacobianVariance / ocean::kPatternSets;
    patterns.push_back({{"size_m", w.params.sizesM[static_cast<std::size_t>(i)]},
                        {"longest_wave_m", i == 0 ? w.params.sizesM[0] : 2.0 * std::numbers::pi / w.kEdge[static_cast<std::size_t>(i)]},
                        {"shortest_wave_m", 2.0 * std::numbers::pi / w.kEdge[static_cast<std::size_t>(i + 1)]},
                        {"choppiness", w.params.choppiness[static_cast<std::size_t>(i)]},
                        {"height_variance_m2", s.heightVarianceM2},
                        {"sigma_up2", s.slope.up}, {"sigma_cross2", s.slope.cross},
                        {"jacobian_variance", s.jacobianVariance}});
  }
  const ocean::SlopeVariance cm = ocean::coxMunkCleanSurface(u);
  nlohmann::json j;
  j["wind_speed_ms"] = u;
  j["wind_from_deg"] = fromDeg;
  j["wind_towards_deg"] = geo::Wind::blowingFrom(u, fromDeg).towardsDeg;
  j["mss"] = resolved.total() + tail.total();
  j["sigma_up2"] = resolved.up + tail.up;
  j["sigma_cross2"] = resolved.cross + tail.cross;
  j["resolved"] = {{"sigma_up2", resolved.up}, {"sigma_cross2", resolved.cross}};
  j["unresolved_tail"] = {{"sigma_up2", tail.up}, {"sigma_cross2", tail.cross}};
  j["cox_munk_clean"] = {{"mss", cm.total()}, {"sigma_up2", cm.up}, {"sigma_cross2", cm.cross}};
  j["height_variance_m2"] = height;
  j["significant_wave_height_m"] = 4.0 * std::sqrt(height);
  j["jacobian_variance"] = jacobian;
  j["whitecap_threshold"] = ocean::kWhitecapThreshold;
  j["whitecap_coverage"] = ocean::whitecapCoverage(1.0, jacobian);
  j["monahan_whitecap_coverage"] = ocean::monahanWhitecapCoverage(u);
  j["fft_size"] = w.params.fftSize;
  j["patterns"] = patterns;
  std::printf("%s\n", j.dump(2).c_str());
}

void printText(const ocean::WavePatterns& w, const ocean::PatternTables& t, double u, double fromDeg) {
  const auto speed = static_cast<std::size_t>(std::lround(std::clamp(u, 0.0, 50.0)));
  ocean::SlopeVariance v = t.tail[speed];
  double height = 0.0, jacobian = 0.0;
  for (int i = 0; i < ocean::kPatternCount; ++i) {
    const auto& s = w.stats[0][static_cast<std::size_t>(i)];
    v.up += s.slope.up;
    v.cross += s.slope.cross;
    height += s.heightVarianceM2;
    for (int set = 0; set < ocean::kPatternSets; ++set)
      jacobian += w.stats[static_cast<std::size_t>(set)][static_cast<std::size_t>(i)].jacobianVariance / ocean::kPatternSets;
  }
  const ocean::SlopeVariance cm = ocean::coxMunkCleanSurface(u);
  std::printf("wind %.2f m/s from %.1f deg; %d FFT patterns of %d^2 modes, waves %.3f m .. %.0f m\n", u,
              fromDeg, ocean::kPatternCount, w.params.fftSize,
              2.0 * std::numbers::pi / w.kEdge[ocean::kPatternCount], w.params.sizesM[0]);
  std::printf("mean-square slope %.5f (up %.5f, cross %.5f); Cox-Munk clean %.5f (%.5f, %.5f)\n",
              v.total(), v.up, v.cross, cm.total(), cm.up, cm.cross);
  std::printf("significant wave height %.2f m\n", 4.0 * std::sqrt(height));
  std::printf("whitecap coverage %.4f (Monahan 1980: %.4f)\n", ocean::whitecapCoverage(1.0, jacobian),
              ocean::monahanWhitecapCoverage(u));
  std::printf("%10s %12s %12s %12s %10s %6s\n", "tile_m", "longest_m", "shortest_m", "height_m2", "mss", "chop");
  for (int i = 0; i < ocean::kPatternCount; ++i) {
    const auto& s = w.stats[0][static_cast<std::size_t>(i)];
    std::printf("%10.3f %12.3f %12.4f %12.5f %10.5f %6.2f\n", w.params.sizesM[static_cast<std::size_t>(i)],
                i == 0 ? w.params.sizesM[0] : 2.0 * std::numbers::pi / w.kEdge[static_cast<std::size_t>(i)],
                2.0 * std::numbers::pi / w.kEdge[static_cast<std::size_t>(i + 1)], s.heightVarianceM2,
                s.slope.total(), w.params.choppiness[static_cast<std::size_t>(i)]);
  }
}
}  // namespace

Run addSpectrumCommand(CLI::App& parent) {
  auto o = std::make_shared<SpectrumOptions>();
  CLI::App* cmd = parent.add_subcommand("spectrum", "print the wave patterns, slope and whitecap statistics for a wind");
  cmd->add_option("--wind", o->wind,
                  "SPEED[,FROM]: 10 m wind in m/s and where it comes from, degrees clockwise from "
                  "north (meteorological)");
  cmd->add_option("--seed", o->seed, "seed for the waves' random amplitudes and phases");
  cmd->add_flag("--json", o->json, "print JSON");
  return [o]() {
    const geo::Wind wind = geo::parseWindFlag(o->wind, 270.0);
    const double u = wind.speedMs, fromDeg = wind.fromDeg();
    ocean::WavePatternParams p;
    p.referenceWindMs = u;
    p.seed = o->seed;
    const ocean::WavePatterns w = ocean::makeWavePatterns(p);
    const ocean::PatternTables t = ocean::makePatternTables(w);
    if (o->json) printJson(w, t, u, fromDeg);
    else printText(w, t, u, fromDeg);
    return 0;
  };
}

}  // namespace og::app
