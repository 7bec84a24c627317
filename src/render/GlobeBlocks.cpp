#include "render/GlobeBlocks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "geo/Wgs84.hpp"

namespace og::render {
namespace {

// A block corner's ray on the ellipsoid: hit, geodetic normal, latitude and longitude
// (degrees), cosine of incidence.
struct CornerHit {
  glm::dvec3 dir{0.0};  ///< the corner's ray, unit
  bool hit = false;
  glm::dvec3 normal{0.0};
  double latDeg = 0.0, lonDeg = 0.0, cosIncidence = 0.0;
  double distanceM = 0.0;
  /// How far the lattice bends here: the largest second difference of latitude and of
  /// longitude (degrees) over the corner's neighbours along either axis of the lattice
  /// (bendCorners); infinite where a neighbour is missing, misses or lies off the regular lattice.
  glm::dvec2 bendDeg{std::numeric_limits<double>::infinity()};
};

// Latitude and longitude (degrees) of a unit geodetic normal.
glm::dvec2 latLonDegOf(const glm::dvec3& n) {
  return glm::dvec2(std::asin(std::clamp(n.z, -1.0, 1.0)), std::atan2(n.y, n.x)) * (180.0 / std::numbers::pi);
}

CornerHit cornerHit(const geo::CameraView& view, double ndcX, double ndcY) {
  CornerHit c;
  const glm::dvec3 dir = view.rayDirection(ndcX, ndcY);
  c.dir = dir;
  const std::optional<double> t = geo::intersectEllipsoid(view.positionEcef, dir);
  if (!t) return c;
  c.hit = true;
  c.normal = geo::ellipsoidNormalAt(view.positionEcef + *t * dir);
  const glm::dvec2 latLon = latLonDegOf(c.normal);
  c.latDeg = latLon.x;
  c.lonDeg = latLon.y;
  c.cosIncidence = -glm::dot(c.normal, dir);
  c.distanceM = *t;
  return c;
}

// A longitude (degrees) unwrapped to lie within 180° of `refDeg`.
double lonNextTo(double lonDeg, double refDeg) {
  return lonDeg + (lonDeg - refDeg > 180.0 ? -360.0 : refDeg - lonDeg > 180.0 ? 360.0 : 0.0);
}

// The corners' bendDeg, for a lattice of `columns` × `rows` corners whose last column and row
// are regular (a full block's side from the one before) where `lastColumnFull` / `lastRowFull`.
void bendCorners(std::vector<CornerHit>& corners, int columns, int rows, bool lastColumnFull, bool lastRowFull) {
  const auto at = [&](int i, int j) -> CornerHit& {
    return corners[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i)];
  };
  const int lastI = lastColumnFull ? columns - 1 : columns - 2, lastJ = lastRowFull ? rows - 1 : rows - 2;
  for (int j = 1; j < lastJ; ++j)
    for (int i = 1; i < lastI; ++i) {
      CornerHit& c = at(i, j);
      const std::array<const CornerHit*, 4> around{&at(i - 1, j), &at(i + 1, j), &at(i, j - 1), &at(i, j + 1)};
      if (!c.hit || !std::all_of(around.begin(), around.end(), [](const CornerHit* n) { return n->hit; })) continue;
      const auto latLon = [&c](const CornerHit* n) { return glm::dvec2(n->latDeg, lonNextTo(n->lonDeg, c.lonDeg)); };
      const glm::dvec2 here(c.latDeg, c.lonDeg);
      c.bendDeg = glm::max(glm::abs(latLon(around[0]) - 2.0 * here + latLon(around[1])),
                           glm::abs(latLon(around[2]) - 2.0 * here + latLon(around[3])));
    }
}

// Whether every point of the block (its four corners' hull) lies in the open deep sea: within
// 0.9 of the clearance of the map's cell under its mean normal (the per-pixel test's margin). Not
// the per-pixel test itself (each pixel's own cell and centre), but as strict: a block it
// passes is open deep sea at every pixel, which either part shades alike.
bool blockInOpenSea(const std::array<const CornerHit*, 4>& corners, const OpenSeaMap& openSea) {
  glm::dvec3 centre{0.0};
  for (const CornerHit* c : corners) centre += c->normal;
  centre = glm::normalize(centre);
  const glm::dvec2 latLon = latLonDegOf(centre);
  const double clearance = openSea.clearanceAt(latLon.x, latLon.y);
  if (clearance <= 0.0) return false;
  for (const CornerHit* c : corners)
    if (glm::dot(c->normal, centre) <= std::cos(0.9 * clearance)) return false;
  return true;
}

// The class the mask gives every point of the box (degrees) `lo` ... `hi` widened by `reach`
// cells of `cellDeg` (columns from the mask's west edge, rows from its south edge), or Both.
data::LandMaskPyramid::Content boxContent(const data::LandMaskPyramid& pyramid, glm::dvec2 lo, glm::dvec2 hi,
                                          double cellDeg, bool fine) {
  const data::LandMask& mask = pyramid.mask();
  const int c0 = static_cast<int>(std::floor((lo.y - mask.westDeg()) / cellDeg)) - 1;
  const int c1 = static_cast<int>(std::floor((hi.y - mask.westDeg()) / cellDeg)) + 1;
  const int r0 = static_cast<int>(std::floor((lo.x - mask.southDeg()) / cellDeg)) - 1;
  const int r1 = static_cast<int>(std::floor((hi.x - mask.southDeg()) / cellDeg)) + 1;
  return fine ? pyramid.fineCells(c0, c1, r0, r1) : pyramid.cells(c0, c1, r0, r1);
}

// Whether every corner's ray sees space (globe.frag's skyOf: it misses the atmosphere's
// sphere) and lies farther than `clearRad` from the Sun's direction.
bool cornersInSpace(const std::array<const CornerHit*, 4>& corners, const geo::CameraView& view,
                    const GlobeSkyOutline& sky, double clearRad) {
  const double r = sky.bottomRadiusM + view.position.heightM;
  for (const CornerHit* c : corners) {
    const double mu = glm::dot(c->dir, view.enu.up);
    if (!(mu >= 0.0 || r * r * (mu * mu - 1.0) + sky.topRadiusM * sky.topRadiusM < 0.0)) return false;
    if (glm::dot(c->dir, sky.sunDirection) > std::cos(clearRad)) return false;
  }
  return true;
}

// What the mask's own fraction (the B-spline of the 2′ cells and the fine level's) makes every
// point of the box lo ... hi (degrees) for footprints up to `footprintDeg`. Where every
// pixel's footprint is under a fine cell (globe.frag: the fine level's weight is 1 up to one,
// with a tenth of margin), the fine cells alone decide, up to 8 times closer to the coast.
data::LandMaskPyramid::Content maskContent(const data::LandMaskPyramid& pyramid, glm::dvec2 lo, glm::dvec2 hi,
                                           double footprintDeg) {
  const data::LandMask& mask = pyramid.mask();
  const data::LandMaskPyramid::Content content = boxContent(pyramid, lo, hi, mask.cellDeg(), false);
  const double fineCellDeg = mask.cellDeg() / data::LandMask::kFinePerCell;
  if (content == data::LandMaskPyramid::Content::Both && mask.hasFineLevel() && footprintDeg < 0.9 * fineCellDeg &&
      hi.y - lo.y < 64.0 * fineCellDeg && hi.x - lo.x < 64.0 * fineCellDeg)
    return boxContent(pyramid, lo, hi, fineCellDeg, true);
  return content;
}

// Where some pixel's footprint spans more than a 2′ cell, the land fraction's pyramid weighs
// in (data::LandFractionMips::landFraction): what every point of the box lo ... hi (degrees)
// is as footprints of footprintLoDeg ... footprintHiDeg see it, from the bytes the pyramid's
// lookups there can blend and, while the B-spline still weighs (under two cells), the mask's
// own (maskContent). Both where a point may lie near 0.5 (2.5 bytes of margin).
data::LandMaskPyramid::Content filteredContent(const data::LandFractionMips& mips, const data::LandMaskPyramid& pyramid,
                                               glm::dvec2 lo, glm::dvec2 hi, double footprintLoDeg,
                                               double footprintHiDeg) {
  const data::LandMaskPyramid::Content filtered =
      mips.boxContent(lo.x, hi.x, lo.y, hi.y, mips.levelOf(footprintLoDeg), mips.levelOf(footprintHiDeg));
  // While the B-spline still weighs, the blend is one class where both are.
  if (filtered == data::LandMaskPyramid::Content::Both || mips.weight(footprintLoDeg) >= 1.0) return filtered;
  return maskContent(pyramid, lo, hi, footprintHiDeg) == filtered ? filtered : data::LandMaskPyramid::Content::Both;
}

// The box (latitude, longitude degrees: low and high corners) that holds every point of a
// block whose corners all hit, its longitudes unwrapped next to the first corner's; none where
// it spans over 30° (classed per pixel).
std::optional<std::array<glm::dvec2, 2>> footprintBox(const std::array<const CornerHit*, 4>& corners) {
  // The corners' box, longitudes unwrapped next to the first corner's.
  double latLo = 90.0, latHi = -90.0, lonLo = 1e9, lonHi = -1e9;
  for (const CornerHit* c : corners) {
    const double lon = lonNextTo(c->lonDeg, corners[0]->lonDeg);
    latLo = std::min(latLo, c->latDeg);
    latHi = std::max(latHi, c->latDeg);
    lonLo = std::min(lonLo, lon);
    lonHi = std::max(lonHi, lon);
  }
  if (lonHi - lonLo > 30.0 || latHi - latLo > 30.0) return std::nullopt;
  // Widened by how far the footprint's edges may bow out between the corners, and (boxContent)
  // by the B-spline's reach: a point's fraction reads the 3 x 3 cells around its nearest
  // centre, the centre of the cell it lies in (the fine level's 3 x 3 fine cells lie in those
  // cells too). An edge's middle lies a second difference's eighth off its chord, and the
  // block's inside at most the sum of the two screen axes' (a quadratic through the corners):
  // per coordinate a quarter of the corners' largest (bendDeg holds the larger axis's), taken
  // four times over (curvature that is not constant across the neighbours' stencil), and a
  // hundredth of the box; a quarter of the box where the lattice gives no bend (its edge, the
  // limb).
  glm::dvec2 bendDeg(0.0);
  for (const CornerHit* c : corners) bendDeg = glm::max(bendDeg, c->bendDeg);
  const glm::dvec2 boxDeg(latHi - latLo, lonHi - lonLo);
  const glm::dvec2 margin = std::isfinite(bendDeg.x) && std::isfinite(bendDeg.y)
                                ? 0.01 * boxDeg + bendDeg
                                : 0.25 * boxDeg;
  return std::array<glm::dvec2, 2>{glm::dvec2(latLo, lonLo) - margin, glm::dvec2(latHi, lonHi) + margin};
}

GlobeBlockClass classifyBlock(const std::array<const CornerHit*, 4>& corners, const data::LandMaskPyramid& pyramid,
                              const data::LandFractionMips* mips, const OpenSeaMap* openSea, bool missOk,
                              double pixelRad) {
  int misses = 0;
  double minCos = 1.0;
  for (const CornerHit* c : corners) {
    misses += c->hit ? 0 : 1;
    minCos = std::min(minCos, c->hit ? c->cosIncidence : 0.0);
  }
  if (misses == 4 && missOk) return GlobeBlockClass::Miss;
  for (const CornerHit* c : corners)
    if (!c->hit || c->cosIncidence < kMinCosIncidence || std::abs(c->latDeg) > 88.0) return GlobeBlockClass::PerPixel;
  const std::optional<std::array<glm::dvec2, 2>> box = footprintBox(corners);
  if (!box) return GlobeBlockClass::PerPixel;
  const data::LandMask& mask = pyramid.mask();
  const glm::dvec2 lo = (*box)[0], hi = (*box)[1];
  double footprintDeg = 0.0, smallestFootprintDeg = 1e9;
  for (const CornerHit* c : corners) {
    const double f = data::LandMask::coastFootprintDeg(c->distanceM, pixelRad, c->cosIncidence);
    footprintDeg = std::max(footprintDeg, f);
    smallestFootprintDeg = std::min(smallestFootprintDeg, f);
  }
  // The pixels' footprints (the mean of four samples') between the corners', with a tenth of
  // margin each way; the pyramid weighs from one cell up.
  const data::LandMaskPyramid::Content content =
      mips != nullptr && 1.1 * footprintDeg > mask.cellDeg()
          ? filteredContent(*mips, pyramid, lo, hi, smallestFootprintDeg / 1.1, 1.1 * footprintDeg)
          : maskContent(pyramid, lo, hi, footprintDeg);
  switch (content) {
    case data::LandMaskPyramid::Content::Land:
      return GlobeBlockClass::Land;
    case data::LandMaskPyramid::Content::Water:
      return openSea != nullptr && minCos >= kMinCosIncidenceOpenSea && blockInOpenSea(corners, *openSea)
                 ? GlobeBlockClass::OpenSea
                 : GlobeBlockClass::Sea;
    case data::LandMaskPyramid::Content::Both:
      break;
  }
  return GlobeBlockClass::PerPixel;
}

}  // namespace

