#version 450 core
// Terrain shading: Lambertian stand-in materials (terrain/material.glsl) lit by the Sun
// attenuated to the point's altitude and by the sky's irradiance (tilted by the slope), then
// aerial perspective along the eye-to-point path ending at the point's altitude (per vertex of
// the full grid, terrain/terrain.vert). Radiance in Sun-irradiance units, like the globe pass.
// The normal is the full grid's, interpolated from its vertices, tilted by the detail octaves
// finer than the grid resolves (terrain/detail.glsl), down to the pixel's footprint. A tile
// drawn from a coarser mesh (TERRAIN_COARSE) reads the full grid's vertices itself.
#include "common/constants.glsl"
#include "common/types.glsl"
#include "atmosphere/model.glsl"
#include "render/aerial.glsl"
#include "terrain/material.glsl"
#include "terrain/imagery.glsl"
#include "terrain/detail.glsl"
#include "terrain/shadow.glsl"
#include "terrain/landmask.glsl"
#ifdef TERRAIN_COARSE
#include "terrain/tile_aerial.glsl"
#include "terrain/tile_grid.glsl"
#endif

in vec3 vRelative;
in vec3 vNormal;
in vec4 vInfo;  // height m, latitude rad, longitude rad, detail amplitude m
#ifdef TERRAIN_COARSE
// Drawn from a coarser mesh (render/TerrainRenderer::tileStrideIndex): the fragment's place in
// the full grid, and 1 on a skirt's lowered edge (terrain.vert). Its normal, height, detail
// amplitude and aerial perspective (from the tile aerial buffer, which the coarser meshes
// need) are the full grid's there, as drawn from it; latitude and longitude are linear in the
// grid, so the coarser mesh interpolates them alike. Only its place on screen moves: less than
// TerrainRenderer::kStrideDeviationPx. (A skirt's fragments take the light of the edge above
// them, not of the lowered vertices': a skirt is seen, if at all, for a pixel at an edge.)
in vec3 vGridPlace;
#endif
#ifndef TERRAIN_COVERAGE
in vec3 vTransmittance;  // aerial perspective, per vertex (terrain/terrain.vert)
in vec3 vInscatter;
#endif
#include "render/outputs.glsl"
// Below the grid's ceiling tiles that may discard are drawn twice (TerrainRenderer::drawCovered):
// TERRAIN_COVERAGE makes only the discards and writes the depth of what survives them, then
// TERRAIN_AFTER_COVERAGE shades, with the depth test (equal) before the shader and no discards:
// llvmpipe runs a shader that may discard in full for every fragment, the sea floor's too,
// before its test. (A fragment of another draw at exactly the depth that survived is shaded
// too: 2 pixels, 5 levels, in 7 coastal views.)
#ifdef TERRAIN_AFTER_COVERAGE
layout(early_fragment_tests) in;
#endif
#if !defined(TERRAIN_LAND_ONLY) && !defined(TERRAIN_AFTER_COVERAGE)
#define TERRAIN_DISCARDS
#endif

uniform vec3 uSunDir;  // unit, ECEF axes
uniform int uSeaFromGlobe;  // 1 above the grid's ceiling: the globe pass draws the sea
uniform int uTileHasWater;  // 1 when a vertex of this tile is at or below sea level

// The detail's octaves (terrain::DetailOctaves): octave k has 2^k uDetailScale0 lattice cells
// per unit of the sphere and weight detailOctaveWeight(k) / uDetailNorm; the eye lies in lattice cell
// uDetailCell[k] at uDetailFrac[k] (split in double on the CPU).
const int MAX_DETAIL_OCTAVES = 24;
uniform int uDetailCount;   // octaves in the normals
uniform int uDetailFirst;   // the first octave this tile's vertex normals leave out
uniform float uDetailNorm;
uniform float uDetailScale0;
uniform ivec3 uDetailCell[MAX_DETAIL_OCTAVES];
uniform vec3 uDetailFrac[MAX_DETAIL_OCTAVES];
uniform float uEyeFootScale;  // |diag(1, 1, a²/b²) F| for the eye's foot point F, m

// Geodetic normal at a foot point minus the eye's, from the offset between the two foot
// points, with no absolute coordinates: n(F) = G F / |G F| with G = diag(1, 1, a²/b²), and
// G F = G F_eye + G r; with e = n(F_eye) and g = G r / |G F_eye|,
// n(F) - e = (g + e (1 - |e + g|)) / |e + g|, where 1 - |e + g| is formed from the small terms.
vec3 normalOffsetFromEye(vec3 footOffset) {
  vec3 g = footOffset * vec3(1.0, 1.0, (WGS84_A / WGS84_B) * (WGS84_A / WGS84_B)) / uEyeFootScale;
  vec3 e = uCamUp;
  float small = 2.0 * dot(e, g) + dot(g, g);
  float len = sqrt(1.0 + small);
  return (g - e * (small / (1.0 + len))) / len;
}

