// What lets one source compile as C++ (on GLM) and as GLSL: the code both engines run is written once, in
// Shared/ headers that include this one (Shared/Warps.h). Write such code in the common subset: GLSL types and
// constructors (vec2, vec3), float literals with an `f` suffix (GLSL accepts it; without it C++ would compute
// in double and the engines would differ), the scalar functions below, RT_FN before each function, RT_OUT(T)
// for out parameters, RT_INOUT(T) for inout ones, RT_IN(T) for struct parameters and RT_ENUM(Type, Value) for
// HostDevice.h's tags, RT_DCHECK(cond) for preconditions (Check.h's in C++, nothing in GLSL). C++ sees it in
// namespace rt::shader. Code whose scalar type is switched to double for the CPU (Shared/SphericalTriangle.h's
// Real) writes its literals without the suffix instead: double in C++, float in GLSL.
#ifndef RT_SHADER_LANG_H
#define RT_SHADER_LANG_H

#ifdef __cplusplus
#include <cmath>
#include <cstdint>

#include "Check.h"
#include "Math/Math.h"

namespace rt::shader
{
using uint = std::uint32_t;
using glm::cross;
using glm::dot;
using glm::floatBitsToInt;
using glm::floatBitsToUint;
using glm::floor;
using glm::intBitsToFloat;
using glm::ivec3;
using glm::length;
using glm::normalize;
using glm::uintBitsToFloat;
using glm::uvec2;
using glm::uvec3;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using rt::kInv2Pi;
using rt::kInv4Pi;
using rt::kInvPi;
using rt::kPi;
using rt::lengthSquared;
using rt::luminance;
using rt::reflect;
using rt::safeSqrt;

// GLSL's built-ins for float, so that an unqualified call never reaches C's double versions.
inline float sqrt(float x) { return std::sqrt(x); }
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float abs(float x) { return std::fabs(x); }
inline float acos(float x) { return std::acos(x); }
inline float log(float x) { return std::log(x); }
inline float pow(float x, float y) { return std::pow(x, y); }
inline float atan(float y, float x) { return std::atan2(y, x); } // GLSL's two-argument atan
inline float min(float a, float b) { return b < a ? b : a; } // GLSL's min/max: the first for NaN b, as std::min
inline float max(float a, float b) { return a < b ? b : a; }
inline uint min(uint a, uint b) { return b < a ? b : a; }
inline uint max(uint a, uint b) { return a < b ? b : a; }
inline float clamp(float x, float lo, float hi) { return min(max(x, lo), hi); } // GLSL's definition
inline float roundEven(float x) { return std::nearbyint(x); } // the default rounding mode: to nearest, ties even
/// +1 or -1 with the sign bit of x (-0 gives -1): copysign(1, x). GLSL's sign() returns 0 for 0.
inline float signNotZero(float x) { return std::copysign(1.0f, x); }
/// GLSL's bitfieldReverse for 32 bits: bit k moves to bit 31 - k.
inline uint bitfieldReverse(uint x)
{
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 4u) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4u);
    x = ((x >> 8u) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8u);
    return (x >> 16u) | (x << 16u);
}

// The same built-ins for double, for Shared code whose scalar type is double on the CPU and float in GLSL
// (Shared/SphericalTriangle.h's Real). A call mixing float and double is ambiguous, so it does not compile.
inline double sqrt(double x) { return std::sqrt(x); }
inline double sin(double x) { return std::sin(x); }
inline double cos(double x) { return std::cos(x); }
inline double abs(double x) { return std::fabs(x); }
inline double atan(double y, double x) { return std::atan2(y, x); }
inline double min(double a, double b) { return b < a ? b : a; }
inline double max(double a, double b) { return a < b ? b : a; }
inline double clamp(double x, double lo, double hi) { return min(max(x, lo), hi); }
} // namespace rt::shader

#define RT_FN inline
#define RT_OUT(Type) Type&
#define RT_INOUT(Type) Type&
// Structs go in by const reference on the CPU, as C++ code passes them (no copy left to the optimiser).
#define RT_IN(Type) const Type&
#define RT_ENUM(Type, Value) Type::Value
// A read-only array that GLSL reads as a global buffer (Bindings.glsl) and C++ passes as a pointer: written
// first in a parameter list, RT_ARRAY(Type, name) declares `const Type* name,` in C++ and nothing in GLSL, so
// the body names the array the same way in both; C++ calls pass it, GLSL calls leave it out.
#define RT_ARRAY(Type, name) const Type* name,
// A read-only struct that GLSL reads as a global block (Bindings.glsl's perlinTables), as RT_ARRAY passes arrays.
#define RT_GLOBAL(Type, name) const Type& name,
#define RT_PASS(name) name, // passes an RT_ARRAY on to another such function
#define RT_SHADER_NAMESPACE_BEGIN namespace rt::shader {
#define RT_SHADER_NAMESPACE_END }
// Exact-error arithmetic (Shared/SphereQuadratic.h) needs every operation rounded as written: C++ builds with
// -ffp-contract=off project-wide; GLSL marks such variables `precise` (no fused multiply-add, no reordering).
#define RT_PRECISE
// A loop the GPU compiler must keep rolled (GL_EXT_control_flow_attributes' [[dont_unroll]]): a sampler's
// iterations unrolled into the megakernel cost every path registers and code, taken or not (the horizon-clipped
// cap's, docs/notebook/PERFORMANCE.md §14). C++ compilers decide for themselves.
#define RT_DONT_UNROLL
#else
// Common/Math/Math.h's constants and helpers, for GLSL.
const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kInv2Pi = 0.15915494309189533577;
const float kInv4Pi = 0.07957747154594766788;

/// sqrt clamped at 0: rounding can push a quantity that is >= 0 in exact arithmetic slightly below it.
float safeSqrt(float x)
{
    return sqrt(max(0.0, x));
}

float lengthSquared(vec3 v)
{
    return dot(v, v);
}

/// Rec. 709 luminance of linear RGB.
float luminance(vec3 c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

bool isFiniteVec(vec3 v)
{
    return !any(isnan(v)) && !any(isinf(v));
}

#define RT_FN
#define RT_OUT(Type) out Type
#define RT_INOUT(Type) inout Type
#define RT_IN(Type) Type
#define RT_ENUM(Type, Value) Type##_##Value

float signNotZero(float x)
{
    return (floatBitsToUint(x) & 0x80000000u) != 0u ? -1.0 : 1.0;
}
// Check.h's debug checks of a precondition: on in C++ Debug builds (compiled, never run, in Release), nothing in
// GLSL.
#define RT_DCHECK(cond)
#define RT_ARRAY(Type, name)
#define RT_GLOBAL(Type, name)
#define RT_PASS(name)
#define RT_SHADER_NAMESPACE_BEGIN
#define RT_SHADER_NAMESPACE_END
#define RT_PRECISE precise
#extension GL_EXT_control_flow_attributes : enable
#define RT_DONT_UNROLL [[dont_unroll]]
#endif

#endif
