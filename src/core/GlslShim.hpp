#pragma once
// The C++ side of the GLSL/C++ twins: files of shaders/ written in the common subset
// (shaders/common/types.glsl) compile as C++ in double precision inside a namespace that opens
// this one, so the CPU tests run the shaders' own code:
//
//   namespace glsl {
//   using namespace og::glsl;
//   #include "ocean/brdf.glsl"
//   }
//
// The vocabulary (both sides, shaders/common/types.glsl): Number for scalars (float in GLSL,
// double here); vectors by their GLSL names (vec2, vec3, vec4, ivec3, mat3: GLM's double
// vectors here), uint; IN(T)/OUT(T)/INOUT(T) for parameter qualifiers; the GLSL built-ins
// below (clamp, mix, dot, ... in GLSL's argument order, atan(y, x), mod as x - y floor(x / y)).
// OG_EXPECT_RANGE(x, lo, hi) states a range (units in the caller's name): it asserts in debug
// C++ builds and vanishes in GLSL and in Release builds.
// Twins: ocean/Brdf.cpp, ocean/Lighting.cpp, ocean/WaterOptics.cpp, ocean/Spectrum.cpp,
// terrain/Heightfield.cpp, atmosphere/Reference.cpp (docs/architecture.md, "GLSL/C++ twins").
#include <glm/glm.hpp>

#include <cassert>
#include <cmath>
#include <cstdint>

namespace og::glsl {

using Number = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using ivec3 = glm::ivec3;
using mat3 = glm::dmat3;
using uint = std::uint32_t;

// Built-ins taking vectors (and, for clamp/mix/max/min/step/smoothstep, scalars too).
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::reflect;
using glm::smoothstep;
using glm::step;
using glm::transpose;
inline vec3 exp(const vec3& x) { return glm::exp(x); }
inline vec3 sqrt(const vec3& x) { return glm::sqrt(x); }

// Scalar built-ins.
inline Number sqrt(Number x) { return std::sqrt(x); }
inline Number exp(Number x) { return std::exp(x); }
inline Number log(Number x) { return std::log(x); }
inline Number pow(Number x, Number y) { return std::pow(x, y); }
inline Number abs(Number x) { return std::abs(x); }
inline Number floor(Number x) { return std::floor(x); }
inline Number sin(Number x) { return std::sin(x); }
inline Number cos(Number x) { return std::cos(x); }
inline Number tan(Number x) { return std::tan(x); }
inline Number acos(Number x) { return std::acos(x); }
inline Number asin(Number x) { return std::asin(x); }
inline Number atan(Number x) { return std::atan(x); }
inline Number atan(Number y, Number x) { return std::atan2(y, x); }  // GLSL's two-argument atan
inline Number tanh(Number x) { return std::tanh(x); }
inline Number mod(Number x, Number y) { return x - y * std::floor(x / y); }

}  // namespace og::glsl

// Tells shaders/common/types.glsl (and twins) that they are compiled as C++.
#define OG_GLSL_SHIM 1
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&

#ifdef NDEBUG
#define OG_EXPECT_RANGE(x, lo, hi) ((void)0)
#else
#define OG_EXPECT_RANGE(x, lo, hi) assert((x) >= (lo) && (x) <= (hi))
#endif
