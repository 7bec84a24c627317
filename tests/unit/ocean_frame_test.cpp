// The ocean frame keeps waves fixed to the Earth as it is rebuilt under a moving camera.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/OceanFrame.hpp"

using namespace og;
using namespace og::ocean;

namespace {
// Where an ECEF point on the sea lies in the wave field, seen through a frame: its tangent-plane
// position plus the frame's offset, turned into the field's axes (as shaders/ocean/patterns.glsl
// does with the folded offsets).
glm::dvec2 fieldPositionOf(const OceanFrame& f, const glm::dvec3& ecef) {
  const glm::dvec3 x = f.axes().toEnu(ecef - f.originEcef());
  const glm::dvec2 p = glm::dvec2(x.x, x.y) + f.fieldOffsetM();
  const double c = std::cos(f.fieldRotationRad()), s = std::sin(f.fieldRotationRad());
  return {c * p.x + s * p.y, -s * p.x + c * p.y};
}
}  // namespace

TEST(OceanFrame, MovesCarryTheFieldSoWavesStayOnTheEarth) {
  for (const geo::Geodetic start : {geo::Geodetic{0, 0, 2}, geo::Geodetic{60, 179.999, 2},
                                    geo::Geodetic{-45, -120, 2}, geo::Geodetic{89.9, 10, 2}}) {
    OceanFrame f;
    f.reset(start);
    // A sea point 30 m from the start, where the near-field waves are drawn.
    const geo::EnuFrame e = geo::enuFrameAt(start.latitudeDeg, start.longitudeDeg);
    const glm::dvec3 point = f.originEcef() + e.toEcef({20, 22, 0});
    const glm::dvec2 before = fieldPositionOf(f, point);
    for (double stepDeg : {1e-8, 1e-5, 1e-3}) {  // ~1 mm, ~1 m, ~100 m
      geo::Geodetic moved = start;
      moved.longitudeDeg += stepDeg;
      moved.latitudeDeg = std::min(89.99, moved.latitudeDeg + 0.5 * stepDeg);
      OceanFrame g = f;
      g.moveTo(moved);
      // Tangent-plane curvature bounds the error: well under the finest pattern's 5 mm texel
      // after a 100 m move.
      EXPECT_LT(glm::length(fieldPositionOf(g, point) - before), 1e-4)
          << "step " << stepDeg << " at " << start.latitudeDeg;
    }
  }
}

TEST(OceanFrame, FoldedOffsetIsTheFieldOffsetModuloTheTile) {
  OceanFrame f;
  f.reset({10, 20, 0});
  for (int i = 1; i <= 40; ++i) f.moveTo({10 + 0.37 * i, 20 + 1.13 * i, 0});  // ~6000 km away
  const double c = std::cos(f.fieldRotationRad()), s = std::sin(f.fieldRotationRad());
  const glm::dvec2 o = f.fieldOffsetM();
  const glm::dvec2 field{c * o.x + s * o.y, -s * o.x + c * o.y};
  for (const double tile : {4983.0, 530.473, 0.64}) {
    const glm::dvec2 folded = f.fieldOffsetModulo(tile);
    for (int axis = 0; axis < 2; ++axis) {
      EXPECT_GE(folded[axis], 0.0);
      EXPECT_LT(folded[axis], tile);
      const double whole = (field[axis] - folded[axis]) / tile;
      EXPECT_NEAR(whole, std::round(whole), 1e-9) << tile;
    }
  }
}
