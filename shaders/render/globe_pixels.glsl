// The globe's scattered pixels (GlobeRenderer::shadeScatteredParts): the pixels of its edge and
// surface parts (the limb, the horizon, the coasts), listed by render/globe_list.frag and shaded
// from the list by render/globe.frag compiled as a compute shader (GLOBE_COMPUTE). A fragment
// shader runs on blocks of pixels, so on llvmpipe a lone coast pixel paid for its whole vector
// of lanes (8 at 256 bits): listed, 64 of them share a work group's vectors.
// uArgs: glDispatchComputeIndirect's groups, written from uCount by render/globe_list_args.comp,
// in rows of at most GLOBE_PIXELS_ROW groups (GL guarantees 65535 a dimension; a 4K frame's
// pixels need more): group (x, y) holds pixels from (y * GLOBE_PIXELS_ROW + x) * GLOBE_PIXELS_GROUP on.
// A pixel is packed as x | y << 16.
layout(std430, binding = OG_GLOBE_PIXELS_BINDING) buffer GlobePixels {
  uint uCount;
  uint uArgs[3];
  uint uPixels[];
};
const uint GLOBE_PIXELS_GROUP = OG_GLOBE_PIXELS_GROUP;  // the compute shader's work group
const uint GLOBE_PIXELS_ROW = OG_GLOBE_PIXELS_ROW;
