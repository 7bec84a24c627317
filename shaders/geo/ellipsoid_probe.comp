#version 450 core
// Evaluates geo/ellipsoid.glsl's latLonOfNormal at given geodetic normals, for tests against the
// CPU's geodetic latitude and longitude (tests/gl/land_mask_gpu_test.cpp): every pass that looks
// a place up (the elevation layer, the land mask, the winds, the imagery) goes through it.
#include "geo/ellipsoid.glsl"

layout(local_size_x = 1) in;
// In: xyz = a unit geodetic normal (ECEF axes); out: xy = (latitude, longitude) radians.
layout(std430, binding = 0) buffer ProbeValues { vec4 probeValues[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  probeValues[i] = vec4(latLonOfNormal(probeValues[i].xyz), 0.0, 0.0);
}
