// Four floats processed together: SSE where the compiler targets x86, plain loops elsewhere. Just the
// operations the packet tests need; comparisons give lane masks (all bits set where true).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__) || defined(_M_X64)
#include <immintrin.h>
#define RT_SIMD4_SSE 1
#endif

namespace rt::cpu
{
#ifdef RT_SIMD4_SSE
struct F4
{
    __m128 v;

    F4() = default;
    F4(__m128 x) : v(x) {}
    explicit F4(float x) : v(_mm_set1_ps(x)) {}
    static F4 load(const float* p) { return _mm_load_ps(p); }
    void store(float* p) const { _mm_store_ps(p, v); }

    friend F4 operator+(F4 a, F4 b) { return _mm_add_ps(a.v, b.v); }
    friend F4 operator-(F4 a, F4 b) { return _mm_sub_ps(a.v, b.v); }
    friend F4 operator*(F4 a, F4 b) { return _mm_mul_ps(a.v, b.v); }
    friend F4 operator/(F4 a, F4 b) { return _mm_div_ps(a.v, b.v); }
    friend F4 operator-(F4 a) { return _mm_xor_ps(a.v, _mm_set1_ps(-0.0f)); }
    friend F4 operator<(F4 a, F4 b) { return _mm_cmplt_ps(a.v, b.v); }
    friend F4 operator<=(F4 a, F4 b) { return _mm_cmple_ps(a.v, b.v); }
    friend F4 operator>(F4 a, F4 b) { return _mm_cmpgt_ps(a.v, b.v); }
    friend F4 operator>=(F4 a, F4 b) { return _mm_cmpge_ps(a.v, b.v); }
    friend F4 operator==(F4 a, F4 b) { return _mm_cmpeq_ps(a.v, b.v); }
    friend F4 operator&(F4 a, F4 b) { return _mm_and_ps(a.v, b.v); }
    friend F4 operator|(F4 a, F4 b) { return _mm_or_ps(a.v, b.v); }
    friend F4 andNot(F4 mask, F4 b) { return _mm_andnot_ps(mask.v, b.v); } // ~mask & b
    friend F4 min(F4 a, F4 b) { return _mm_min_ps(a.v, b.v); }
    friend F4 max(F4 a, F4 b) { return _mm_max_ps(a.v, b.v); }
    friend F4 sqrt(F4 a) { return _mm_sqrt_ps(a.v); }
    friend F4 abs(F4 a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a.v); }
    /// Magnitude of a with the sign of b.
    friend F4 copysign(F4 a, F4 b)
    {
        const __m128 sign = _mm_set1_ps(-0.0f);
        return _mm_or_ps(_mm_andnot_ps(sign, a.v), _mm_and_ps(sign, b.v));
    }
    /// mask ? a : b, lane by lane.
    friend F4 select(F4 mask, F4 a, F4 b) { return _mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v)); }
    friend int movemask(F4 mask) { return _mm_movemask_ps(mask.v); }
    /// Smallest lane, broadcast to every lane.
    friend F4 horizontalMin(F4 a)
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
struct F4
{
    float v[4];

    F4() = default;
    explicit F4(float x) : v{x, x, x, x} {}
    static F4 load(const float* p) { return F4::map([&](int i) { return p[i]; }); }
    void store(float* p) const
    {
        for (int i = 0; i < 4; ++i)
            p[i] = v[i];
    }
    template <typename Fn>
    static F4 map(Fn&& fn)
    {
        F4 r;
        for (int i = 0; i < 4; ++i)
            r.v[i] = fn(i);
        return r;
    }
    static float maskOf(bool b) { return std::bit_cast<float>(b ? 0xFFFFFFFFu : 0u); }
    static bool isSet(float m) { return std::bit_cast<std::uint32_t>(m) != 0; }

    friend F4 operator+(F4 a, F4 b) { return map([&](int i) { return a.v[i] + b.v[i]; }); }
    friend F4 operator-(F4 a, F4 b) { return map([&](int i) { return a.v[i] - b.v[i]; }); }
    friend F4 operator*(F4 a, F4 b) { return map([&](int i) { return a.v[i] * b.v[i]; }); }
    friend F4 operator/(F4 a, F4 b) { return map([&](int i) { return a.v[i] / b.v[i]; }); }
    friend F4 operator-(F4 a) { return map([&](int i) { return -a.v[i]; }); }
    friend F4 operator<(F4 a, F4 b) { return map([&](int i) { return maskOf(a.v[i] < b.v[i]); }); }
    friend F4 operator<=(F4 a, F4 b) { return map([&](int i) { return maskOf(a.v[i] <= b.v[i]); }); }
    friend F4 operator>(F4 a, F4 b) { return map([&](int i) { return maskOf(a.v[i] > b.v[i]); }); }
    friend F4 operator>=(F4 a, F4 b) { return map([&](int i) { return maskOf(a.v[i] >= b.v[i]); }); }
    friend F4 operator==(F4 a, F4 b) { return map([&](int i) { return maskOf(a.v[i] == b.v[i]); }); }
    friend F4 operator&(F4 a, F4 b) { return map([&](int i) { return maskOf(isSet(a.v[i]) && isSet(b.v[i])); }); }
    friend F4 operator|(F4 a, F4 b) { return map([&](int i) { return maskOf(isSet(a.v[i]) || isSet(b.v[i])); }); }
    friend F4 andNot(F4 m, F4 b) { return map([&](int i) { return isSet(m.v[i]) ? 0.0f : b.v[i]; }); }
    friend F4 min(F4 a, F4 b) { return map([&](int i) { return a.v[i] < b.v[i] ? a.v[i] : b.v[i]; }); }
    friend F4 max(F4 a, F4 b) { return map([&](int i) { return a.v[i] > b.v[i] ? a.v[i] : b.v[i]; }); }
    friend F4 sqrt(F4 a) { return map([&](int i) { return std::sqrt(a.v[i]); }); }
    friend F4 abs(F4 a) { return map([&](int i) { return std::fabs(a.v[i]); }); }
    friend F4 copysign(F4 a, F4 b) { return map([&](int i) { return std::copysign(a.v[i], b.v[i]); }); }
    friend F4 select(F4 m, F4 a, F4 b) { return map([&](int i) { return isSet(m.v[i]) ? a.v[i] : b.v[i]; }); }
    friend int movemask(F4 m)
    {
        int r = 0;
        for (int i = 0; i < 4; ++i)
            r |= (std::bit_cast<std::uint32_t>(m.v[i]) >> 31) << i;
        return r;
    }
    friend F4 horizontalMin(F4 a)
    {
        const float m = std::fmin(std::fmin(a.v[0], a.v[1]), std::fmin(a.v[2], a.v[3]));
        return F4(m);
    }
    float operator[](int i) const { return v[i]; }
};
#endif
} // namespace rt::cpu
