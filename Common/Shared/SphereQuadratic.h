// The constant term c = |f|^2 - r^2 of the ray-sphere quadratic (f = ray origin - centre), written once for
// both engines (Shared/ShaderLang.h). Near the surface of a huge sphere, |f|^2 and r^2 are nearly equal
// (a 1e6-radius ground seen from 1.5 units above: both ~1e12, c ~3e6): float's rounding of them (~1e5)
// put c, and the hit distance with it, a few % off, and the ground's lighting with it (tests/Cpu/StressTest.cpp
// StressGroundSphere). Where c cancels, it is evaluated with exact products (Dekker's split) and exact
// sums (Knuth's TwoSum), whose rounding errors are carried and added last: correct to a few ulps of c.
// (T. J. Dekker, "A floating-point technique for extending the available precision", Numerische Mathematik
// 18, 1971; D. E. Knuth, TAOCP vol. 2, §4.2.2.) f itself is as exact as o - centre rounds.
#ifndef RT_SHARED_SPHERE_QUADRATIC_H
#define RT_SHARED_SPHERE_QUADRATIC_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Below this |c| / (|f|^2 + r^2), float's c has lost more than ~1e-4 of itself: take the exact path.
RT_CONST(float, kSphereCancellation, 1.0f / 1024.0f)

/// gamma(8) = 8u / (1 - 8u), u = 2^-24: the rounding error of float's c = f.f - r^2 (with f = o - centre
/// rounded too), relative to f.f + r^2 (Pharr, Jakob & Humphreys, PBR 4th ed. §6.8). A root nearer 0 than
/// this error over |q| cannot be told from 0; a float c larger than it has a sure sign.
RT_CONST(float, kSphereRootError, 4.7684e-7f)

/// a * a = hi + lo exactly (Dekker's product through Veltkamp's split by 2^12 + 1); |a| < 1e34. Not the fused
/// multiply-add's error of the product: Vulkan lets fma() round its product (lavapipe does), which lost the
/// exactness there (GpuStressGround).
RT_FN vec2 exactSquare(float a)
{
    RT_PRECISE float split = 4097.0f * a;
    RT_PRECISE float hi = split - (split - a);
    RT_PRECISE float lo = a - hi;
    RT_PRECISE float p = a * a;
    RT_PRECISE float e = ((hi * hi - p) + 2.0f * hi * lo) + lo * lo;
    return vec2(p, e);
}

/// s + t = sum + error exactly (Knuth's TwoSum): returns (sum, error).
RT_FN vec2 exactSum(float s, float t)
{
    RT_PRECISE float sum = s + t;
    RT_PRECISE float tPart = sum - s;
    RT_PRECISE float error = (s - (sum - tPart)) + (t - tPart);
    return vec2(sum, error);
}

/// c = dot(f, f) - r * r, to a few ulps of c even where the two terms nearly cancel.
RT_FN float sphereQuadraticC(vec3 f, float r)
{
    const float ff = dot(f, f);
    const float rr = r * r;
    const float c = ff - rr;
    if (abs(c) >= kSphereCancellation * (ff + rr))
        return c;
    const vec2 x = exactSquare(f.x);
    const vec2 y = exactSquare(f.y);
    const vec2 z = exactSquare(f.z);
    const vec2 r2 = exactSquare(r);
    vec2 s = exactSum(x.x, y.x);
    RT_PRECISE float lost = s.y + x.y + y.y;
    s = exactSum(s.x, z.x);
    lost += s.y + z.y;
    s = exactSum(s.x, -r2.x);
    lost += s.y - r2.y;
    return s.x + lost;
}

/// c for the near root c / q of the ray-sphere quadratic (q = -(b + sign(b) sqrt(a disc)), the far root q / a
/// needs no c): sphereQuadraticC's exact path only where the near root lies surely ahead of the ray, that is
/// where float's c is larger than its rounding error, kSphereRootError (f.f + r^2), and of q's sign. Elsewhere
/// float's c serves:
/// - with a sure sign opposite to q's, the near root is behind the ray with either c;
/// - within its rounding error, the ray's origin cannot be told from the sphere's surface, and the near root
///   c / q lies within the bound under which the intersection tests reject a root as the surface the ray
///   leaves (kSphereRootError (f.f + r^2) / |q|): the ray leaves the surface, and only its far root counts
///   (so also for a ray from another surface that starts that close to the sphere).
/// That is nearly every ray leaving a sphere (each bounce off a ground sphere, each refraction through glass),
/// which took the exact path when the rule was "unless surely behind": 10 % of rtow-default's sphere tests, now
/// 0.8 % (docs/notebook/PERFORMANCE.md §8.7). There the exact c puts the near root within twice that bound: a root
/// between the bound and twice it, which the exact c accepted, is now taken for the surface the ray leaves, on
/// both engines alike.
RT_FN float sphereQuadraticCForNearRoot(vec3 f, float r, float q)
{
    const float ff = dot(f, f);
    const float rr = r * r;
    const float c = ff - rr;
    const bool nearRootAhead = (c > 0.0f && q > 0.0f) || (c < 0.0f && q < 0.0f);
    return abs(c) > kSphereRootError * (ff + rr) && nearRootAhead ? sphereQuadraticC(f, r) : c;
}

RT_SHADER_NAMESPACE_END

#endif
