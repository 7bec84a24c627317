#version 450 core
// The sky maps' frame layer (render/Atmosphere::prepareFrameSkyLayer): the two layers around one
// Sun zenith angle blended into the array's last layer, one mip level per dispatch (mip-mapping
// is linear, so blending the levels gives the levels of the blend). Views whose Sun zenith
// hardly varies (the sea from a few metres) then read one filtered layer, not two
// (atmosphere/skymap.glsl, SKY_FRAME_LAYER).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = OG_UNIT_SKY_MAP) uniform sampler2DArray uSkyMap;
layout(binding = 0, rgba16f) writeonly uniform image2D uFrameLayer;  // the last layer, level uLevel
uniform int uLevel;
uniform int uLayer0;    // the lower of the two layers
uniform float uWeight;  // of the upper one, [0, 1]

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(uFrameLayer)))) return;
  vec4 a = texelFetch(uSkyMap, ivec3(p, uLayer0), uLevel);
  vec4 b = texelFetch(uSkyMap, ivec3(p, uLayer0 + 1), uLevel);
  imageStore(uFrameLayer, p, mix(a, b, uWeight));
}
