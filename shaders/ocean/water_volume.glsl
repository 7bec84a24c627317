// The water volume under the projected grid's sea, per pixel (seed 001, Baboud & Decoret 2006
// §3): the view ray refracted through the footprint's mean surface normal, the sea floor found
// by marching the elevation layer's heightfield along it (stopping at d_max, Eq. 6, where the
// water leaves nothing of the floor), the floor lit by the Sun refracted and focused by the
// waves (caustics) and shadowed by the terrain along its refracted path, plus the sky; the
// water column's absorption and in-scattering from ocean/water_optics.glsl. The result goes to
// gWater (terrain/shallow.glsl), which the lighting's refracted term reads (lighting.glsl).
// The water's K_d per RGB channel is Jerlov's (1976, Table XXVII) at 600, 550 and 450 nm
// (uWaterAttenuation, terrain/shallow.glsl; the C++ twin's ocean::jerlovWater).
//
// Needs (included first): SEA_IN (ocean/ocean.frag), ocean/patterns.glsl, ocean/brdf.glsl, ocean/lighting.glsl (which
// brings terrain/shallow.glsl and ocean/water_optics.glsl), render/elevation.glsl,
// terrain/shadow.glsl, common/types.glsl.
#include "terrain/detail.glsl"

// Sea-floor detail below the elevation layer (sand ripples, patches of rubble and weed):
// octaves of the terrain's gradient noise (terrain/detail.glsl) from FLOOR_LONGEST_M down,
// each faded out as its wavelength nears two pixels. The eye lies in lattice cell
// uFloorCell[k] at uFloorFrac[k] of octave k (split in double on the CPU: render/WaterVolume).
const int FLOOR_OCTAVES = 6;
uniform ivec3 uFloorCell[FLOOR_OCTAVES];
uniform vec3 uFloorFrac[FLOOR_OCTAVES];
uniform float uFloorScale0;        // octave 0's lattice cells per unit of the sphere (a / wavelength)
uniform float uFloorEyeFootScale;  // |diag(1, 1, a²/b²) F| for the eye's foot point F, m
uniform vec3 uFloorEyeUp;          // geodetic normal under the eye, ECEF axes
uniform float uFloorEyeHeightM;    // the eye's height above the ellipsoid, m
const float FLOOR_RELIEF_M = 0.12;     // height of octave 0's ripples, m (weight 0.6^k below)
const float FLOOR_ALBEDO_SPREAD = 0.45;  // relative albedo variation of the floor's patches
// Below this share of the floor in the pixel (transmission down and up x (1 - Fresnel)), its
// detail, caustics and shadows are not worth their cost: a plain floor stands in.
const float FLOOR_DETAIL_MIN_SHARE = 0.02;

// Geodetic normal at a foot point minus the eye's, from the offset between the two foot points
// (terrain.frag's normalOffsetFromEye, here with this pass's uniforms).
vec3 floorOffsetFromEye(vec3 footOffset) {
  vec3 g = footOffset * vec3(1.0, 1.0, (WGS84_A / WGS84_B) * (WGS84_A / WGS84_B)) / uFloorEyeFootScale;
  vec3 e = uFloorEyeUp;
  float small = 2.0 * dot(e, g) + dot(g, g);
  float len = sqrt(1.0 + small);
  return (g - e * (small / (1.0 + len))) / len;
}

// The floor's detail at a point (dUp: its geodetic normal minus the eye's) seen with a footprint
// of `footprintM`: (albedo factor - 1, height gradient per metre in ECEF axes).
vec4 floorDetail(vec3 dUp, float footprintM) {
  float scale = uFloorScale0;
  float value = 0.0;
  vec3 grad = vec3(0.0);
  for (int k = 0; k < FLOOR_OCTAVES; ++k) {
    float w = 1.0 - smoothstep(0.25, 0.5, footprintM * scale / WGS84_A);  // cells per pixel
    if (w <= 0.0) break;
    vec3 q = uFloorFrac[k] + dUp * scale;
    vec3 c = floor(q);
    vec4 r = detailNoise(uFloorCell[k] + ivec3(c), q - c);
    float weight = w * detailOctaveWeight(k);
    value += weight * r.x;
    grad += (weight * FLOOR_RELIEF_M * scale / WGS84_A) * r.yzw;
    scale *= 2.0;
  }
  return vec4(FLOOR_ALBEDO_SPREAD * value, grad);
}

