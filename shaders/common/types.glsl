// Type names shared with C++: files written in the common GLSL/C++ subset (ocean/brdf.glsl,
// ocean/spectrum.glsl, terrain/detail.glsl) use these so their C++ twins can compile them in
// double precision.
#define Number float
#define Vec2 vec2
#define Vec3 vec3
#define Vec4 vec4
#define IVec3 ivec3