// Gradient (per unit of the sphere) of the detail octaves from uDetailFirst on, each faded out
// as its wavelength nears two pixels: shading detail without aliasing. `dUp`: the point's
// geodetic normal minus the eye's; `footprint`: how much dUp changes across a pixel.
vec3 pixelDetailGradient(vec3 dUp, float footprint) {
  vec3 grad = vec3(0.0);
  float scale = uDetailScale0 * exp2(float(uDetailFirst));
  for (int k = uDetailFirst; k < min(uDetailCount, MAX_DETAIL_OCTAVES); ++k) {
    float w = 1.0 - smoothstep(0.25, 0.5, footprint * scale);  // lattice cells per pixel
    if (w <= 0.0) break;
    vec3 q = uDetailFrac[k] + dUp * scale;
    vec3 c = floor(q);
    vec4 r = detailRidgedFiltered(uDetailCell[k] + ivec3(c), q - c, footprint * scale);
    grad += (w * detailOctaveWeight(k) / uDetailNorm * scale) * r.yzw;
    scale *= 2.0;
  }
  return grad;
}

// The finest imagery texel over (latitude, longitude) radians, radians: the base image's, or a
// user layer's where one's bounds hold the point (terrain/imagery.glsl's uniforms).
float imageryFinestTexelRad(vec2 latLon) {
  float texel = uImageryDayTexelRad;
  for (int i = 0; i < IMAGERY_LAYER_COUNT; ++i) {
    vec2 st = imageryBoxCoord(latLon, uImageryLayerBounds[i]);
    if (all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0))))
      texel = min(texel, uImageryLayerTexelRad);
  }
  return texel;
}

void main() {
  // Triangles of a tile's row at a pole collapse onto the pole; llvmpipe can still emit a
  // fragment for them with undefined (NaN) attributes. They cover nothing: drop them.
#ifdef TERRAIN_DISCARDS  // (not for tiles all above the sea, away from the poles: TerrainRenderer)
  if (any(isnan(vInfo)) || any(isnan(vRelative)) || any(isnan(vNormal))) discard;
#endif
  // The mesh's height here (where vRelative lies), and the grid's (the same but on a coarser mesh).
  float meshHeightM = vInfo.x;
#ifdef TERRAIN_COARSE
  TileGridTriangle gridTriangle = tileGridTriangle(vGridPlace.xy);
  TileGridSample grid = tileGridSample(gridTriangle, vGridPlace.z);
  vec3 vertexNormal = grid.normalHeight.xyz;
  float heightM = grid.normalHeight.w;
  float detailAmplitudeM = grid.detailAmplitudeM;
#else
  vec3 vertexNormal = vNormal;
  float heightM = meshHeightM;
  float detailAmplitudeM = vInfo.w;
#endif
  // From high up the globe pass's sea covers the bathymetry: leave it to it rather than to a
  // depth test a few kilometres deep at thousands of kilometres (which llvmpipe's multisample
  // depth interpolation does not resolve).
  // Below the grid's ceiling the sea pass draws the floor itself, through the water
  // (ocean/water_volume.glsl): drop the floor deeper than a metre, which the sea's chords
  // would otherwise let show through far away over shallow banks (issue 15).
  // Where the coastline mask decides the coast (terrain/landmask.glsl), it does so per pixel up
  // here: the mesh's zero crossing is straight between vertices, which on far tiles are
  // kilometres apart (a staircase of straight lines along the coast from 30 km). Tiles that are
  // land at every vertex skip it (a lake narrower than their vertex spacing does not show), and
  // so do those drawn over the globe's land class alone (TERRAIN_GLOBE_LAND).
  float lat = vInfo.y, lon = vInfo.z;
  vec3 up = vec3(cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat));
#ifndef TERRAIN_LAND_ONLY
  // The mask's coast as the pixel's footprint on the ground resolves it (the globe's and the
  // grid's too). Below the ceiling the mesh's zero crossing lies up to a vertex spacing off
  // it (heights jump at the mask's coast where the layer disagrees with it: a 15″ bay the 5′
  // layer calls land, a spit it calls sea), so land the mask holds stays drawn where the
  // mesh dips under the sea, else the grid's sea (which stops at the mask's coast) leaves a gap.
  vec3 viewDir = normalize(vRelative);
  float maskFootprintRad = coastFootprintRad(length(vRelative), max(length(dFdx(viewDir)), length(dFdy(viewDir))),
                                             -dot(up, viewDir));
  // Above the ceiling (the globe's sea) the mask decides every pixel of a tile with water (but
  // with TERRAIN_GLOBE_LAND, where the globe's classes decide); below it, the pixels of the
  // mesh more than a metre under the sea, tested where the view ray crosses sea level, as the
  // grid tests its surface (the mesh point lies |h| below it, up to a fine cell farther along
  // the ray at oblique views). One lookup for either case: llvmpipe runs both sides of an if
  // for every pixel.
  bool globeSea = uSeaFromGlobe == 1;
  bool maskCoast = uTileHasWater == 1 && landMaskOn();
  bool below = heightM < (globeSea ? 0.0 : -1.0);