// The caustics' curvature map (render/WaterVolume's CausticCurvature, ocean/caustic_curvature.comp):
// tr H of the CAUSTIC_PATTERNS finest patterns per texel (1/texel), mip-mapped.
layout(binding = OG_UNIT_CAUSTIC_CURVATURE) uniform sampler2DArray uCausticCurvature;

// Trace of the height's Hessian (1/m) of the sea surface at xy (frame axes) filtered over a
// footprint of `footprintM`, from the finest patterns only (the ones that focus light at these
// depths; longer waves focus far deeper): one lookup per pattern and wind bin.
float causticCurvature(vec2 xy, float footprintM, vec2 wind) {
  vec2 p = fieldPosition(xy);
  vec2 fieldTurn;
  WindBins wb = windBinsOf(wind.y, fieldTurn);
  float traceH = 0.0;
  for (int j = 0; j < CAUSTIC_PATTERNS; ++j) {
    int i = PATTERN_COUNT - CAUSTIC_PATTERNS + j;
    float lod = patternLod(footprintM, i);
    if (lod >= uPatternTopLod) break;
    float perM = patternTable(i, wind.x).y * uPatternFftSize / uPatternSizeM[i];
    for (int k = 0; k < PATTERN_BINS; ++k) {
      vec3 c = patternCoord(p, wb.bin[k], i);
      c.z = float((wb.bin[k] & 1) * CAUSTIC_PATTERNS + j);
      traceH += wb.weight[k] * perM * textureLod(uCausticCurvature, c, lod).x;
    }
  }
  return traceH * uPatternAmplitude;
}

// Caustics: the Sun's irradiance on the floor relative to a flat sea. A ray entering where the
// surface slope is s leaves the vertical towards the slope's rise by (1 - 1/n) s per metre of
// path, so the map from surface to floor a path z below is J = I + z (1 - 1/n) H (H the
// surface's height Hessian) and the irradiance 1 / det J ~ 1 - c, c = z (1 - 1/n) tr H
// (docs/coast.md, "Caustics"): crests focus, troughs spread. c is compressed to c / (1 + |c|), an
// odd function, so the gain keeps a mean of 1 over the floor (energy is conserved) and stays in
// (0, 2). tr H is filtered over the blur of the Sun's disc at that depth (0.53° in air, /n in
// water) or twice the pixel's footprint, whichever is larger: caustics sharpen with depth up to
// the waves' focal depth, blur beyond it, and average out with distance (no aliasing).
float causticGain(vec2 xy, float pathM, float footprintM, float blurM, vec2 wind) {
  float blur = max(max(2.0 * footprintM, blurM), pathM * (0.0093 / WATER_INDEX));
  float c = pathM * (1.0 - 1.0 / WATER_INDEX) * causticCurvature(xy, blur, wind);
  return 1.0 - c / (1.0 + abs(c));
}

// The terrain's shadow on the floor: the Sun seen from the point `rel` where its refracted
// ray to the floor entered the water (seed 001 §4.3), from the shadow maps (terrain/shadow.glsl)
// with one 2x2 hardware comparison instead of the surface's four (a 2x2-texel soft edge: the
// floor is seen through the moving surface, which blurs it more than that).
float floorSunVisibility(vec3 rel, vec3 n) {
  float visible = 1.0;
#ifndef SHADOWS_OFF
  for (int on = 0; on < uShadowOn; ++on) {
    int c = length(rel) < uShadowSplitM ? 0 : 1;
    vec4 s = uShadowMatrix[c] * vec4(rel + n * (1.5 * uShadowTexelM[c]), 1.0);
    bool inside = all(greaterThanEqual(s.xy, uShadowCropUv[c].xy)) && all(lessThanEqual(s.xy, uShadowCropUv[c].zw)) && s.z > 0.0;
    visible = inside ? texture(uShadowMap, vec4(s.xy, float(c), min(s.z, 1.0))) : 1.0;  // as terrain/shadow.glsl
  }
#endif
  return visible;
}

// Height of the layer's floor (m, negative below sea level) along a ray leaving the surface at
// (latitude, longitude) `latLon` with horizontal direction `east`/`north` components per metre,
// its coast as the pixel's footprint `footprintRad` (radians of arc) resolves it (a bay only
// the fine level holds keeps its depth: the 2′ level puts land there, a floor at the surface).
float floorHeightAlong(vec2 latLon, vec2 horizontal, float s, float footprintRad) {
  vec2 d = s * horizontal / WGS84_A;
  return elevationAt(latLon + vec2(d.y, d.x / max(cos(latLon.x), 1e-3)), footprintRad);
}

