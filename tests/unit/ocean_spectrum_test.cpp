#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "ocean/WaveSet.hpp"

using namespace og::ocean;

// Issue 4: the mean-square slope follows Cox & Munk's clean-surface regression within ±25%
// for 3..15 m/s, with the up/crosswind ratio in their observed range.
TEST(OceanSpectrum, WaveSetSlopeVarianceFollowsCoxMunk) {
  for (double u = 3.0; u <= 15.0; u += 1.0) {
    WaveSetParams p;
    p.windSpeedMs = u;
    const WaveSet set = makeWaveSet(p);
    const SlopeVariance cm = coxMunkCleanSurface(u);
    EXPECT_NEAR(set.total.total() / cm.total(), 1.0, 0.25) << "U = " << u;
    const double ratio = set.total.up / set.total.cross;
    EXPECT_GT(ratio, 1.0) << "U = " << u;  // rougher along the wind
    EXPECT_LT(ratio, 2.0) << "U = " << u;
    // The unresolved tail (sub-2 cm waves) is counted, and grows with the wind.
    EXPECT_GT(set.unresolvedTail.total(), 0.01 * set.total.total());
    EXPECT_DOUBLE_EQ(set.total.up, set.resolved.up + set.unresolvedTail.up);
    EXPECT_GT(set.resolved.total(), 0.3 * set.total.total());
  }
}

TEST(OceanSpectrum, WaveSetIsReproducibleAndGeometric) {
  WaveSetParams p;
  p.windSpeedMs = 10.0;
  p.windDirectionDeg = 45.0;
  p.seed = 42;
  const WaveSet a = makeWaveSet(p), b = makeWaveSet(p);
  ASSERT_EQ(a.waves.size(), 60u);
  for (std::size_t i = 0; i < a.waves.size(); ++i) {
    EXPECT_EQ(a.waves[i].phaseRad, b.waves[i].phaseRad);
    EXPECT_EQ(a.waves[i].kEast, b.waves[i].kEast);
    if (i > 0) {
      EXPECT_NEAR(a.waves[i].wavelengthM / a.waves[i - 1].wavelengthM, a.wavelengthRatio, 1e-12);
    }
    // Dispersion: omega² = g k (1 + (k/km)²) >= g k.
    const double k = a.waves[i].k();
    EXPECT_GE(a.waves[i].omegaRadS * a.waves[i].omegaRadS, 9.81 * k * (1 - 1e-12));
    EXPECT_LT(k * a.waves[i].amplitudeM, 0.45);  // trochoids never loop
  }
  EXPECT_NEAR(a.waves.back().wavelengthM, 0.02, 1e-12);
  p.seed = 43;
  EXPECT_NE(makeWaveSet(p).waves[0].phaseRad, a.waves[0].phaseRad);
}

TEST(OceanSpectrum, WavesTravelDownwindAndRoughnessGrowsWithWind) {
  WaveSetParams p;
  p.windDirectionDeg = 200.0;
  double previousMss = 0.0, previousHeight = 0.0;
  for (double u : {2.0, 5.0, 10.0, 20.0}) {
    p.windSpeedMs = u;
    const WaveSet set = makeWaveSet(p);
    for (const auto& w : set.waves) {
      const double off = std::remainder(w.directionDeg - p.windDirectionDeg, 360.0);
      EXPECT_LE(std::abs(off), 90.0 + 1e-9);
    }
    EXPECT_GT(set.total.total(), previousMss);
    EXPECT_GT(set.heightVarianceM2, previousHeight);
    previousMss = set.total.total();
    previousHeight = set.heightVarianceM2;
  }
  // Significant wave height of a fully developed sea at 10 m/s is about 2 m (PM: 0.21 U²/g).
  p.windSpeedMs = 10.0;
  const double hs = 4.0 * std::sqrt(makeWaveSet(p).heightVarianceM2);
  EXPECT_GT(hs, 1.2);
  EXPECT_LT(hs, 3.5);
}

TEST(OceanSpectrum, TrochoidSlopeVarianceMatchesEq4) {
  Wave w;
  w.wavelengthM = 2.0 * 3.14159265358979323846;  // k = 1
  w.kEast = 1.0;
  w.amplitudeM = 0.1;
  // Along k: 1 - sqrt(1 - k²h²); across: 0; small kh: ~ k²h²/2.
  EXPECT_NEAR(trochoidSlopeVariance(w, 1, 0), 1.0 - std::sqrt(1.0 - 0.01), 1e-15);
  EXPECT_NEAR(trochoidSlopeVariance(w, 0, 1), 0.0, 1e-15);
  EXPECT_NEAR(trochoidSlopeVariance(w, 1, 0, 0.0), 0.0, 1e-15);
}

TEST(OceanSpectrum, RejectsBadParameters) {
  WaveSetParams p;
  p.windSpeedMs = -1;
  EXPECT_THROW(makeWaveSet(p), og::InputError);
  p.windSpeedMs = NAN;
  EXPECT_THROW(makeWaveSet(p), og::InputError);
  p.windSpeedMs = 5;
  p.count = 0;
  EXPECT_THROW(makeWaveSet(p), og::InputError);
}

TEST(OceanSpectrum, WindTablesMatchTheWaveSetAtItsOwnWind) {
  WaveSetParams p;
  p.windSpeedMs = 8.0;
  const WaveSet set = makeWaveSet(p);
  const WindTables t = makeWindTables(set, 41, 1.0);
  ASSERT_EQ(t.total.size(), 41u);
  for (std::size_t i = 0; i < set.waves.size(); ++i)
    EXPECT_NEAR(t.amplitudeM[8][i], set.waves[i].amplitudeM, 1e-12) << i;
  EXPECT_NEAR(t.total[8].total(), set.total.total(), 0.05 * set.total.total());
  // Calmer: smaller waves and slopes; windier: larger.
  EXPECT_LT(t.total[3].total(), t.total[8].total());
  EXPECT_GT(t.total[15].total(), t.total[8].total());
  EXPECT_LT(t.amplitudeM[3][0], t.amplitudeM[8][0]);
}