GlobeBlocks classifyGlobeBlocks(const geo::CameraView& view, int width, int height, const std::array<int, 4>& rect,
                                const data::LandMaskPyramid& mask, const OpenSeaMap* openSea,
                                const GlobeSkyOutline* sky, const data::LandFractionMips* mips) {
  GlobeBlocks b;
  // The lattice on multiples of kGlobeBlockPx from the frame's corner, rect widened down to it:
  // llvmpipe rasterises and shades blocks of 4 x 4 pixels at multiples of 4, and a block off
  // that lattice touches nine of them instead of four (orbit's per-pixel draw: +15 %).
  const int x0 = rect[0] / kGlobeBlockPx * kGlobeBlockPx, y0 = rect[1] / kGlobeBlockPx * kGlobeBlockPx;
  b.rect = {x0, y0, rect[2] + rect[0] - x0, rect[3] + rect[1] - y0};
  b.columns = (b.rect[2] + kGlobeBlockPx - 1) / kGlobeBlockPx;
  b.rows = (b.rect[3] + kGlobeBlockPx - 1) / kGlobeBlockPx;
  // The corners, shared between neighbouring blocks.
  const int cornerColumns = b.columns + 1;
  std::vector<CornerHit> corners(static_cast<std::size_t>(cornerColumns) * static_cast<std::size_t>(b.rows + 1));
  for (int j = 0; j <= b.rows; ++j)
    for (int i = 0; i <= b.columns; ++i) {
      const int x = x0 + std::min(i * kGlobeBlockPx, b.rect[2]), y = y0 + std::min(j * kGlobeBlockPx, b.rect[3]);
      corners[static_cast<std::size_t>(j) * static_cast<std::size_t>(cornerColumns) + static_cast<std::size_t>(i)] =
          cornerHit(view, 2.0 * x / width - 1.0, 2.0 * y / height - 1.0);
    }
  bendCorners(corners, cornerColumns, b.rows + 1, b.columns * kGlobeBlockPx == b.rect[2],
              b.rows * kGlobeBlockPx == b.rect[3]);
  // The ellipsoid's outline, a circle of r pixels (angular radius asin(b / |eye|) or more),
  // bulges by r (1 - cos(4 / r)) between two corners 8 pixels apart: 0.06 pixels from r = 128,
  // where a sample lies at least 0.125 pixels inside its block. (A sample that still hit would
  // be classed per pixel without the land's and the sea's tests: the surface part's count,
  // which with several samples a pixel is drawn over the per-pixel blocks and the fills only,
  // GlobeRenderer::drawPartOverBlocks: this margin keeps such a pixel from staying black.)
  const double pixelRad = 2.0 * std::tan(0.5 * view.verticalFovRad) / height;
  const bool missOk = std::asin(std::min(1.0, geo::kWgs84SemiMinorM / glm::length(view.positionEcef))) > 128.0 * pixelRad;
  // Space: the atmosphere's outline as round (outside it: the eye above the atmosphere), and
  // a block's diagonal (under 12 pixels) clear of the Sun's disc.
  const double r = sky != nullptr ? sky->bottomRadiusM + view.position.heightM : 0.0;
  const bool spaceOk = sky != nullptr && r > sky->topRadiusM && std::asin(sky->topRadiusM / r) > 128.0 * pixelRad;
  const double sunClearRad = sky != nullptr ? sky->sunAngularRadiusRad + 12.0 * pixelRad : 0.0;
  b.classes.resize(static_cast<std::size_t>(b.columns) * static_cast<std::size_t>(b.rows));
  for (int j = 0; j < b.rows; ++j)
    for (int i = 0; i < b.columns; ++i) {
      auto at = [&](int di, int dj) {
        return &corners[static_cast<std::size_t>(j + dj) * static_cast<std::size_t>(cornerColumns) + static_cast<std::size_t>(i + di)];
      };
      const std::array<const CornerHit*, 4> blockCorners{at(0, 0), at(1, 0), at(0, 1), at(1, 1)};
      GlobeBlockClass c = classifyBlock(blockCorners, mask, mips, openSea, missOk, pixelRad);
      if (c == GlobeBlockClass::Miss && spaceOk && cornersInSpace(blockCorners, view, *sky, sunClearRad))
        c = GlobeBlockClass::Space;
      b.classes[static_cast<std::size_t>(j) * static_cast<std::size_t>(b.columns) + static_cast<std::size_t>(i)] = c;
    }
  return b;
}

std::vector<float> GlobeBlocks::triangles(GlobeBlockClass c, int width, int height) const {
  std::vector<float> v;
  auto ndcX = [&](int x) { return static_cast<float>(2.0 * std::min(x, rect[0] + rect[2]) / width - 1.0); };
  auto ndcY = [&](int y) { return static_cast<float>(2.0 * std::min(y, rect[1] + rect[3]) / height - 1.0); };
  auto classAt = [&](int i, int j) {
    return classes[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i)];
  };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns;) {
      if (classAt(i, j) != c) {
        ++i;
        continue;
      }
      int end = i + 1;
      while (end < columns && classAt(end, j) == c) ++end;
      const float x0 = ndcX(rect[0] + i * kGlobeBlockPx), x1 = ndcX(rect[0] + end * kGlobeBlockPx);
      const float y0 = ndcY(rect[1] + j * kGlobeBlockPx), y1 = ndcY(rect[1] + (j + 1) * kGlobeBlockPx);
      v.insert(v.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
      i = end;
    }
  return v;
}

}  // namespace og::render
