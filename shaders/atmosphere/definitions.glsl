// GLSL side of the conventions of atmosphere/functions.glsl (the C++ side is
// src/atmosphere/Reference.cpp): single precision, samplers as table types.
#include "common/constants.glsl"
#define Real float
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define Texture2D sampler2D
#define Texture3D sampler3D
