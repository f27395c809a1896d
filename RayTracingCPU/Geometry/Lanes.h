// A vector of floats processed together, as wide as the build's instruction set allows: 8 lanes with AVX
// (x86-64-v3 and v4 builds, RT_X86_LEVEL), 4 with SSE (x86-64-v2), 4 plain-loop lanes elsewhere. Just the operations the packet
// tests need; comparisons give lane masks (all bits set where true).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__AVX__)
#include <immintrin.h>
#define RT_LANES_AVX 1
#elif defined(__SSE2__) || defined(_M_X64)
#include <immintrin.h>
#define RT_LANES_SSE 1
#endif

namespace rt::cpu
{
#if defined(RT_LANES_AVX)
inline constexpr int kLanes = 8;

struct Lanes
{
    __m256 v;

    Lanes() = default;
    Lanes(__m256 x) : v(x) {}
    explicit Lanes(float x) : v(_mm256_set1_ps(x)) {}
    static Lanes load(const float* p) { return _mm256_load_ps(p); }
    void storeTo(float* p) const { _mm256_store_ps(p, v); } // p aligned to 32 bytes

    friend Lanes operator+(Lanes a, Lanes b) { return _mm256_add_ps(a.v, b.v); }
    friend Lanes operator-(Lanes a, Lanes b) { return _mm256_sub_ps(a.v, b.v); }
    friend Lanes operator*(Lanes a, Lanes b) { return _mm256_mul_ps(a.v, b.v); }
    friend Lanes operator/(Lanes a, Lanes b) { return _mm256_div_ps(a.v, b.v); }
    friend Lanes operator-(Lanes a) { return _mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f)); }
    friend Lanes operator<(Lanes a, Lanes b) { return _mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ); }
    friend Lanes operator<=(Lanes a, Lanes b) { return _mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ); }
    friend Lanes operator>(Lanes a, Lanes b) { return _mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ); }
    friend Lanes operator>=(Lanes a, Lanes b) { return _mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ); }
    friend Lanes operator==(Lanes a, Lanes b) { return _mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ); }
    friend Lanes operator&(Lanes a, Lanes b) { return _mm256_and_ps(a.v, b.v); }
    friend Lanes operator|(Lanes a, Lanes b) { return _mm256_or_ps(a.v, b.v); }
    friend Lanes andNot(Lanes mask, Lanes b) { return _mm256_andnot_ps(mask.v, b.v); } // ~mask & b
    friend Lanes min(Lanes a, Lanes b) { return _mm256_min_ps(a.v, b.v); }
    friend Lanes max(Lanes a, Lanes b) { return _mm256_max_ps(a.v, b.v); }
    friend Lanes sqrt(Lanes a) { return _mm256_sqrt_ps(a.v); }
    friend Lanes abs(Lanes a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v); }
    /// Magnitude of a with the sign of b.
    friend Lanes copysign(Lanes a, Lanes b)
    {
        const __m256 sign = _mm256_set1_ps(-0.0f);
        return _mm256_or_ps(_mm256_andnot_ps(sign, a.v), _mm256_and_ps(sign, b.v));
    }
    /// mask ? a : b, lane by lane.
    friend Lanes select(Lanes mask, Lanes a, Lanes b) { return _mm256_blendv_ps(b.v, a.v, mask.v); }
    friend int movemask(Lanes mask) { return _mm256_movemask_ps(mask.v); }
    /// Smallest lane, broadcast to every lane.
    friend Lanes horizontalMin(Lanes a)
    {
        __m256 m = _mm256_min_ps(a.v, _mm256_permute2f128_ps(a.v, a.v, 1));
        m = _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
        return _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    }
    float operator[](int i) const
    {
        alignas(32) float lanes[8];
        _mm256_store_ps(lanes, v);
        return lanes[i];
    }
};
#elif defined(RT_LANES_SSE)
inline constexpr int kLanes = 4;

struct Lanes
{
    __m128 v;

    Lanes() = default;
    Lanes(__m128 x) : v(x) {}
    explicit Lanes(float x) : v(_mm_set1_ps(x)) {}
    static Lanes load(const float* p) { return _mm_load_ps(p); }
    void storeTo(float* p) const { _mm_store_ps(p, v); } // p aligned to 16 bytes

