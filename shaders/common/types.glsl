// Type names shared with C++: files written in the common GLSL/C++ subset (ocean/brdf.glsl,
// ocean/spectrum.glsl) use these so their C++ twins can compile them in double precision.
#define Number float
#define Vec2 vec2
#define Vec3 vec3