// The secant step's root between (sA, gapA) and (sB, gapB) along the ray, in [0, sMax];
// sMax when the gap does not close (the floor falls away faster than the ray goes down).
float secantRoot(float sA, float gapA, float sB, float gapB, float sMax) {
  float slope = (gapB - gapA) / (sB - sA);
  return slope < -1e-6 ? clamp(sB - gapB / slope, 0.0, sMax) : sMax;
}

// Where a ray leaving the surface `gap0` m above the floor, going down by `down` (< 0) and
// horizontally across a floor whose depth grows by `depthGain` per metre of path, meets that
// plane, in [0, sMax]; sMax when it does not (the floor falls away as fast as the ray goes down).
float floorPlaneRoot(float gap0, float down, float depthGain, float sMax) {
  float closing = -down - depthGain;  // m of gap closed per metre along the ray
  return closing > 1e-6 ? min(gap0 / closing, sMax) : sMax;
}

// Depth of the floor under the grid's vertices, m (ocean/water_volume_vertex.glsl), linear
// across a cell of a few pixels: the search's first guess.
#ifndef OCEAN_NO_WATER_VOLUME
SEA_IN float vFloorDepthM;
// Above 0 where a vertex of the triangle has the land mask's fine level moving the floor (its
// coast differs from the 2′ one's there): only those pixels need the fine level's lookups in
// the search below (a GPU skips them elsewhere; llvmpipe runs them masked for every pixel).
SEA_IN float vFloorFine;
#ifndef OCEAN_SIMPLE_SKY
SEA_IN vec3 vWaterSunE;  // the Sun's and the sky's irradiance at sea level
SEA_IN vec3 vWaterSkyE;
#endif
#else
const float vFloorDepthM = 1e4;
const float vFloorFine = 0.0;
#endif

