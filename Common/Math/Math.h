// Vector math on GLM (float, right-handed, y up) and the few scalar helpers every layer needs.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace rt
{
using glm::dvec3;
using glm::ivec2;
using glm::mat3;
using glm::mat4;
using glm::uvec2;
using glm::vec2;
using glm::vec3;
using glm::vec4;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline float radians(float degrees) { return degrees * (kPi / 180.0f); }

/// min / max that compile to one minss / maxss: std::fmin / fmax are library calls without -ffast-math
/// (their NaN rules differ from the instruction's). A NaN in `a` yields `b`.
inline float minf(float a, float b) { return a < b ? a : b; }
inline float maxf(float a, float b) { return a > b ? a : b; }

/// sqrt clamped at 0: rounding can push a quantity that is >= 0 in exact arithmetic slightly below it.
inline float safeSqrt(float x) { return std::sqrt(maxf(x, 0.0f)); }

inline float lengthSquared(const vec3& v) { return glm::dot(v, v); }

inline bool isFinite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline float maxComponent(const vec3& v) { return maxf(v.x, maxf(v.y, v.z)); }

/// Rec. 709 luminance of linear RGB.
inline float luminance(const vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/// Mirror reflection of `v` about the plane with unit normal `n` (v points towards the surface).
inline vec3 reflect(const vec3& v, const vec3& n) { return v - 2.0f * glm::dot(v, n) * n; }

} // namespace rt
