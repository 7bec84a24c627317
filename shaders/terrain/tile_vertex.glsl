// A terrain tile's vertex as terrain/terrain.vert places it, and the aerial perspective of its
// path from the eye: shared with terrain/tile_aerial.comp, which computes that light for the
// vertices of the frame's tiles the eye may see on every core (llvmpipe runs a draw's vertex
// shaders on one thread; render/TerrainRenderer's tile aerial buffer).
// Needs (included first): common/constants.glsl, atmosphere/model.glsl, render/aerial.glsl.

uniform vec3 uTileOffset;  // tile centre - eye, m
// The parent's screen-space error over the limit at 1 m: (parent spacing) x (pixels per
// radian) / (limit in pixels); 0 for tiles that do not morph (forced levels, no parent drawn).
uniform float uMorphScale;

// Geomorphing (as in CDLOD): a tile is chosen once its parent's vertex spacing exceeds the
// screen-space limit at the parent's nearest point, so at that moment its vertices morph
// fully onto the parent's mesh (no pop), and they reach their own positions as the parent's
// spacing there grows to twice the limit, when the tile itself would split.
// position: m from the tile centre; info: height m, latitude rad, longitude rad, detail
// amplitude m; morph: the parent mesh's point minus the vertex, m (terrain::TileVertex).
// Returns the camera-relative position (m, ECEF axes); heightM: the morphed height, m (precise:
// terrain.vert's clip distance from it must come out alike in every program of a tile).
// morphedTileVertexOf: of a tile whose centre minus the eye is tileOffset (m) and whose morph
// scale is morphScale (uTileOffset's and uMorphScale's values).
vec3 morphedTileVertexOf(vec3 tileOffset, float morphScale, vec3 position, vec4 info, vec3 morph,
                         out precise float heightM) {
  vec3 relative = tileOffset + position;
  float m = morphScale > 0.0 ? clamp(2.0 - morphScale / max(length(relative), 1e-3), 0.0, 1.0) : 0.0;
  vec3 up = vec3(cos(info.y) * cos(info.z), cos(info.y) * sin(info.z), sin(info.y));
  heightM = info.x + m * dot(morph, up);
  return relative + m * morph;
}
vec3 morphedTileVertex(vec3 position, vec4 info, vec3 morph, out precise float heightM) {
  return morphedTileVertexOf(uTileOffset, uMorphScale, position, info, morph, heightM);
}

#ifndef TERRAIN_DEPTH_ONLY
uniform vec3 uSunDir;  // unit, ECEF axes

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

// The aerial perspective of the path from the eye to a camera-relative point `relative` at
// height heightM (m; below sea level taken at it).
void tileVertexAerial(vec3 relative, float heightM, out vec3 transmittance, out vec3 inscatter) {
  float t = max(length(relative), 1e-3);
  aerialToAltitude(relative / t, t, max(heightM, 0.0), transmittance, inscatter);
}

#include "terrain/tile_aerial.glsl"
#endif