// Prepares gWater for the sea pixel at camera-relative `rel` (to the eye `v`, mean normal `n`,
// geodetic vertical `up`, at `latLon`, `oceanXY` in the ocean frame whose rows are
// `ecefToOcean`), pixel footprint `footprintM` (m), local wind (speed, azimuth), the floor's
// depth gradient in the pixel's triangle (floorDepthSlope) and how the pixel's slopes spread
// (the mean slope's change to the next pixel, the unresolved slopes' standard deviation).
void prepareWaterVolume(vec3 rel, vec3 v, vec3 n, vec3 up, vec2 latLon, vec2 oceanXY,
                        mat3 ecefToOcean, float footprintM, vec2 wind, vec3 sunE, vec2 floorSlope,
                        vec2 slopeSpread) {
  vec3 k = uWaterAttenuation;
  float dMax = waterMaxPathM(k, WATER_EPSILON);
  float gap0 = max(vFloorDepthM, 0.0);  // ray height minus floor height at the surface (>= 0)
  if (uElevationSize.x <= 0.0 || gap0 > dMax) {
    gWater = WaterVolume(true, uSeaColor);  // deep: the floor contributes less than epsilon
    return;
  }
  // The view ray refracted into the water, kept going down (grazing views of a tilted facet).
  vec3 t = refract(-v, n, 1.0 / WATER_INDEX);
  float down = min(dot(t, up), -0.05);
  t = normalize(t - (dot(t, up) - down) * up);
  down = dot(t, up);
  mat3 frame = localFrame(up);
  vec2 horizontal = vec2(dot(t, frame[0]), dot(t, frame[1]));
  // The floor along the ray (seed 001 §3.2's search). Where the land mask's fine level does not
  // move the floor, the layer is bilinear over kilometres and the grid's triangle, a few pixels
  // wide, holds it as a plane: the ray meets that plane (no lookup). Where the fine coast moves
  // it, a secant step through the layer's heights at the pixel's surface point and where a flat
  // floor at that depth would be (exact on a plane).
  float sHit = floorPlaneRoot(gap0, down, dot(floorSlope, (ecefToOcean * t).xy), dMax);
  float gapHit = 0.0;
  for (int fine = 0; fine < (vFloorFine > 0.0 ? 1 : 0); ++fine) {  // a GPU skips it; llvmpipe runs it, masked
    // From the pixel's own floor under its surface point, at its footprint, then one secant
    // step (exact on a plane). It started from the vertices' floor, which at the fine level's
    // points can be land where the pixel (kept as sea by the coast test at its footprint) is
    // not: a cell of a few hundred metres took the floor at the surface (a bright square of
    // sand off Ceuta from 1 km), which the two secant steps from there never left.
    float footprintRad = footprintM / WGS84_A;
    float gapStart = -floorHeightAlong(latLon, horizontal, 0.0, footprintRad);  // <= 0: at the surface
    float s1 = min(max(gapStart, 0.0) / -down, dMax);
    float gap1 = s1 * down - floorHeightAlong(latLon, horizontal, s1, footprintRad);
    sHit = s1 > 1e-3 ? secantRoot(0.0, gapStart, s1, gap1, dMax) : 0.0;  // 0: floor at the surface
    gapHit = sHit >= dMax ? gap1 : 0.0;
  }
  if (sHit >= dMax && gapHit >= 0.0) {
    gWater = WaterVolume(true, uSeaColor);  // no floor within d_max
    return;
  }
  float depthM = max(-(sHit * down), 0.0);
  vec3 floorRel = rel + sHit * t;
  // The Sun refracted through the mean surface, its path down to the floor, and the point
  // where it entered the water: caustics and the terrain's (refracted) shadows are taken there.
  float muS = dot(sunE, up);
  vec3 sunWater = refract(-sunE, up, 1.0 / WATER_INDEX);  // going down
  float cosSunWater = waterRefractedCosine(max(muS, 0.0));
  float sunPathM = depthM / max(cosSunWater, 0.05);
  vec3 albedo = uFloorAlbedo;
  vec3 nFloor = up;
  float sunFactor = 1.0;
  vec3 seen = waterTransmittance(k, sunPathM + sHit) * (1.0 - fresnelSchlick(max(dot(n, v), 0.0)));
  if (max(seen.x, max(seen.y, seen.z)) > FLOOR_DETAIL_MIN_SHARE) {
    // The floor's detail, filtered by the pixel's footprint there (refraction magnifies little).
    vec3 dUp = floorOffsetFromEye(floorRel + depthM * up + uFloorEyeHeightM * uFloorEyeUp);
    // The pixel's footprint on the floor: the surface's, carried down the ray, plus how far the
    // floor point moves to the next pixel as the resolved slopes turn the refracted ray ((1 -
    // 1/n) of a slope change per unit of path): seen through 5 m of water the finest waves move
    // it by centimetres a pixel, and caustics looked up finer than that sparkled pixel by
    // pixel. The unresolved slopes within the pixel spread its rays over the floor too: a blur.
    float perSlopeM = sHit * (1.0 - 1.0 / WATER_INDEX);
    float floorFootprintM = footprintM * (1.0 + sHit / max(length(rel), 1.0)) + perSlopeM * slopeSpread.x;
    float floorBlurM = perSlopeM * slopeSpread.y;
    vec4 detail = floorDetail(dUp, floorFootprintM + 0.5 * floorBlurM);
    vec3 g = detail.yzw - dot(detail.yzw, up) * up;
    nFloor = normalize(up - g);
    albedo *= clamp(1.0 + detail.x, 0.3, 1.7);
    vec3 entryRel = floorRel - sunPathM * sunWater;
    vec2 entryXY = oceanXY + (ecefToOcean * (entryRel - rel)).xy;
    sunFactor = floorSunVisibility(entryRel, up) * causticGain(entryXY, sunPathM, floorFootprintM, floorBlurM, wind) *
                max(dot(nFloor, -sunWater), 0.0) / max(cosSunWater, 0.05);
  }
#if defined(OCEAN_SIMPLE_SKY) || defined(OCEAN_NO_WATER_VOLUME)
  float sunZenith = acos(clamp(muS, -1.0, 1.0));
  vec3 eSun = sunIrradiance(sunZenith), eSky = skyIrradiance(sunZenith);
#else
  vec3 eSun = vWaterSunE, eSky = vWaterSkyE;  // per vertex (ocean/water_volume_vertex.glsl)
#endif
  vec3 sunBelow = eSun * max(muS, 0.0) * (1.0 - fresnelSchlick(max(muS, 0.0)));
  vec3 skyBelow = eSky * (1.0 - SKY_FRESNEL_MEAN) * (0.5 + 0.5 * dot(nFloor, up));
  vec3 floorIrr = floorIrradiance(k, depthM, cosSunWater, sunBelow, sunFactor, skyBelow);
  // Per unit of the irradiance the lighting multiplies by (lighting.glsl's seaRefracted).
  vec3 surfaceIrr = eSun * gSeaSunVisibility * max(muS, 0.0) + eSky;
  vec3 radiance = waterColumnRadiance(k, uSeaColor, albedo, floorIrr, depthM, sHit, surfaceIrr);
  gWater = WaterVolume(true, radiance / max(surfaceIrr, vec3(1e-6)));
}
