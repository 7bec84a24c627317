#pragma once
// The globe's classifying draw above the grid's ceiling by blocks of pixels (GlobeRenderer,
// render/globe.frag's GLOBE_PART_CLASSIFY). Per pixel that draw traces four rays and tests each
// sample against the land mask (a fifth to half of the globe pass on llvmpipe); most pixels lie
// in blocks that are wholly land or wholly sea, which the CPU can tell for a whole block from
// its corners and the mask's pyramid (data::LandMaskPyramid). Those blocks get their class by a
// draw that only writes the depth; the per-pixel draw covers the rest (coasts, the limb, the
// sky, grazing views).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "data/LandFractionMips.hpp"
#include "data/LandMaskPyramid.hpp"
#include "geo/Camera.hpp"
#include "render/OpenSeaMap.hpp"

namespace og::render {

/// A block's side, pixels.
inline constexpr int kGlobeBlockPx = 8;

/// What a block's every pixel is, as the per-pixel classifying draw would class it: PerPixel
/// where the CPU cannot tell (a coast, the limb, a grazing view), else land, sea, or open deep
/// sea (render/OpenSeaMap) for all four samples of every pixel; Miss where its corners all miss
/// the ellipsoid (the sky, space: classed per pixel, but without the land's and the sea's
/// tests, which no sample there needs); Space where besides they all miss the atmosphere and
/// the Sun's disc (globe.frag's count 0 at every sample: not drawn at all).
enum class GlobeBlockClass : std::uint8_t { PerPixel, Land, Sea, OpenSea, Miss, Space };
inline constexpr std::size_t kGlobeBlockClasses = 6;

/// What tells space from the sky (render/globe.frag's skyOf): the atmosphere's sphere of radius
/// topRadiusM around the centre bottomRadiusM + the eye's height below the eye, and the Sun's
/// disc.
struct GlobeSkyOutline {
  double bottomRadiusM = 0.0, topRadiusM = 0.0;
  glm::dvec3 sunDirection{0.0, 0.0, 1.0};  ///< unit, ECEF axes
  double sunAngularRadiusRad = 0.0;
};

struct GlobeBlocks {
  /// Pixels covered: x, y (lower-left origin), width, height; the rect asked for, its lower-left
  /// corner moved down to multiples of kGlobeBlockPx.
  std::array<int, 4> rect{0, 0, 0, 0};
  int columns = 0, rows = 0;            ///< blocks across rect (the last ones may be partial)
  std::vector<GlobeBlockClass> classes;  ///< row-major from rect's lower-left block

  /// Triangles (x, y in NDC, 6 vertices a quad) over the blocks of class c, a row's runs of
  /// neighbouring blocks merged, for a frame of width × height pixels.
  [[nodiscard]] std::vector<float> triangles(GlobeBlockClass c, int width, int height) const;
};

/// Classes the blocks of kGlobeBlockPx² pixels of `rect` (x, y, width, height; lower-left
/// origin, within the frame) in a frame of width × height pixels seen by `view`, on a lattice
/// of multiples of kGlobeBlockPx from the frame's corner (GlobeBlocks::rect). A block is land or sea when all
/// its corners hit the ellipsoid at a cosine of incidence of at least kMinCosIncidence and the
/// mask's cells within reach of its footprint (its corners' latitude-longitude box, widened by
/// a quarter and by the B-spline's reach of a cell) are all that class, none refined; open
/// sea when, besides, its corners' cosine is at least kMinCosIncidenceOpenSea (the per-pixel
/// test's 0.2 at the pixel centre, with a margin) and they lie within 0.9 of `openSea`'s
/// clearance of its centre's cell (nullptr: none is). Miss where the ellipsoid's outline
/// is too round to bulge between two corners onto a sample (a radius over 128 pixels).
/// With `sky`, Miss blocks whose corners all lie in space (outside the atmosphere's outline,
/// itself over 128 pixels in radius, and more than the Sun's radius and a block's diagonal from
/// the Sun) are Space. With `mips` (the land fraction's pyramid, as the GPU has it uploaded),
/// blocks whose pixels' footprints span more than a 2′ cell are land or sea where every
/// lookup the pyramid's blend there can make is (data::LandFractionMips::boxContent).
GlobeBlocks classifyGlobeBlocks(const geo::CameraView& view, int width, int height, const std::array<int, 4>& rect,
                                const data::LandMaskPyramid& mask, const OpenSeaMap* openSea,
                                const GlobeSkyOutline* sky = nullptr, const data::LandFractionMips* mips = nullptr);
inline constexpr double kMinCosIncidence = 0.1;
inline constexpr double kMinCosIncidenceOpenSea = 0.25;

}  // namespace og::render
