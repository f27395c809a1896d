// Moving a ray's origin off the surface it leaves, written once for both engines (Shared/ShaderLang.h):
// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, 2019,
// scaled by the largest coordinate the surface's intersection test computes with.
#ifndef RT_SHARED_RAY_OFFSET_H
#define RT_SHARED_RAY_OFFSET_H

#include "Shared/ShaderLang.h"

#if defined(__cplusplus) && defined(__SSE4_1__)
#include <immintrin.h>
#endif

RT_SHADER_NAMESPACE_BEGIN

/// Moves the surface point p along the unit geometric normal n (pointing to the side the new ray leaves
/// from) far enough that the new ray, started with tmin = 0, does not hit the surface it leaves: 256 ulps of
/// each coordinate, except below |p_i| = scale/32, where the offset is an absolute scale/65536 (Wächter &
/// Binder's constants are those of scale = 1). `scale` is the largest coordinate magnitude the surface's
/// intersection test computes with (the largest |vertex coordinate| of a triangle or quad; 1 for surfaces whose
/// test errs in proportion to p, such as our own sphere test): a triangle test in a driver (NVIDIA's) errs by
/// ulps of the vertices, and a wall at x = 0 of a 555-unit Cornell box re-hit itself from the 1/65536 offset
/// often enough to lose 6-10 % of its radiance on the H100. Values below 1 count as 1. The constants are powers
/// of two, so s times them is exact. One coordinate at a time: what GLSL runs, and C++ without SSE 4.1.
RT_FN vec3 offsetRayOriginScalar(vec3 p, vec3 n, float scale)
{
    const float s = scale > 1.0f ? scale : 1.0f;
    const float origin = s * (1.0f / 32.0f);
    const float floatOffset = s * (1.0f / 65536.0f);
    const ivec3 offset = ivec3(256.0f * n); // truncated towards 0
    const ivec3 bits = floatBitsToInt(p);
    const vec3 moved = intBitsToFloat(ivec3(bits.x + (p.x < 0.0f ? -offset.x : offset.x),
                                            bits.y + (p.y < 0.0f ? -offset.y : offset.y),
                                            bits.z + (p.z < 0.0f ? -offset.z : offset.z)));
    RT_PRECISE vec3 shifted = p + floatOffset * n;
    return vec3(abs(p.x) < origin ? shifted.x : moved.x, abs(p.y) < origin ? shifted.y : moved.y,
                abs(p.z) < origin ? shifted.z : moved.z);
}

#if defined(__cplusplus) && defined(__SSE4_1__)
/// offsetRayOriginScalar with the three coordinates in one SSE register: the same operations, so the same bits
/// (MathTest's RayOffset.SseIsTheScalarOneBitForBit), in about half the instructions.
inline vec3 offsetRayOrigin(vec3 p, vec3 n, float scale)
{
    const float s = scale > 1.0f ? scale : 1.0f;
    const __m128 pv = _mm_setr_ps(p.x, p.y, p.z, 0.0f);
    const __m128 nv = _mm_setr_ps(n.x, n.y, n.z, 0.0f);
    const __m128i offset = _mm_cvttps_epi32(_mm_mul_ps(_mm_set1_ps(256.0f), nv)); // truncated towards 0
    const __m128i negative = _mm_castps_si128(_mm_cmplt_ps(pv, _mm_setzero_ps()));
    const __m128i signedOffset = _mm_sub_epi32(_mm_xor_si128(offset, negative), negative); // -offset where p < 0
    const __m128 moved = _mm_castsi128_ps(_mm_add_epi32(_mm_castps_si128(pv), signedOffset));
    const __m128 nearOrigin = _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), pv), _mm_set1_ps(s * (1.0f / 32.0f)));
    const __m128 shifted = _mm_add_ps(pv, _mm_mul_ps(_mm_set1_ps(s * (1.0f / 65536.0f)), nv));
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, _mm_blendv_ps(moved, shifted, nearOrigin));
    return vec3(lanes[0], lanes[1], lanes[2]);
}
#else
RT_FN vec3 offsetRayOrigin(vec3 p, vec3 n, float scale)
{
    return offsetRayOriginScalar(p, n, scale);
}
#endif

/// The `scale` of offsetRayOrigin for a planar primitive: its largest |vertex coordinate|, world space.
RT_FN float planarOffsetScale(vec3 a, vec3 b, vec3 c)
{
    const vec3 m = max(abs(a), max(abs(b), abs(c)));
    return max(m.x, max(m.y, m.z));
}

RT_SHADER_NAMESPACE_END

#endif
