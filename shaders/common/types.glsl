// The vocabulary of the GLSL/C++ twins (files compiled both as shaders and, in double precision,
// as C++: ocean/brdf.glsl, ocean/lighting.glsl, ocean/water_optics.glsl, ocean/spectrum.glsl,
// terrain/detail.glsl, atmosphere/functions.glsl). Scalars are Number; vectors keep their GLSL
// names (vec2, vec3, vec4, ivec3, mat3), parameters are qualified IN(T)/OUT(T)/INOUT(T), and
// OG_EXPECT_RANGE(x, lo, hi); states a range that C++ debug builds assert. The C++ side of these
// names is src/core/GlslShim.hpp, which defines OG_GLSL_SHIM.
#ifndef OG_GLSL_SHIM
#define Number float
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define OG_EXPECT_RANGE(x, lo, hi)
#endif
