#pragma once

#include <bit>
#include <cstdint>

#if defined(__SSE4_1__)
#include <immintrin.h>
#endif

#include "Math/Math.h"

namespace rt
{
/// Moves a surface point off the surface along the geometric normal `n` (pointing to the side the new ray
/// leaves from) far enough that the new ray, started with tmin = 0, does not hit the surface it leaves.
/// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, 2019:
/// 256 ulps of each coordinate, except below |p_i| = scale/32, where the offset is an absolute scale/65536
/// (their constants are those of scale = 1).
///
/// `scale` is the largest coordinate magnitude the surface's intersection test computes with (the largest
/// |vertex coordinate| of a triangle or quad; 1 for surfaces whose test errs in proportion to p, such as
/// our own sphere test). Wächter & Binder bound the error of p alone; a triangle test in a driver (NVIDIA's)
/// errs by ulps of the vertices, and a wall at x = 0 of a 555-unit Cornell box re-hit itself from the
/// 1/65536 offset often enough to lose 6-10 % of its radiance on the H100. Values below 1 count as 1.
/// The offset grows with the largest primitive: a ground quad of side 1e5 moves points near its axis planes
/// by about 1.5 units (the catalogue's largest, rtnw-final's ground boxes, by 0.015).
/// A quad is two triangles on the GPU, each scaled by its own three corners; the CPU takes all four, so the
/// two engines' offsets can differ on tilted quads (by a factor below 2; both clear the error).
/// The GLSL twin is Shaders/RayOffset.glsl, bit for bit (the constants are powers of two: s times them is exact).
inline vec3 offsetRayOrigin(const vec3& p, const vec3& n, float scale = 1.0f)
{
    const float s = scale > 1.0f ? scale : 1.0f;
    const float origin = s * (1.0f / 32.0f);
    const float floatOffset = s * (1.0f / 65536.0f);
    constexpr float kIntScale = 256.0f;
#if defined(__SSE4_1__)
    // The loop below, the three coordinates in one register: the same operations, so the same bits.
    const __m128 pv = _mm_setr_ps(p.x, p.y, p.z, 0.0f);
    const __m128 nv = _mm_setr_ps(n.x, n.y, n.z, 0.0f);
    const __m128i offset = _mm_cvttps_epi32(_mm_mul_ps(_mm_set1_ps(kIntScale), nv)); // truncated, as static_cast
    const __m128i negative = _mm_castps_si128(_mm_cmplt_ps(pv, _mm_setzero_ps()));
    const __m128i signedOffset = _mm_sub_epi32(_mm_xor_si128(offset, negative), negative); // -offset where p < 0
    const __m128 moved = _mm_castsi128_ps(_mm_add_epi32(_mm_castps_si128(pv), signedOffset));
    const __m128 nearOrigin = _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), pv), _mm_set1_ps(origin));
    const __m128 shifted = _mm_add_ps(pv, _mm_mul_ps(_mm_set1_ps(floatOffset), nv));
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, _mm_blendv_ps(moved, shifted, nearOrigin));
    return {lanes[0], lanes[1], lanes[2]};
#else
    vec3 out;
    for (int i = 0; i < 3; ++i)
    {
        const auto offset = static_cast<std::int32_t>(kIntScale * n[i]);
        const std::int32_t bits = std::bit_cast<std::int32_t>(p[i]);
        const float moved = std::bit_cast<float>(bits + (p[i] < 0.0f ? -offset : offset));
        out[i] = std::fabs(p[i]) < origin ? p[i] + floatOffset * n[i] : moved;
    }
    return out;
#endif
}

/// The `scale` of offsetRayOrigin for a planar primitive: its largest |vertex coordinate|, world space.
inline float planarOffsetScale(const vec3& a, const vec3& b, const vec3& c)
{
    return maxComponent(glm::max(glm::abs(a), glm::max(glm::abs(b), glm::abs(c))));
}
} // namespace rt
