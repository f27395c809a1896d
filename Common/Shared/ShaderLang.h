// What lets one source compile as C++ (on GLM) and as GLSL: the sampling code both engines run is written
// once, in Shared/ headers that include this one (Shared/Warps.h). Write such code in the common subset:
// GLSL types and constructors (vec2, vec3), float literals with an `f` suffix (GLSL accepts it; without it
// C++ would compute in double and the engines would differ), the scalar functions below, RT_FN before each
// function and RT_OUT(T) for out parameters. C++ sees it in namespace rt::shader.
#ifndef RT_SHADER_LANG_H
#define RT_SHADER_LANG_H

#ifdef __cplusplus
#include <cmath>

#include "Math/Math.h"

namespace rt::shader
{
using glm::vec2;
using glm::vec3;
using rt::kInv4Pi;
using rt::kInvPi;
using rt::kPi;
using rt::safeSqrt;

// GLSL's built-ins for float, so that an unqualified call never reaches C's double versions.
inline float sqrt(float x) { return std::sqrt(x); }
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float abs(float x) { return std::fabs(x); }
inline float roundEven(float x) { return std::nearbyint(x); } // the default rounding mode: to nearest, ties even
} // namespace rt::shader

#define RT_FN inline
#define RT_OUT(Type) Type&
#define RT_SHADER_NAMESPACE_BEGIN namespace rt::shader {
#define RT_SHADER_NAMESPACE_END }
#else
#include "Math/Constants.glsl"

#define RT_FN
#define RT_OUT(Type) out Type
#define RT_SHADER_NAMESPACE_BEGIN
#define RT_SHADER_NAMESPACE_END
#endif

#endif
