// The water volume's smooth terms per vertex of the projected grid (ocean/grid.vert), read by
// ocean/water_volume.glsl: they vary over kilometres, a grid cell spans a few pixels, and
// llvmpipe pays for every lookup per pixel (docs/performance.md). The sea floor's depth under
// the vertex (each pixel's search along its refracted ray starts there instead of marching
// from the surface), and the Sun's and the sky's irradiance at sea level (the atmosphere's
// tables, two lookups a pixel otherwise).
// Needs (included first): render/elevation.glsl, geo/ellipsoid.glsl; without OCEAN_SIMPLE_SKY
// uSunDirEcef.
#ifndef OCEAN_NO_WATER_VOLUME
out float vFloorDepthM;  // m below mean sea level, negative over land
#ifndef OCEAN_SIMPLE_SKY
#include "atmosphere/skymap.glsl"
out vec3 vWaterSunE;     // the Sun's irradiance at the vertex's Sun zenith (skymap.glsl's units)
out vec3 vWaterSkyE;     // the sky's, on a horizontal surface
#endif

void prepareWaterVolumeVertex(vec2 latLon, vec3 up) {
  vFloorDepthM = uElevationSize.x > 0.0 ? -elevationAt(latLon) : 1e4;
#ifndef OCEAN_SIMPLE_SKY
  float sunZenith = acos(clamp(dot(uSunDirEcef, up), -1.0, 1.0));
  vWaterSunE = sunIrradiance(sunZenith);
  vWaterSkyE = skyIrradiance(sunZenith);
#endif
}
#else
void prepareWaterVolumeVertex(vec2 latLon, vec3 up) {}
#endif
