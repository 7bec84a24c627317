// Shallow water (Baboud & Decoret 2006, seed 001 §4.1): light seen through the sea is the deep
// water's upwelling plus the sea floor, both through the water column's absorption and
// in-scattering (ocean/water_optics.glsl, the C++ twin's physics), the floor's depth from the
// elevation layer's bathymetry. Hook for ocean/lighting.glsl's refracted term, shared by the
// globe's sea (orbit: prepareWaterColumn, a vertical column under the point) and the projected
// grid (ocean/water_volume.glsl: the refracted ray marched to the floor per pixel), so
// shelves, banks and coasts read the same from orbit and up close.
#include "geo/ellipsoid.glsl"
#include "render/elevation.glsl"
#include "ocean/water_optics.glsl"

// Diffuse attenuation K_d, 1/m, per RGB channel at 600, 550 and 450 nm (Jerlov 1976, Table
// XXVII; ocean::jerlovWater: type IB by default, 0.245, 0.072, 0.036).
uniform vec3 uWaterAttenuation;
uniform vec3 uFloorAlbedo;       // the sea floor's reflectance (ocean::kCoralSandAlbedo)
// The march's epsilon (seed 001 Eq. 6; ocean::kWaterEpsilon).
const float WATER_EPSILON = 1.0 / 256.0;
// Fresnel reflectance of the surface for diffuse sky light entering the water (~6.6 %).
const float SKY_FRESNEL_MEAN = 0.066;

// What the water under the shaded point sends up: radiance leaving the sea per unit of the
// irradiance the lighting multiplies it by (sr^-1), set by the caller before lighting.
struct WaterVolume {
  bool set;
  vec3 reflectance;
};
WaterVolume gWater = WaterVolume(false, vec3(0.0));

// Depth of the sea floor below mean sea level at a point with geodetic normal upE, m, its
// coast as a footprint of `footprintRad` (radians of arc) sees it (the same coast as the
// land's: else a bay that only the fine mask holds reads as a floor at the surface); without
// an elevation layer the sea is deep everywhere. `land`: the land mask's fraction there at
// that footprint (0 without a mask or a layer); `keepDepth`: the layer's (render/elevation.glsl).
float seaFloorDepthM(vec3 upE, float footprintRad, out float land, out float keepDepth) {
  land = 0.0;
  keepDepth = 0.0;
  if (uElevationSize.x <= 0.0) return 1e4;
  vec2 latLon = latLonOfNormal(upE);
  vec2 heightKeep = elevationLayerAt(latLon);
  keepDepth = heightKeep.y;
  if (!landMaskOn()) return max(-heightKeep.x, 0.0);
  land = landFraction(latLon, footprintRad);
  return max(-constrainByLandFraction(heightKeep.x, heightKeep.y, land), 0.0);  // (elevationAt's)
}
float seaFloorDepthM(vec3 upE) {
  float land, keepDepth;
  return seaFloorDepthM(upE, 1e9, land, keepDepth);
}

// The width of the nearshore shallows, m. Within the land mask's reach of its coast (its
// fraction of land above 0: a few 2′ cells) the floor comes from a layer's cells kilometres
// wide and from the coast's lift of it (render/elevation.glsl's constrainByLandFraction),
// metres under the surface along every coast; a footprint wider than this sees the shallows
// over only this much of it, deep water over the rest. A stand-in like the beach's width
// (terrain/material.glsl): a nearshore slope of ~1:50 down to 10 m. Not on the banks the
// layer's correction set (keepDepth: their floor is the bank's own), nor on shelves away
// from the coast. (From orbit the sea side of every coast pixel was pale with floor.)
const float WATER_SHALLOWS_WIDTH_M = 500.0;

// The water column under a point seen from afar (the globe's sea): a flat floor at the layer's
// depth, the view (vE, to the eye) and the Sun (sunE) refracted by the mean surface, lit by
// the Sun (irradiances from the sky model, `sunSeen` of its disc) and the sky; the pixel's
// footprint there `footprintRad` (radians of arc).
void prepareWaterColumn(vec3 vE, vec3 upE, vec3 sunE, float sunSeen, float footprintRad) {
  float land, keepDepth;
  float depthM = seaFloorDepthM(upE, footprintRad, land, keepDepth);
  // The coast's shallows: their share of the footprint, faded in over the mask's first tenth
  // of land and out over the banks' marks (no step where either starts).
  float share = min(WATER_SHALLOWS_WIDTH_M / max(footprintRad * WGS84_A, 1e-3), 1.0);
  float floorShare = mix(1.0, share, smoothstep(0.0, 0.1, land) * (1.0 - smoothstep(0.25, 0.75, keepDepth)));
  vec3 k = uWaterAttenuation;
  if (depthM > waterMaxPathM(k, WATER_EPSILON)) {
    gWater = WaterVolume(true, uSeaColor);
    return;
  }
  float muS = dot(sunE, upE);
  float sunZenith = acos(clamp(muS, -1.0, 1.0));
  vec3 eSun = sunIrradiance(sunZenith) * sunSeen, eSky = skyIrradiance(sunZenith);
  vec3 sunBelow = eSun * max(muS, 0.0) * (1.0 - fresnelSchlick(max(muS, 0.0)));
  float cosSunWater = waterRefractedCosine(max(muS, 0.0));
  vec3 floorIrr = floorIrradiance(k, depthM, cosSunWater, sunBelow, 1.0, eSky * (1.0 - SKY_FRESNEL_MEAN));
  float viewPathM = depthM / waterRefractedCosine(clamp(dot(vE, upE), 0.0, 1.0));
  vec3 surfaceIrr = eSun * max(muS, 0.0) + eSky;
  vec3 radiance = waterColumnRadiance(k, uSeaColor, uFloorAlbedo, floorIrr, depthM, viewPathM, surfaceIrr);
  gWater = WaterVolume(true, mix(uSeaColor, radiance / max(surfaceIrr, vec3(1e-6)), floorShare));
}

// Upwelling radiance per unit irradiance (sr^-1) over water `depthM` deep: what the caller
// prepared (gWater), else the deep sea's `deepColor` (the validation variants, which model the
// open sea only).
vec3 shallowSeaColor(vec3 deepColor, float depthM) {
  return gWater.set ? gWater.reflectance : deepColor;
}
