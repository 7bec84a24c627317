#include "gl/ShaderContract.hpp"

#include <cstdio>
#include <numbers>

#include "geo/Wgs84.hpp"

namespace og::gl {
namespace {
std::string define(const char* name, double value) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s %.17g", name, value);
  return buffer;
}
std::string define(const char* name, unsigned value) { return std::string(name) + " " + std::to_string(value); }
}  // namespace

std::vector<std::string> contractDefines() {
  return {define("OG_PI", std::numbers::pi),
          define("OG_WGS84_A", geo::kWgs84SemiMajorM),
          define("OG_WGS84_B", geo::kWgs84SemiMinorM),
          define("OG_UNIT_ELEVATION", kUnitElevation),
          define("OG_UNIT_WIND", kUnitWind),
          define("OG_UNIT_ATM_TRANSMITTANCE", kUnitAtmTransmittance),
          define("OG_UNIT_ATM_SCATTERING", kUnitAtmScattering),
          define("OG_UNIT_ATM_SINGLE_MIE", kUnitAtmSingleMie),
          define("OG_UNIT_ATM_IRRADIANCE", kUnitAtmIrradiance),
          define("OG_UNIT_SKY_MAP", kUnitSkyMap),
          define("OG_UNIT_SKY_IRRADIANCE", kUnitSkyIrradiance),
          define("OG_UNIT_SKY_RADIAL_SUMS", kUnitSkyRadialSums),
          define("OG_UNIT_SKY_RADIAL_SUMS_LAYERS", kUnitSkyRadialSumsLayers),
          define("OG_UNIT_BUMP_MAP", kUnitBumpMap),
          define("OG_UNIT_FRESNEL_RAMP", kUnitFresnelRamp),
          define("OG_BLOCK_PATTERN_TABLE", kBlockPatternTable),
          define("OG_TERRAIN_AERIAL_BINDING", kTerrainAerialBinding),
          define("OG_TILE_VERTICES_BINDING", kTileVerticesBinding),
          define("OG_TILE_AERIAL_TILES_BINDING", kTileAerialTilesBinding),
          define("OG_TILE_AERIAL_LIST_BINDING", kTileAerialListBinding),
          define("OG_TILE_QUADS", kTerrainTileQuads),
          define("OG_SEA_CLASS_BITS", kSeaClassBits),
          define("OG_OPEN_SEA_CELLS_PER_DEG", kOpenSeaCellsPerDeg),
          define("OG_GLOBE_PIXELS_BINDING", kGlobePixelsBinding),
          define("OG_GLOBE_PIXELS_GROUP", kGlobePixelsGroup),
          define("OG_GLOBE_PIXELS_ROW", kGlobePixelsRow),
          define("OG_UNCOVERED_BLOCKS_BINDING", kUncoveredBlocksBinding),
          define("OG_UNCOVERED_TRIANGLES_BINDING", kUncoveredTrianglesBinding),
          define("OG_SEA_LATTICE_BLOCKS_BINDING", kSeaLatticeBlocksBinding),
          define("OG_UNIT_SHADOW_MAP", kUnitShadowMap),
          define("OG_UNIT_PATTERN_DISPLACEMENT", kUnitPatternDisplacement),
          define("OG_UNIT_PATTERN_SLOPES", kUnitPatternSlopes),
          define("OG_UNIT_IMAGERY_DAY", kUnitImageryDay),
          define("OG_UNIT_IMAGERY_NIGHT", kUnitImageryNight),
          define("OG_UNIT_IMAGERY_LAYERS", kUnitImageryLayers),
          define("OG_UNIT_IMAGERY_TILES", kUnitImageryTiles),
          define("OG_UNIT_LAND_MASK", kUnitLandMask),
          define("OG_UNIT_LAND_MASK_FINE", kUnitLandMaskFine),
          define("OG_UNIT_LAND_FRACTION", kUnitLandFraction),
          define("OG_UNIT_OPEN_SEA", kUnitOpenSea),
          define("OG_UNIT_SEA_LATTICE", kUnitSeaLattice),
          define("OG_UNIT_SEA_LATTICE_BLOCKS", kUnitSeaLatticeBlocks),
          define("OG_UNIT_SEA_STENCIL", kUnitSeaStencil),
          define("OG_UNIT_SEA_GRID_VERTICES", kUnitSeaGridVertices),
          define("OG_UNIT_SEA_GRID_INDICES", kUnitSeaGridIndices),
          define("OG_UNIT_SEA_GRID_TERMS", kUnitSeaGridTerms),
          define("OG_UNIT_SKY_LOW", kUnitSkyLow),
          define("OG_UNIT_AERIAL_TABLE", kUnitAerialTable),
          define("OG_UNIT_TERRAIN_AERIAL_TABLE", kUnitTerrainAerialTable),
          define("OG_UNIT_CAUSTIC_CURVATURE", kUnitCausticCurvature),
          define("OG_UNIT_SEA_SURFACE", kUnitSeaSurface),
          define("OG_UNIT_TONE_RADIANCE", kUnitToneRadiance),
          define("OG_UNIT_OVERLAY_TEXT", kUnitOverlayText)};
}

}  // namespace og::gl
