// oceanglobe spectrum: the wave set and slope statistics for a wind, as text or JSON.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/Commands.hpp"
#include "core/Error.hpp"
#include "ocean/WaveSet.hpp"

namespace og::app {
namespace {
struct SpectrumOptions {
  std::string wind = "7";
  int waves = 60;
  unsigned long long seed = 1;
  bool json = false;
};

double parseNumber(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    throw InputError("--wind: " + what + " '" + text + "' is not a number");
  return v;
}
}  // namespace

Run addSpectrumCommand(CLI::App& parent) {
  auto o = std::make_shared<SpectrumOptions>();
  CLI::App* cmd = parent.add_subcommand("spectrum", "print the wave set and slope variances for a wind");
  cmd->add_option("--wind", o->wind,
                  "SPEED[,FROM]: 10 m wind in m/s and where it comes from, degrees clockwise from "
                  "north (meteorological)");
  cmd->add_option("--waves", o->waves, "number of waves")->check(CLI::Range(1, 256));
  cmd->add_option("--seed", o->seed, "seed for directions and phases");
  cmd->add_flag("--json", o->json, "print JSON");
  return [o]() {
    ocean::WaveSetParams p;
    const std::size_t comma = o->wind.find(',');
    p.windSpeedMs = parseNumber(o->wind.substr(0, comma), "speed");
    double fromDeg = 270.0;
    if (comma != std::string::npos) fromDeg = parseNumber(o->wind.substr(comma + 1), "direction");
    p.windDirectionDeg = std::fmod(fromDeg + 180.0, 360.0);  // the waves run downwind
    p.count = o->waves;
    p.seed = o->seed;
    const ocean::WaveSet set = ocean::makeWaveSet(p);
    const ocean::SlopeVariance cm = ocean::coxMunkCleanSurface(p.windSpeedMs);
    if (o->json) {
      nlohmann::json j;
      j["wind_speed_ms"] = p.windSpeedMs;
      j["wind_from_deg"] = fromDeg;
      j["wind_towards_deg"] = p.windDirectionDeg;
      j["mss"] = set.total.total();
      j["sigma_up2"] = set.total.up;
      j["sigma_cross2"] = set.total.cross;
      j["resolved"] = {{"sigma_up2", set.resolved.up}, {"sigma_cross2", set.resolved.cross}};
      j["unresolved_tail"] = {{"sigma_up2", set.unresolvedTail.up},
                              {"sigma_cross2", set.unresolvedTail.cross}};
      j["cox_munk_clean"] = {{"mss", cm.total()}, {"sigma_up2", cm.up}, {"sigma_cross2", cm.cross}};
      j["height_variance_m2"] = set.heightVarianceM2;
      j["significant_wave_height_m"] = 4.0 * std::sqrt(set.heightVarianceM2);
      for (const auto& w : set.waves)
        j["waves"].push_back({{"wavelength_m", w.wavelengthM}, {"amplitude_m", w.amplitudeM},
                              {"direction_deg", w.directionDeg}, {"omega_rad_s", w.omegaRadS},
                              {"phase_rad", w.phaseRad}});
      std::printf("%s\n", j.dump(2).c_str());
    } else {
      std::printf("wind %.2f m/s from %.1f deg; %zu waves, %.3f m .. %.3f m\n", p.windSpeedMs,
                  fromDeg, set.waves.size(), set.waves.back().wavelengthM,
                  set.waves.front().wavelengthM);
      std::printf("mean-square slope %.5f (up %.5f, cross %.5f); Cox-Munk clean %.5f (%.5f, %.5f)\n",
                  set.total.total(), set.total.up, set.total.cross, cm.total(), cm.up, cm.cross);
      std::printf("significant wave height %.2f m\n", 4.0 * std::sqrt(set.heightVarianceM2));
      std::printf("%12s %12s %10s %10s\n", "lambda_m", "height_m", "dir_deg", "omega");
      for (const auto& w : set.waves)
        std::printf("%12.4f %12.5f %10.1f %10.3f\n", w.wavelengthM, w.amplitudeM, w.directionDeg,
                    w.omegaRadS);
    }
    return 0;
  };
}

}  // namespace og::app
