// The ocean frame keeps waves fixed to the Earth as it is rebuilt under a moving camera.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/OceanFrame.hpp"

using namespace og;
using namespace og::ocean;

namespace {
// Phase of wave i at an ECEF point on the sea, seen through a frame (tangent-plane coords).
double phaseAt(const OceanFrame& f, const OceanFrame::WavePhases& p, std::size_t i,
               const glm::dvec3& ecef) {
  const glm::dvec3 x = f.axes().toEnu(ecef - f.originEcef());
  return p.phaseRad[i] - glm::dot(p.k[i], glm::dvec2(x.x, x.y));
}
double wrapped(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }
}  // namespace

TEST(OceanFrame, MovesCarryPhasesSoWavesStayOnTheEarth) {
  WaveSetParams params;
  params.windSpeedMs = 9.0;
  const WaveSet waves = makeWaveSet(params);
  for (const geo::Geodetic start : {geo::Geodetic{0, 0, 2}, geo::Geodetic{60, 179.999, 2},
                                    geo::Geodetic{-45, -120, 2}, geo::Geodetic{89.9, 10, 2}}) {
    OceanFrame f;
    f.reset(start);
    // A sea point 30 m from the start, where the near-field waves are drawn.
    const geo::EnuFrame e = geo::enuFrameAt(start.latitudeDeg, start.longitudeDeg);
    const glm::dvec3 point = f.originEcef() + e.toEcef({20, 22, 0});
    const auto before = f.phases(waves, 12.5);
    for (double stepDeg : {1e-8, 1e-5, 1e-3}) {  // ~1 mm, ~1 m, ~100 m
      geo::Geodetic moved = start;
      moved.longitudeDeg += stepDeg;
      moved.latitudeDeg = std::min(89.99, moved.latitudeDeg + 0.5 * stepDeg);
      OceanFrame g = f;
      g.moveTo(moved);
      const auto after = g.phases(waves, 12.5);
      for (std::size_t i = 0; i < waves.waves.size(); ++i) {
        // Error grows with k and the distance moved (tangent-plane curvature): bounded by
        // 1e-3 rad for the shortest (2 cm) waves after a 100 m move.
        EXPECT_NEAR(wrapped(phaseAt(g, after, i, point) - phaseAt(f, before, i, point)), 0.0, 1e-3)
            << "wave " << i << " step " << stepDeg << " at " << start.latitudeDeg;
      }
    }
  }
}

TEST(OceanFrame, PhasesAdvanceWithTimeAtTheWaveFrequency) {
  WaveSetParams params;
  const WaveSet waves = makeWaveSet(params);
  OceanFrame f;
  f.reset({10, 20, 0});
  const auto a = f.phases(waves, 100.0), b = f.phases(waves, 100.25);
  for (std::size_t i = 0; i < waves.waves.size(); ++i)
    EXPECT_NEAR(wrapped(b.phaseRad[i] - a.phaseRad[i] - 0.25 * waves.waves[i].omegaRadS), 0.0, 1e-9);
}
