// Shallow water (Baboud & Decoret 2006, seed 001 §4.1): light seen through the sea is the deep
// water's upwelling plus the sea floor, attenuated per channel as alpha(d) = exp(-a_lambda d)
// over the distance d through water. Here d = 2 x depth (down to the floor and back up, the
// vertical path: refraction keeps rays steep under the surface), the depth from the elevation
// layer's bathymetry. Hook for ocean/lighting.glsl's refracted term, shared by the globe's sea
// (orbit) and the projected grid, so shelves, banks and coasts read from orbit and up close.
#include "geo/ellipsoid.glsl"
#include "render/elevation.glsl"

// Diffuse attenuation of clear coastal water, m^-1 (red, green, blue): pure water absorption
// (Pope & Fry 1997: ~0.35, 0.06, 0.01) raised for the dissolved and suspended matter of coasts.
const vec3 WATER_ATTENUATION = vec3(0.40, 0.075, 0.045);
// A sandy sea floor's reflectance (the terrain's stand-in material under water is sand too).
const vec3 SEA_FLOOR_ALBEDO = vec3(0.30, 0.27, 0.19);

// Depth of the sea floor below mean sea level at a point with geodetic normal upE, m; without
// an elevation layer the sea is deep everywhere.
float seaFloorDepthM(vec3 upE) {
  if (uElevationSize.x <= 0.0) return 1e4;
  return max(-elevationAt(latLonOfNormal(upE)), 0.0);
}

// Upwelling radiance per unit irradiance (sr^-1) over water `depthM` deep, from the deep sea's
// `deepColor`.
vec3 shallowSeaColor(vec3 deepColor, float depthM) {
  vec3 floorSeen = exp(-WATER_ATTENUATION * (2.0 * depthM));
  return mix(deepColor, SEA_FLOOR_ALBEDO / PI, floorSeen);
}
