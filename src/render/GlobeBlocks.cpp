#include "render/GlobeBlocks.hpp"

#include <algorithm>
#include <cmath>
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

// Whether every point of the block (its four corners' hull) lies in the open deep sea: within
// 0.9 of the clearance of the 1° cell under its mean normal (the per-pixel test's margin). Not
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

GlobeBlockClass classifyBlock(const std::array<const CornerHit*, 4>& corners, const data::LandMaskPyramid& pyramid,
                              const OpenSeaMap* openSea, bool missOk, double pixelRad) {
  int misses = 0;
  double minCos = 1.0;
  for (const CornerHit* c : corners) {
    misses += c->hit ? 0 : 1;
    minCos = std::min(minCos, c->hit ? c->cosIncidence : 0.0);
  }
  if (misses == 4 && missOk) return GlobeBlockClass::Miss;
  for (const CornerHit* c : corners)
    if (!c->hit || c->cosIncidence < kMinCosIncidence || std::abs(c->latDeg) > 88.0) return GlobeBlockClass::PerPixel;
  // The corners' box, longitudes unwrapped next to the first corner's.
  double latLo = 90.0, latHi = -90.0, lonLo = 1e9, lonHi = -1e9;
  for (const CornerHit* c : corners) {
    double lon = c->lonDeg;
    lon += lon - corners[0]->lonDeg > 180.0 ? -360.0 : (corners[0]->lonDeg - lon > 180.0 ? 360.0 : 0.0);
    latLo = std::min(latLo, c->latDeg);
    latHi = std::max(latHi, c->latDeg);
    lonLo = std::min(lonLo, lon);
    lonHi = std::max(lonHi, lon);
  }
  if (lonHi - lonLo > 30.0 || latHi - latLo > 30.0) return GlobeBlockClass::PerPixel;
  // Widened by a quarter each way (the footprint's edges bow between the corners) and by the
  // B-spline's reach: a point's fraction reads the 3 x 3 cells around its nearest centre, the
  // centre of the cell it lies in (the fine level's 3 x 3 fine cells lie in those cells too).
  const data::LandMask& mask = pyramid.mask();
  const glm::dvec2 margin = 0.25 * glm::dvec2(latHi - latLo, lonHi - lonLo);
  const glm::dvec2 lo = glm::dvec2(latLo, lonLo) - margin, hi = glm::dvec2(latHi, lonHi) + margin;
  data::LandMaskPyramid::Content content = boxContent(pyramid, lo, hi, mask.cellDeg(), false);
  // Where every pixel's footprint is under a fine cell (globe.frag: the fine level's weight is 1
  // up to one, with a tenth of margin), the fine cells alone decide, up to 8 times closer to
  // the coast.
  const double fineCellDeg = mask.cellDeg() / data::LandMask::kFinePerCell;
  double footprintDeg = 0.0;
  for (const CornerHit* c : corners)
    footprintDeg = std::max(footprintDeg, data::LandMask::coastFootprintDeg(c->distanceM, pixelRad, c->cosIncidence));
  if (content == data::LandMaskPyramid::Content::Both && mask.hasFineLevel() && footprintDeg < 0.9 * fineCellDeg &&
      hi.y - lo.y < 64.0 * fineCellDeg && hi.x - lo.x < 64.0 * fineCellDeg)
    content = boxContent(pyramid, lo, hi, fineCellDeg, true);
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
                                const GlobeSkyOutline* sky) {
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
  // The ellipsoid's outline, a circle of r pixels (angular radius asin(b / |eye|) or more),
  // bulges by r (1 - cos(4 / r)) between two corners 8 pixels apart: 0.06 pixels from r = 128,
  // where a sample lies at least 0.125 pixels inside its block. (A sample that still hit would
  // be classed per pixel without the land's and the sea's tests: the surface part's count.)
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
      GlobeBlockClass c = classifyBlock(blockCorners, mask, openSea, missOk, pixelRad);
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
