#version 450 core
// Terrain tiles: positions relative to the tile centre plus the tile centre relative to the
// camera (computed in double on the CPU), so nothing on the GPU is in world coordinates.
// Geomorphing (as in CDLOD): a tile is chosen once its parent's vertex spacing exceeds the
// screen-space limit at the parent's nearest point, so at that moment its vertices morph
// fully onto the parent's mesh (no pop), and they reach their own positions as the parent's
// spacing there grows to twice the limit, when the tile itself would split.
// The aerial perspective is evaluated here, per vertex: it is smooth over a triangle of a few
// pixels and was over half the terrain pass's cost per pixel (docs/performance.md); up to 500
// km from this frame's table (TERRAIN_AERIAL_TABLE). Not in the
// shadow maps' depth-only program (TERRAIN_DEPTH_ONLY).
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"

layout(location = 0) in vec3 aPosition;  // m, relative to the tile centre, ECEF axes
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aInfo;      // height m, latitude rad, longitude rad, detail amplitude m
layout(location = 3) in vec3 aMorph;     // the parent mesh's point minus this vertex, m

uniform mat4 uViewProjection;  // for camera-relative ECEF positions
uniform vec3 uTileOffset;      // tile centre - eye, m
// The parent's screen-space error over the limit at 1 m: (parent spacing) x (pixels per
// radian) / (limit in pixels); 0 for tiles that do not morph (forced levels, no parent drawn).
uniform float uMorphScale;
uniform float uFloorClipM;     // m; 0: none (see main)
uniform float uFloorClipFarM;  // m

out vec3 vRelative;
out vec3 vNormal;
out vec4 vInfo;
// The same in every program (TERRAIN_DEPTH_ONLY too): the terrain's second draw of a tile
// tests its depth for equality with the first's (TerrainRenderer::drawCovered).
invariant gl_Position;
#ifndef TERRAIN_DEPTH_ONLY
uniform vec3 uSunDir;  // unit, ECEF axes
out vec3 vTransmittance;  // of the eye-to-vertex path
out vec3 vInscatter;      // light scattered towards the eye along it (Sun-irradiance units)

// Aerial perspective to a point at altitude hP (the tables' sphere, as in globe.frag): the
// path's zenith cosine is the one joining the eye's radius to R + hP over distance t; at or
// below sea level the globe's convention (render/aerial.glsl).
void aerialToAltitude(vec3 dir, float t, float hP, out vec3 transmittance, out vec3 inscatter) {
#ifdef TERRAIN_AERIAL_TABLE  // this frame's table (render/aerial.glsl, render/AerialTable)
  aerialToAltitudeFromTable(t, hP, dot(dir, uSunDir), transmittance, inscatter);
#else
  if (hP <= 0.0) {
    aerialPerspective(dir, t, uSunDir, transmittance, inscatter);
    return;
  }
  float R = uAtmosphere.bottomRadius;
  float r = R + uCamAltitude;
  float rP = R + hP;
  float d = max(t, 1e-3);
  float mu = clamp(((hP - uCamAltitude) * (rP + r) - d * d) / (2.0 * r * d), -1.0, 1.0);  // rP² - r² without cancelling
  inscatter = skyRadianceToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie, r, mu,
                                 dot(uSunDir, uCamUp), dot(dir, uSunDir), d, transmittance);
#endif
}
#endif

void main() {
  vec3 relative = uTileOffset + aPosition;
  float m = uMorphScale > 0.0 ? clamp(2.0 - uMorphScale / max(length(relative), 1e-3), 0.0, 1.0) : 0.0;
  vec3 up = vec3(cos(aInfo.y) * cos(aInfo.z), cos(aInfo.y) * sin(aInfo.z), sin(aInfo.y));
  vRelative = relative + m * aMorph;
  vNormal = aNormal;
  vInfo = vec4(aInfo.x + m * dot(aMorph, up), aInfo.yzw);
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
#ifdef TERRAIN_SHADOW_CASTER
  // Ground below sea level casts no shadow (terrain/shadow_depth.frag): the clipper cuts it
  // off where the interpolated height crosses 0, as a discard would per fragment, so the
  // maps' fragments need no shader (llvmpipe then writes their depth without running one).
  gl_ClipDistance[0] = vInfo.x;
#endif
#ifndef TERRAIN_DEPTH_ONLY
  float t = max(length(vRelative), 1e-3);
  aerialToAltitude(vRelative / t, t, max(vInfo.x, 0.0), vTransmittance, vInscatter);
#endif
}
