// GLSL side of the conventions of atmosphere/functions.glsl (the C++ side is
// src/atmosphere/Reference.cpp): single precision, samplers as table types.
#include "common/constants.glsl"
#include "common/types.glsl"  // Number, IN, OUT, INOUT
#define Texture2D sampler2D
#define Texture3D sampler3D