#ifdef TERRAIN_GLOBE_LAND
  // Drawn only over the pixels the globe's classifying draw found land at all four samples
  // (the stencil: GlobeRenderer's frameLandLast_), which decides the coast up here: the globe's
  // own parts shade the coast's mixed pixels, anti-aliased, and the sea's.
  bool maskTest = false, atSeaLevel = true;
#else
  bool maskTest = maskCoast && (globeSea || below), atSeaLevel = maskTest;
#endif
#ifdef TERRAIN_DISCARDS
  if (below && !maskCoast) discard;
  vec2 maskLatLon = vec2(lat, lon);
  if (!globeSea && below) {
    vec3 toSea = vRelative * (meshHeightM / (uCamAltitude - meshHeightM));
    vec3 east = vec3(-sin(lon), cos(lon), 0.0);
    vec3 north = vec3(-sin(lat) * cos(lon), -sin(lat) * sin(lon), cos(lat));
    maskLatLon += vec2(dot(toSea, north), dot(toSea, east) / max(cos(lat), 1e-3)) / WGS84_A;
  }
  if (maskTest && landFraction(maskLatLon, maskFootprintRad) < 0.5) discard;
#endif
  if (atSeaLevel) {  // land: where the mesh dips under the sea it is taken at sea level
    heightM = max(heightM, 0.0);
    meshHeightM = max(meshHeightM, 0.0);
  }
#endif
#ifdef TERRAIN_COVERAGE  // the depth only (TerrainRenderer masks the colour writes)
  fragRadiance = vec4(0.0);
  fragAux = vec4(0.0);
#else
  // Triangles that collapse at a pole give no normal (zero or NaN): the vertical stands in.
  vec3 n = dot(vertexNormal, vertexNormal) > 1e-20 ? normalize(vertexNormal) : up;
  float t = length(vRelative);
  vec3 dir = vRelative / t;
  // Seen from below (a skirt or a back face at a grazing angle): light it like its surroundings.
  if (dot(n, dir) > 0.0) {
    vec3 m = n - dot(n, dir) * dir;  // zero when the face looks straight away from the eye
    n = dot(m, m) > 1e-12 ? normalize(m) : up;
  }
  vec3 nGeometric = n;
  // Tilt by the finer detail: its height gradient per metre along the surface, tangential.
  vec3 dUp = normalOffsetFromEye(vRelative - meshHeightM * up + uCamAltitude * uCamUp);
  float footprint = max(length(dFdx(dUp)), length(dFdy(dUp)));
#ifndef TERRAIN_NO_DETAIL  // (no pixel resolves an octave the vertex normals leave out: TerrainRenderer's variants)
  if (detailAmplitudeM > 0.0) {
    vec3 g = pixelDetailGradient(dUp, footprint) * (detailAmplitudeM / WGS84_A);
    n = normalize(n - (g - dot(g, n) * n));
  }
#endif
  float slope = 1.0 - clamp(dot(n, up), 0.0, 1.0);
  float hP = max(heightM, 0.0);
  vec3 skyIrr;
  vec3 sunIrr = sunAndSkyIrradiance(uAtmosphere, uAtmTransmittance, uAtmIrradiance,
                                    uAtmosphere.bottomRadius + hP, dot(up, uSunDir), skyIrr);
  float snowLineM = terrainSnowLineM(abs(lat) * (180.0 / PI));
  vec3 albedo = terrainAlbedo(heightM, slope, lat, snowLineM, footprint * WGS84_A);
  if (uImageryEnabled == 1 && heightM >= 0.0)
    albedo = terrainAlbedoOverImagery(imageryAlbedo(vec2(lat, lon), footprint), albedo, heightM, slope, snowLineM,
                                      footprint / imageryFinestTexelRad(vec2(lat, lon)));
  // Sky light on a tilted surface: the part of the sky dome it sees.
  float skyView = 0.5 + 0.5 * dot(n, up);
  float sunSeen = dot(n, uSunDir) > 0.0 ? sunVisibility(vRelative, nGeometric) : 0.0;
  vec3 surface = albedo / PI * (sunIrr * (max(dot(n, uSunDir), 0.0) * sunSeen) + skyIrr * skyView);
#ifndef TERRAIN_NO_NIGHT  // (no point in view, or on the tile, has the Sun down: TerrainRenderer's variants)
  if (heightM >= 0.0) surface += nightLightsRadiance(vec2(lat, lon), footprint, dot(up, uSunDir));
#endif
#if defined(TERRAIN_COARSE) && defined(TERRAIN_AERIAL_BUFFER)
  vec3 transmittance, inscatter;
  tileGridAerial(gridTriangle, transmittance, inscatter);
#else
  vec3 transmittance = vTransmittance, inscatter = vInscatter;
#endif
  fragRadiance = vec4(surface * transmittance + inscatter, 1.0);
  fragAux = vec4(0.0);
#endif
}
