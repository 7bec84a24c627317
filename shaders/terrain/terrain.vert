#version 450 core
// Terrain tiles: positions relative to the tile centre plus the tile centre relative to the
// camera (computed in double on the CPU), so nothing on the GPU is in world coordinates.
// The geomorph and the aerial perspective are terrain/tile_vertex.glsl's. The aerial perspective
// is per vertex: it is smooth over a triangle of a few pixels and was over half the terrain
// pass's cost per pixel (docs/performance.md); up to 500 km from this frame's table
// (TERRAIN_AERIAL_TABLE). With TERRAIN_AERIAL_BUFFER it is read from the frame's tile aerial
// buffer, which terrain/tile_aerial.comp filled on every core. Not in the shadow maps'
// depth-only program (TERRAIN_DEPTH_ONLY).
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/tile_vertex.glsl"
#ifdef TERRAIN_COARSE
#include "terrain/tile_grid.glsl"
#endif

layout(location = 0) in vec3 aPosition;  // m, relative to the tile centre, ECEF axes
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aInfo;      // height m, latitude rad, longitude rad, detail amplitude m
layout(location = 3) in vec3 aMorph;     // the parent mesh's point minus this vertex, m

uniform mat4 uViewProjection;  // for camera-relative ECEF positions
uniform float uFloorClipM;     // m; 0: none (see main)
uniform float uFloorClipFarM;  // m
// The rays under the sea's lowest surface (terrain::seaHorizonCone, whose seaHorizonClip this
// computes): unit axis from the eye (ECEF axes), and (cos, sin) of the half angle and the cap's
// distance along the axis, m.
uniform vec3 uSeaHorizonAxis;
uniform vec3 uSeaHorizonCone;

out vec3 vRelative;
out vec3 vNormal;
out vec4 vInfo;
// The same in every program (TERRAIN_DEPTH_ONLY too): the terrain's second draw of a tile
// tests its depth for equality with the first's (TerrainRenderer::drawCovered).
invariant gl_Position;
#ifdef TERRAIN_COARSE
// A coarser mesh's vertex (every 2nd of the grid): its place in the full grid, and 1 on a
// skirt's lowered edge (terrain/tile_grid.glsl), from which terrain.frag reads the full grid.
out vec3 vGridPlace;
#endif
#ifndef TERRAIN_DEPTH_ONLY
out vec3 vTransmittance;  // of the eye-to-vertex path
out vec3 vInscatter;      // light scattered towards the eye along it (Sun-irradiance units)
#endif

void main() {
  precise float heightM;
  vRelative = morphedTileVertex(aPosition, aInfo, aMorph, heightM);
  vNormal = aNormal;
  vInfo = vec4(heightM, aInfo.yzw);
  gl_Position = uViewProjection * vec4(vRelative, 1.0);
#if !defined(TERRAIN_SHADOW_CASTER) && !defined(TERRAIN_LAND_ONLY)
  // Below the grid's ceiling terrain.frag discards the floor deeper than a metre but where the
  // land mask holds land at the view ray's sea crossing, ρ a / (a - h) across the eye's
  // vertical for a point ρ across it, h high, the eye a high. Within uFloorClipM = L of the
  // eye the mask holds none at the level the test reads out to uFloorClipFarM from the eye
  // (TerrainRenderer::floorClip): the clipper cuts off the floor whose crossing lies there,
  // before any fragment (enabled only then). Its distance is a ρ - L (a - h), (a - h) times the
  // crossing's beyond L: ρ and the distance are convex, so between vertices their
  // interpolation is never below a kept fragment's own.
  // Precise: the coverage and the shading programs of a tile (TerrainRenderer::drawCovered)
  // must clip alike for their depths to match.
  precise float across = length(vRelative - dot(vRelative, uCamUp) * uCamUp);
  precise float floorClip = max(max(vInfo.x + 1.0, length(vRelative) - uFloorClipFarM),
                                uCamAltitude * across - uFloorClipM * (uCamAltitude - vInfo.x));
  gl_ClipDistance[0] = floorClip;
#endif
#ifndef TERRAIN_SHADOW_CASTER
  // Beyond the sea's horizon (from near the sea, most of the far coasts' hills): the clipper
  // cuts off what the sea or the land before it hides, before any fragment (enabled below the
  // grid's ceiling where the land mask decides the coast, for the tiles it may cut:
  // TerrainRenderer::drawTileGroup). The function is convex, so between vertices its
  // interpolation is never below a kept point's own. Most of what it cuts is the sea floor,
  // which terrain.frag would discard after its whole shader. (The floor it keeps as land
  // where the mask holds land at the ray's sea-level crossing, a spit the layer sinks, is
  // cut too where that crossing lies before the cone and the floor point beyond it: the
  // globe's land shows there instead. Keeping all of the floor lost the gain.) Precise, as
  // the floor's clip.
  precise float horizonAlong = dot(vRelative, uSeaHorizonAxis);
  precise float horizonAcross = length(vRelative - horizonAlong * uSeaHorizonAxis);
  precise float horizonClip = max(horizonAcross * uSeaHorizonCone.x - horizonAlong * uSeaHorizonCone.y,
                                  uSeaHorizonCone.z - horizonAlong);
  gl_ClipDistance[1] = horizonClip;
#endif
#ifdef TERRAIN_SHADOW_CASTER
  // Ground below sea level casts no shadow (terrain/shadow_depth.frag): the clipper cuts it
  // off where the interpolated height crosses 0, as a discard would per fragment, so the
  // maps' fragments need no shader (llvmpipe then writes their depth without running one).
  gl_ClipDistance[0] = vInfo.x;
#endif
#ifdef TERRAIN_COARSE
  vGridPlace = tileGridPlace(gl_VertexID);
#endif
#if defined(TERRAIN_AERIAL_BUFFER) && !defined(TERRAIN_DEPTH_ONLY)
  vTransmittance = tileAerial[tileAerialSlot(gl_VertexID)].rgb;
  vInscatter = tileAerial[tileAerialSlot(gl_VertexID) + 1].rgb;
#elif !defined(TERRAIN_DEPTH_ONLY)
  tileVertexAerial(vRelative, vInfo.x, vTransmittance, vInscatter);
#endif
}
