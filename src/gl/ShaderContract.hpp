#pragma once
// The contract between the C++ and the GLSL sides, named once here: shared constants (π, WGS84)
// and the texture units of the samplers the frame's passes share. gl::expandShader injects them
// into every shader as #defines (OG_PI, OG_WGS84_A, OG_WGS84_B, OG_UNIT_WIND, ...), so GLSL
// writes `layout(binding = OG_UNIT_WIND)` and C++ binds to gl::kUnitWind: a number written on one
// side only. (Image units of the compute passes are local to one shader and stay there.)
#include <string>
#include <vector>

namespace og::gl {

/// Texture units of the frame's samplers (GLSL: OG_UNIT_<NAME>).
enum TextureUnit : unsigned {
  kUnitElevation = 0,            ///< render/elevation.glsl uElevation
  kUnitWind = 1,                 ///< ocean/wind.glsl uWind (render/WindTextures)
  kUnitAtmTransmittance = 2,     ///< atmosphere/model.glsl
  kUnitAtmScattering = 3,
  kUnitAtmSingleMie = 4,
  kUnitAtmIrradiance = 5,
  kUnitSkyMap = 6,               ///< atmosphere/skymap.glsl
  kUnitSkyIrradiance = 7,
  kUnitBumpMap = 8,              ///< ocean/classic.frag
  kUnitFresnelRamp = 9,
  kUnitShadowMap = 11,           ///< terrain/shadow.glsl
  kUnitPatternDisplacement = 12,
  kUnitPatternSlopes = 13,
  kUnitImageryTiles = 14,        ///< terrain/imagery.glsl (render/ImageryTiles)
  kUnitImageryDay = 15,          ///< terrain/imagery.glsl (render/ImageryTextures)
  kUnitImageryNight = 16,
  kUnitImageryLayers = 17,
  kUnitLandMask = 18,            ///< terrain/landmask.glsl (render/LandMaskTexture)
  kUnitOpenSea = 19,             ///< render/globe.frag uOpenSea (render/OpenSeaMap)
  kUnitSkyRadialSums = 20,       ///< atmosphere/skymap.glsl SKY_RADIAL_SUMS, the frame layer's (render/SkyRadialSums)
  kUnitCausticCurvature = 21,    ///< ocean/water_volume.glsl uCausticCurvature (render/WaterVolume)
  kUnitLandMaskFine = 22,        ///< terrain/landmask.glsl uLandMaskFine (render/LandMaskTexture)
  kUnitSeaSurface = 23,          ///< ocean/sea_surface.glsl uSeaSurface (render/SeaSurfaceBuffer)
  kUnitSkyLow = 24,              ///< render/globe.frag uSkyLow (GlobeRenderer::drawSkyLow)
  kUnitAerialTable = 25,         ///< render/aerial.glsl uAerialTable (render/AerialTable, seaLevel)
  kUnitTerrainAerialTable = 26,  ///< render/aerial.glsl uTerrainAerialTable (render/AerialTable, terrain)
  kUnitSkyRadialSumsLayers = 27, ///< atmosphere/skymap.glsl SKY_RADIAL_SUMS, the Sun layers' (render/SkyRadialSums)
  kUnitLandFraction = 28,        ///< terrain/landmask.glsl uLandFraction (render/LandMaskTexture: data::LandFractionMips)
  kUnitSeaLattice = 29,          ///< render/sea_lattice.frag uLattice (render/SeaLattice)
  kUnitSeaLatticeBlocks = 30,    ///< render/sea_lattice.frag uBlockInterpolated
  kUnitSeaStencil = 31,          ///< ocean/ocean.frag OCEAN_COMPUTE uSeaStencil: the classes (OceanRenderer::drawDeferred)
  // The projected grid's vertex records as buffer textures (ocean/grid_vertex_buffer.glsl,
  // OceanRenderer::computeGridVertices), on units the sea's passes read nothing else from
  // (uSeaStencil and the globe's lattice are other passes'):
  kUnitSeaGridVertices = 31,     ///< uGridVertexTexels
  kUnitSeaGridTerms = 30,        ///< uGridRadianceTermsTexels (the forward draw of grown cells)
  kUnitSeaGridIndices = 30,      ///< ocean/sea_visibility.glsl uGridIndexTexels (frames without the terms)
  // Passes of their own, which bind nothing else, reuse unit 0:
  kUnitToneRadiance = 0,         ///< render/tonemap.frag uRadiance (the HDR target)
  kUnitOverlayText = 0,          ///< viewer/text.frag uText (the viewer's text overlay)
};

/// Binding points of the uniform blocks (GLSL: OG_BLOCK_<NAME>).
enum UniformBlockBinding : unsigned {
  kBlockPatternTable = 0,  ///< ocean/patterns.glsl PatternTable (render/OceanPatterns)
};

/// Binding points of shader storage blocks that several programs share (GLSL: OG_<NAME>); under 8,
/// the least GL 4.5 guarantees (render/OceanRenderer's own passes use 3-7, and 2 for the grid's
/// near-land flags, which GlobeRenderer binds again for its pixels, render/UncoveredPixels for
/// its blocks (with 3 for their triangles), TerrainRenderer::computeTileAerial for its tiles
/// (with 3 for its vertices) and render/SeaLattice for its points (with 3 for its blocks);
/// gl::runProbe's test probes bind 0 for their run: the terrain binds its buffer again at each
/// draw).
enum StorageBinding : unsigned {
  kTerrainAerialBinding = 0,  ///< terrain/tile_vertex.glsl TileAerial (TerrainRenderer::computeTileAerial)
  /// terrain/tile_grid.glsl TileVertices: a tile's vertex buffer (TERRAIN_COARSE), or the frame's
  /// tiles' vertices one after another (tile_aerial.comp)
  kTileVerticesBinding = 1,
  kGlobePixelsBinding = 2,         ///< render/globe_pixels.glsl GlobePixels (GlobeRenderer::shadeScatteredParts)
  kTileAerialTilesBinding = 2,     ///< terrain/tile_aerial.comp TileAerialTiles (TerrainRenderer::computeTileAerial)
  kUncoveredBlocksBinding = 2,     ///< render/uncovered_blocks.glsl UncoveredBlocks (render/UncoveredPixels)
  kUncoveredTrianglesBinding = 3,  ///< render/uncovered_blocks.comp UncoveredTriangles (render/UncoveredPixels)
  kTileAerialListBinding = 3,      ///< terrain/tile_aerial.comp TileAerialList (TerrainRenderer::computeTileAerial)
  kSeaLatticeBlocksBinding = 3,    ///< render/sea_lattice.comp SeaLatticeBlocks (render/SeaLattice)
};

/// Quads along a terrain tile's edge (terrain::kTileQuads, asserted by render/TerrainRenderer;
/// GLSL: OG_TILE_QUADS): terrain/tile_grid.glsl finds a vertex's place in the grid from it.
inline constexpr unsigned kTerrainTileQuads = 32;

/// The globe's listed pixels (render/globe_pixels.glsl, GlobeRenderer::shadeScatteredParts) and
/// the sea lattice's points and blocks (render/SeaLattice): a compute work group's
/// invocations, and the most groups a row of a dispatch (GLSL: OG_GLOBE_PIXELS_GROUP,
/// OG_GLOBE_PIXELS_ROW).
inline constexpr unsigned kGlobePixelsGroup = 64;
inline constexpr unsigned kGlobePixelsRow = 4096;

/// The bits of the deferred sea's surface buffer that hold a pixel's class where the driver
/// cannot export stencil values (the footprint's lowest three: ocean/sea_surface.glsl,
/// ocean/sea_class_stencil.frag; GLSL: OG_SEA_CLASS_BITS).
inline constexpr unsigned kSeaClassBits = 7;

/// Cells per degree of the open-sea map (render/OpenSeaMap::kCellsPerDeg; GLSL:
/// OG_OPEN_SEA_CELLS_PER_DEG): render/open_sea_map.glsl finds a point's texel from it.
inline constexpr unsigned kOpenSeaCellsPerDeg = 8;

/// The contract as "NAME value" #define bodies, in full double precision.
std::vector<std::string> contractDefines();

}  // namespace og::gl
