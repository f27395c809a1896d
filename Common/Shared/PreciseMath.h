// Transcendental functions to float's precision on every device, for the samplers whose results depend on
// them directly (both engines, Shared/ShaderLang.h). Vulkan bounds GLSL's built-ins loosely: sin and cos to an
// absolute 2^-11 on [-pi, pi], asin, acos and atan inherited from atan's 4096 ulp. Measured: lavapipe's acos
// moved the spherical rectangle's solid angle by 1e-3, NVIDIA's sin a grazing triangle's pdf by 1.5e-3, and
// lavapipe's trigonometry the projected cap's crescent samples by 1e-3 (a chi-square rejected at p = 1e-84).
// In C++ sin, cos and atan are the standard library's (correctly rounded to a few ulps), in float or double; acos
// is one polynomial in both languages.
#ifndef RT_SHARED_PRECISE_MATH_H
#define RT_SHARED_PRECISE_MATH_H

#include "Shared/ShaderLang.h"

#ifdef __cplusplus
namespace rt::shader
{
inline float preciseSin(float x) { return std::sin(x); }
inline double preciseSin(double x) { return std::sin(x); }
inline float preciseCos(float x) { return std::cos(x); }
inline double preciseCos(double x) { return std::cos(x); }
inline float preciseAtan(float y, float x) { return std::atan2(y, x); }
inline double preciseAtan(double y, double x) { return std::atan2(y, x); }
} // namespace rt::shader
#else
/// sin(x) for x in [-2 pi, 2 pi]: the Taylor series to x^13 after reduction to [-pi/2, pi/2] (truncation below
/// 7e-10), relative precision kept near 0.
float preciseSin(float x)
{
    if (x > kPi)
        x -= 2.0 * kPi;
    else if (x < -kPi)
        x += 2.0 * kPi;
    if (x > 0.5 * kPi)
        x = kPi - x;
    else if (x < -0.5 * kPi)
        x = -kPi - x;
    float x2 = x * x;
    return x * (1.0 + x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0 +
                x2 * (-1.0 / 39916800.0 + x2 * (1.0 / 6227020800.0)))))));
}

/// cos(x) for x in [-3 pi / 2, 5 pi / 2], as sin(pi / 2 - x).
float preciseCos(float x)
{
    return preciseSin(0.5 * kPi - x);
}

/// atan(y / x) in (-pi, pi], GLSL's two-argument atan: the ratio r = min / max of |x| and |y| in [0, 1],
/// reduced to |r'| <= tan(pi / 12) by atan(r) = pi / 6 + atan((sqrt(3) r - 1) / (r + sqrt(3))), then the
/// odd Taylor series to r'^15 (truncation below 1e-10); relative precision kept near 0.
float preciseAtan(float y, float x)
{
    const float ax = abs(x);
    const float ay = abs(y);
    const float big = max(ax, ay);
    if (!(big > 0.0))
        return 0.0;
    float r = min(ax, ay) / big;
    float offset = 0.0;
    if (r > 0.26794919)
    {
        r = (1.7320508 * r - 1.0) / (r + 1.7320508);
        offset = kPi / 6.0;
    }
    const float r2 = r * r;
    float a = offset + r * (1.0 + r2 * (-1.0 / 3.0 + r2 * (1.0 / 5.0 + r2 * (-1.0 / 7.0 + r2 * (1.0 / 9.0 +
              r2 * (-1.0 / 11.0 + r2 * (1.0 / 13.0 + r2 * (-1.0 / 15.0))))))));
    if (ay > ax)
        a = 0.5 * kPi - a;
    if (x < 0.0)
        a = kPi - a;
    return y < 0.0 ? -a : a;
}

#endif

RT_SHADER_NAMESPACE_BEGIN

/// acos(x) for x in [-1, 1] to 2e-8 absolute (Abramowitz & Stegun 4.4.46: sqrt(1 - |x|) times a degree-7
/// polynomial), the same in both languages, so that the engines compute the spherical rectangle's four angles
/// alike (and the CPU without a libm call: rt_bench SampleLight).
RT_FN float preciseAcos(float x)
{
    const float a = min(abs(x), 1.0f);
    // Estrin's scheme: three levels of independent products where Horner's chains seven, which the CPU waits for.
    const float a2 = a * a;
    const float a4 = a2 * a2;
    const float p01 = 1.5707963050f - 0.2145988016f * a;
    const float p23 = 0.0889789874f - 0.0501743046f * a;
    const float p45 = 0.0308918810f - 0.0170881256f * a;
    const float p67 = 0.0066700901f - 0.0012624911f * a;
    const float p = (p01 + a2 * p23) + a4 * (p45 + a2 * p67);
    const float r = sqrt(1.0f - a) * p;
    return x < 0.0f ? kPi - r : r;
}

RT_SHADER_NAMESPACE_END

#endif
