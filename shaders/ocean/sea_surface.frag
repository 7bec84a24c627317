#version 450 core
// The deferred sea's first pass (render/OceanRenderer::drawDeferred): the projected grid's
// nearest fragment per pixel writes what its vertices hand the shading into the surface buffer
// (ocean/sea_surface.glsl) and its class into the stencil (ocean/sea_class.glsl), after the
// coast test where land may be near; the shading (ocean/ocean.frag with OCEAN_DEFERRED) then
// runs once per pixel, class by class. Without GL_ARB_shader_stencil_export (NVIDIA's drivers)
// the class goes into the surface buffer (SEA_CLASS_IN_SURFACE) and ocean/sea_class_stencil.frag
// copies it into the stencil.
#if !defined(SEA_CLASS_IN_SURFACE) && defined(OG_STENCIL_EXPORT)  // (OG_STENCIL_EXPORT: gl::Program)
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/types.glsl"
#include "geo/ellipsoid.glsl"
#include "ocean/wind.glsl"
#include "ocean/patterns.glsl"
#include "render/elevation.glsl"
#include "ocean/coast.glsl"

in vec2 vOceanXY;
in vec3 vRelative;
in vec2 vPatternMean;
in vec3 vPatternCov;
in vec2 vPatternJacobian;
in float vPatternShare[PATTERN_COUNT];
#ifndef OCEAN_SIMPLE_SKY
in vec3 vTransmittance;
in vec3 vInscatter;
#endif
#ifdef OCEAN_SEA_CLASSIFY
#include "ocean/sea_class.glsl"
#elif !defined(OCEAN_NO_WATER_VOLUME)
in float vFloorDepthM;
#endif
#ifndef OCEAN_NO_WATER_VOLUME
in float vFloorFine;
#ifndef OCEAN_SIMPLE_SKY
in vec3 vWaterSunE;
in vec3 vWaterSkyE;
#endif
#endif
#define SEA_SURFACE_WRITE
#include "ocean/sea_surface.glsl"

void main() {
  // Derivatives first, while the pixel's quad is whole.
  float footprint = max(length(dFdx(vOceanXY)), length(dFdy(vOceanXY)));
#ifndef OCEAN_NO_WATER_VOLUME
  vec2 floorSlope = floorDepthSlope(vOceanXY, vFloorDepthM);
#else
  vec2 floorSlope = vec2(0.0);
#endif
  // With classes the grid is drawn three times, the triangles near land by the program with the
  // coast test, the others by ones without it (ocean/grid_near_land.comp): a condition here
  // would skip nothing on llvmpipe.
  KEEP_SEA_SAMPLES(vRelative)
#ifdef OCEAN_SEA_CLASSIFY
  int seaClass = seaClassOfFragment();
#else
  int seaClass = 1;
#endif
#ifndef SEA_CLASS_IN_SURFACE
  gl_FragStencilRefARB = seaClass;
#endif
  writeSeaSurface(footprint, floorSlope, seaClass);
}