    friend Lanes operator+(Lanes a, Lanes b) { return _mm_add_ps(a.v, b.v); }
    friend Lanes operator-(Lanes a, Lanes b) { return _mm_sub_ps(a.v, b.v); }
    friend Lanes operator*(Lanes a, Lanes b) { return _mm_mul_ps(a.v, b.v); }
    friend Lanes operator/(Lanes a, Lanes b) { return _mm_div_ps(a.v, b.v); }
    friend Lanes operator-(Lanes a) { return _mm_xor_ps(a.v, _mm_set1_ps(-0.0f)); }
    friend Lanes operator<(Lanes a, Lanes b) { return _mm_cmplt_ps(a.v, b.v); }
    friend Lanes operator<=(Lanes a, Lanes b) { return _mm_cmple_ps(a.v, b.v); }
    friend Lanes operator>(Lanes a, Lanes b) { return _mm_cmpgt_ps(a.v, b.v); }
    friend Lanes operator>=(Lanes a, Lanes b) { return _mm_cmpge_ps(a.v, b.v); }
    friend Lanes operator==(Lanes a, Lanes b) { return _mm_cmpeq_ps(a.v, b.v); }
    friend Lanes operator&(Lanes a, Lanes b) { return _mm_and_ps(a.v, b.v); }
    friend Lanes operator|(Lanes a, Lanes b) { return _mm_or_ps(a.v, b.v); }
    friend Lanes andNot(Lanes mask, Lanes b) { return _mm_andnot_ps(mask.v, b.v); } // ~mask & b
    friend Lanes min(Lanes a, Lanes b) { return _mm_min_ps(a.v, b.v); }
    friend Lanes max(Lanes a, Lanes b) { return _mm_max_ps(a.v, b.v); }
    friend Lanes sqrt(Lanes a) { return _mm_sqrt_ps(a.v); }
    friend Lanes abs(Lanes a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a.v); }
    friend Lanes copysign(Lanes a, Lanes b)
    {
        const __m128 sign = _mm_set1_ps(-0.0f);
        return _mm_or_ps(_mm_andnot_ps(sign, a.v), _mm_and_ps(sign, b.v));
    }
    friend Lanes select(Lanes mask, Lanes a, Lanes b) { return _mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v)); }
    friend int movemask(Lanes mask) { return _mm_movemask_ps(mask.v); }
    friend Lanes horizontalMin(Lanes a)
    {
        const __m128 m = _mm_min_ps(a.v, _mm_shuffle_ps(a.v, a.v, _MM_SHUFFLE(2, 3, 0, 1)));
        return _mm_min_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    }
    float operator[](int i) const
    {
        alignas(16) float lanes[4];
        _mm_store_ps(lanes, v);
        return lanes[i];
    }
};
#else
inline constexpr int kLanes = 4;

struct Lanes
{
    float v[4];

    Lanes() = default;
    explicit Lanes(float x) : v{x, x, x, x} {}
    static Lanes load(const float* p) { return Lanes::map([&](int i) { return p[i]; }); }
    void storeTo(float* p) const
    {
        for (int i = 0; i < 4; ++i)
            p[i] = v[i];
    }
    template <typename Fn>
    static Lanes map(Fn&& fn)
    {
        Lanes r;
        for (int i = 0; i < 4; ++i)
            r.v[i] = fn(i);
        return r;
    }
    static float maskOf(bool b) { return std::bit_cast<float>(b ? 0xFFFFFFFFu : 0u); }
    static bool isSet(float m) { return std::bit_cast<std::uint32_t>(m) != 0; }

    friend Lanes operator+(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] + b.v[i]; }); }
    friend Lanes operator-(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] - b.v[i]; }); }
    friend Lanes operator*(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] * b.v[i]; }); }
    friend Lanes operator/(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] / b.v[i]; }); }
    friend Lanes operator-(Lanes a) { return map([&](int i) { return -a.v[i]; }); }
    friend Lanes operator<(Lanes a, Lanes b) { return map([&](int i) { return maskOf(a.v[i] < b.v[i]); }); }
    friend Lanes operator<=(Lanes a, Lanes b) { return map([&](int i) { return maskOf(a.v[i] <= b.v[i]); }); }
    friend Lanes operator>(Lanes a, Lanes b) { return map([&](int i) { return maskOf(a.v[i] > b.v[i]); }); }
    friend Lanes operator>=(Lanes a, Lanes b) { return map([&](int i) { return maskOf(a.v[i] >= b.v[i]); }); }
    friend Lanes operator==(Lanes a, Lanes b) { return map([&](int i) { return maskOf(a.v[i] == b.v[i]); }); }
    friend Lanes operator&(Lanes a, Lanes b) { return map([&](int i) { return maskOf(isSet(a.v[i]) && isSet(b.v[i])); }); }
    friend Lanes operator|(Lanes a, Lanes b) { return map([&](int i) { return maskOf(isSet(a.v[i]) || isSet(b.v[i])); }); }
    friend Lanes andNot(Lanes m, Lanes b) { return map([&](int i) { return isSet(m.v[i]) ? 0.0f : b.v[i]; }); }
    friend Lanes min(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] < b.v[i] ? a.v[i] : b.v[i]; }); }
    friend Lanes max(Lanes a, Lanes b) { return map([&](int i) { return a.v[i] > b.v[i] ? a.v[i] : b.v[i]; }); }
    friend Lanes sqrt(Lanes a) { return map([&](int i) { return std::sqrt(a.v[i]); }); }
    friend Lanes abs(Lanes a) { return map([&](int i) { return std::fabs(a.v[i]); }); }
    friend Lanes copysign(Lanes a, Lanes b) { return map([&](int i) { return std::copysign(a.v[i], b.v[i]); }); }
    friend Lanes select(Lanes m, Lanes a, Lanes b) { return map([&](int i) { return isSet(m.v[i]) ? a.v[i] : b.v[i]; }); }
    friend int movemask(Lanes m)
    {
        int r = 0;
        for (int i = 0; i < 4; ++i)
            r |= static_cast<int>(std::bit_cast<std::uint32_t>(m.v[i]) >> 31) << i;
        return r;
    }
    friend Lanes horizontalMin(Lanes a)
    {
        const float m = std::fmin(std::fmin(a.v[0], a.v[1]), std::fmin(a.v[2], a.v[3]));
        return Lanes(m);
    }
    float operator[](int i) const { return v[i]; }
};
#endif
} // namespace rt::cpu
