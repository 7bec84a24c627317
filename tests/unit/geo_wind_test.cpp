// The one wind type (geo/Wind.hpp): where it comes from (flags, scene files) against where it
// blows towards (the physics, the shaders' u/v), and the one reading of --wind.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "geo/Wind.hpp"
#include "io/SceneFile.hpp"

using og::geo::Wind;
using og::geo::WindVector;

TEST(Wind, FromIsOppositeTowards) {
  // A westerly comes from the west (270) and blows towards the east (90): u > 0.
  const Wind westerly = Wind::blowingFrom(10.0, 270.0);
  EXPECT_DOUBLE_EQ(westerly.towardsDeg, 90.0);
  EXPECT_DOUBLE_EQ(westerly.fromDeg(), 270.0);
  EXPECT_NEAR(westerly.vector().uMs, 10.0, 1e-12);
  EXPECT_NEAR(westerly.vector().vMs, 0.0, 1e-12);
  // A north wind blows towards the south: v < 0.
  const WindVector north = Wind::blowingFrom(4.0, 0.0).vector();
  EXPECT_NEAR(north.uMs, 0.0, 1e-12);
  EXPECT_NEAR(north.vMs, -4.0, 1e-12);
  // A south-westerly (225) blows towards the north-east: u = v > 0.
  const WindVector sw = Wind::blowingFrom(2.0, 225.0).vector();
  EXPECT_NEAR(sw.uMs, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(sw.vMs, std::sqrt(2.0), 1e-12);
  // Angles wrap into [0, 360) whichever way they are given.
  EXPECT_DOUBLE_EQ(Wind::blowingFrom(1.0, -90.0).towardsDeg, 90.0);
  EXPECT_DOUBLE_EQ(Wind::blowingFrom(1.0, 630.0).towardsDeg, 90.0);
  EXPECT_DOUBLE_EQ(Wind::blowingTowards(1.0, -45.0).towardsDeg, 315.0);
  EXPECT_DOUBLE_EQ(Wind::blowingTowards(1.0, 45.0).fromDeg(), 225.0);
}

TEST(Wind, VectorRoundTrip) {
  for (double towards = 0.0; towards < 360.0; towards += 22.5) {
    const Wind w = Wind::ofVector(Wind::blowingTowards(7.5, towards).vector());
    EXPECT_NEAR(w.speedMs, 7.5, 1e-12) << towards;
    EXPECT_NEAR(w.towardsDeg, towards, 1e-9) << towards;
  }
  const Wind calm = Wind::ofVector({0.0, 0.0});
  EXPECT_EQ(calm.speedMs, 0.0);
  EXPECT_EQ(calm.towardsDeg, 0.0);
}

TEST(Wind, SceneWindIsWhereItComesFrom) {
  og::io::SceneSettings s;  // default: 7 m/s from 270
  EXPECT_DOUBLE_EQ(s.wind().towardsDeg, 90.0);
  s.windFromDeg = 10.0;
  s.windSpeedMs = 3.0;
  EXPECT_DOUBLE_EQ(s.wind().towardsDeg, 190.0);
  EXPECT_DOUBLE_EQ(s.wind().speedMs, 3.0);
}

TEST(Wind, TheFlagIsReadOnce) {
  const Wind a = og::geo::parseWindFlag("12,45", 270.0);
  EXPECT_DOUBLE_EQ(a.speedMs, 12.0);
  EXPECT_DOUBLE_EQ(a.fromDeg(), 45.0);
  EXPECT_DOUBLE_EQ(a.towardsDeg, 225.0);
  const Wind b = og::geo::parseWindFlag("5", 300.0);  // direction left out: the default "from"
  EXPECT_DOUBLE_EQ(b.fromDeg(), 300.0);
  auto error = [](const std::string& text) {
    try {
      (void)og::geo::parseWindFlag(text, 270.0);
    } catch (const og::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error("5,abc").find("--wind: expected SPEED[,FROM]"), std::string::npos) << error("5,abc");
  EXPECT_NE(error("").find("--wind"), std::string::npos);
  EXPECT_NE(error("80").find("wind speed must be within [0, 50] m/s"), std::string::npos) << error("80");
  EXPECT_NE(error("-1,0").find("wind speed"), std::string::npos);
  EXPECT_NE(error("5,1000").find("wind direction"), std::string::npos);
  EXPECT_NE(error("nan").find("wind speed"), std::string::npos);
}
