// A sphere light's cap of directions projected orthographically onto the tangent plane of a receiver, cut by
// its horizon, and sampled uniformly there: the projected-solid-angle sampler of Ureña & Georgiev 2018
// ("Stratified Sampling of Projected Spherical Caps", EGSR), both engines (Shared/ShaderLang.h).
//
// Frame: n the receiver's unit normal, x the unit horizontal direction towards the sphere's centre, y = n x x;
// the centre is at elevation beta over the horizon, the cap's angular radius alpha (sin alpha = R / d).
// The cap's rim projects to an ellipse centred at cos(alpha) cos(beta) along x, semi-axes sin(alpha) |sin(beta)|
// along x and sin(alpha) along y (§3). What the horizon leaves of the cap projects to:
//   - beta >= alpha (whole): the ellipse;
//   - 0 <= beta < alpha (clipped): the ellipse left of the chord x = x_t = cos(alpha) / cos(beta), where its rim
//     touches the unit circle (the horizon), joined to the disk's segment right of that chord (§4.2); the same
//     region is the whole ellipse and the crescent of -beta side by side, which is how it is sampled;
//   - -alpha < beta < 0 (crescent): the disk's segment right of the chord less the ellipse there;
//   - beta <= -alpha: nothing.
// Its area F is the cap's projected solid angle (the irradiance of a unit-radiance sphere), and a point uniform
// over it, lifted to the hemisphere, is a direction of solid-angle density cos / F. The ellipse is sampled by
// the concentric map scaled to it; the crescent is swept along x (the paper's "parallel" map): u1 picks the
// abscissa by inverting the swept area, u2 the ordinate uniformly over the region's chord there, so the map of
// the unit square is area-preserving and monotone in each coordinate (stratification survives). The sweep's areas are disk and ellipse segments
// (diskSegmentArea), inverted by Newton's method.
//
// Closed forms written for float32 (research notes §0.2): with s = |sin beta|, q = sqrt(sin^2 alpha - s^2) (the
// horizon chord's half-length times cos beta) and u = q / cos alpha, the crescent's area is
//   G = sin^2(alpha) s f(u / s) - f(u),   f(w) = w - atan(w),
// and the clipped shape's is pi sin^2(alpha) sin(beta) + G (the whole cap's signed projected area, pi sin^2 alpha
// sin beta, plus what lies below the horizon reflected up, which is the crescent of -beta). Both sums are of
// terms of the same order as G except as beta -> -alpha, where a series in (u / s)^2 with positive
// coefficients takes over (crescentArea). Relative error in float below 3e-4 from beta = -0.999 alpha up, for
// alpha from 1e-3 to 1.4 rad, against float64 (ProjectedCapTest). Trigonometry is Shared/PreciseMath.h's:
// the GPU's built-ins moved the crescent's samples by 1e-3.
#ifndef RT_SHARED_LIGHTS_PROJECTED_CAP_H
#define RT_SHARED_LIGHTS_PROJECTED_CAP_H

#include "Shared/HostDevice.h"
#include "Shared/Onb.h"
#include "Shared/PreciseMath.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

RT_CONST(uint, kCapNotApplicable, 0u) // no receiver (a medium) or p inside the sphere: not this sampler's case
RT_CONST(uint, kCapBelow, 1u)         // the whole cap under the horizon: no direction to sample
RT_CONST(uint, kCapWhole, 2u)         // the ellipse
RT_CONST(uint, kCapClipped, 3u)       // ellipse part and disk segment, 0 <= beta < alpha
RT_CONST(uint, kCapCrescent, 4u)      // disk segment less the ellipse, -alpha < beta < 0

struct ProjectedCap
{
    vec3 x;             // unit, horizontal, towards the centre
    vec3 y;             // n x x
    float sinAlpha;
    float cosAlpha;
    float sinBeta;      // n . (unit direction to the centre)
    float cosBeta;
    float tangentTheta; // the horizon chord x_t = cos(tangentTheta); the disk segment beyond it has half-angle
                        // tangentTheta
    float ellipseTheta; // the same chord in the ellipse's coordinate: (x_t - centre) / semi-axis = cos(ellipseTheta)
    float area;         // F, the projected solid angle of the visible cap, sr
    uint kind;          // kCap*
};

/// Area of the unit disk's segment beyond the chord at cos(theta), theta in [0, pi]: theta - sin(theta) cos(theta),
/// by its Taylor series below 0.5 (where the difference loses up to 5 digits), in float to 1e-6 relative.
RT_FN float diskSegmentArea(float theta)
{
    if (theta < 0.5f)
    {
        // theta - sin(2 theta) / 2 = sum_k (-1)^(k+1) w^(2k+1) / (2 (2k+1)!), w = 2 theta; the next term is
        // below 1e-9 of the first at theta = 0.5.
        const float w = 2.0f * theta;
        const float w2 = w * w;
        return w * w2 *
               (1.0f / 12.0f -
                w2 * (1.0f / 240.0f - w2 * (1.0f / 10080.0f - w2 * (1.0f / 725760.0f - w2 * (1.0f / 79833600.0f)))));
    }
    return theta - 0.5f * preciseSin(2.0f * theta);
}

/// w - atan(w) for w >= 0, by its series below 0.5.
RT_FN float capCubicRemainder(float w)
{
    if (w < 0.5f)
    {
        const float w2 = w * w;
        float sum = 0.0f;
        float power = w * w2;
        float sign = 1.0f;
        RT_DONT_UNROLL for (int k = 1; k <= 12; ++k) // (1/2)^24 / 25: float's precision
        {
            const float term = power / float(2 * k + 1);
            sum += sign * term;
            if (term <= 1e-8f * sum) // alternating, decreasing: the rest is below this term
                break;
            power *= w2;
            sign = -sign;
        }
        return sum;
    }
    return w - preciseAtan(w, 1.0f);
}

/// The crescent's area G(alpha, |beta|) of the header, for 0 <= s = |sin beta| < sin alpha.
RT_FN float crescentArea(float sinAlpha, float cosAlpha, float s)
{
    const float q2 = max((sinAlpha - s) * (sinAlpha + s), 0.0f);
    const float u = sqrt(q2) / cosAlpha;
    if (u < 0.5f * s)
    {
        // G = sum_k (-1)^(k+1) u (u/s)^(2k) D_k / (2k+1), D_k = sin^2 alpha - s^(2k) = q^2 + cos^2 beta (s^2 + ...
        // + s^(2k-2)): both f's expanded, the cancellation between them done exactly (D_1 = q^2).
        const float r2 = (u / s) * (u / s);
        const float cosBeta2 = 1.0f - s * s;
        float d = q2;
        float sPower = s * s;
        float rPower = r2;
        float sum = 0.0f;
        float sign = 1.0f;
        RT_DONT_UNROLL for (int k = 1; k <= 14; ++k) // r^2 < 1/4: (1/4)^12 below float's precision of the first terms
        {
            const float term = u * rPower * d / float(2 * k + 1);
            sum += sign * term;
            if (k > 2 && term <= 1e-8f * abs(sum)) // the first two terms may nearly cancel; then each is 1/4 of the last
                break;
            d += sPower * cosBeta2;
            sPower *= s * s;
            rPower *= r2;
            sign = -sign;
        }
        return sum;
    }
    // s f(u / s) = u - s atan(u / s), without the division for s -> 0.
    return sinAlpha * sinAlpha * (u - s * preciseAtan(u, s)) - capCubicRemainder(u);
}

/// The cap of a sphere light (centre light.p0, radius light.radius) seen from p over the horizon of the unit receiver
/// normal n (0: none, a medium). Sets every field; returns cap.kind.
RT_FN uint projectedCap(RT_IN(LightData) light, vec3 p, vec3 n, RT_OUT(ProjectedCap) cap)
{
    const vec3 toCenter = light.p0 - p;
    const float d = length(toCenter);
    const vec3 axis = toCenter / d;
    cap.x = vec3(1.0f, 0.0f, 0.0f);
    cap.y = vec3(0.0f, 1.0f, 0.0f);
    cap.sinAlpha = light.radius / d;
    cap.cosAlpha = safeSqrt(1.0f - cap.sinAlpha * cap.sinAlpha);
    cap.sinBeta = dot(n, axis);
    cap.cosBeta = 1.0f;
    cap.tangentTheta = 0.0f;
    cap.ellipseTheta = 0.0f;
    cap.area = 0.0f;
    cap.kind = kCapNotApplicable;
    if (!(cap.sinAlpha < 1.0f) || !(lengthSquared(n) > 0.0f))
        return cap.kind;
    if (!(cap.sinBeta > -cap.sinAlpha))
    {
        cap.kind = kCapBelow;
        return cap.kind;
    }
    const vec3 horizontal = axis - cap.sinBeta * n;
    const float h = length(horizontal);
    cap.cosBeta = h;
    // Straight overhead the ellipse is a circle about the normal: any horizontal axis will do.
    cap.x = h > 1e-6f ? horizontal / h : onbFromNormal(n).u;
    cap.y = cross(n, cap.x);
    if (cap.sinBeta >= cap.sinAlpha)
    {
        cap.kind = kCapWhole;
        cap.area = kPi * cap.sinAlpha * cap.sinAlpha * cap.sinBeta;
        return cap.kind;
    }
    // The horizon chord: x_t = cos(alpha) / cos(beta), y_t = q / cos(beta), so tan(tangentTheta) = q / cos alpha;
    // in the ellipse's coordinate (x_t - centre) / semi-axis = cos(alpha) s / (cos(beta) sin(alpha)) and the
    // matching sine q / (cos(beta) sin(alpha)).
    const float s = abs(cap.sinBeta);
    const float q = safeSqrt((cap.sinAlpha - s) * (cap.sinAlpha + s));
    cap.tangentTheta = preciseAtan(q, cap.cosAlpha);
    cap.ellipseTheta = preciseAtan(q, cap.cosAlpha * s);
    cap.kind = cap.sinBeta >= 0.0f ? kCapClipped : kCapCrescent;
    cap.area = crescentArea(cap.sinAlpha, cap.cosAlpha, s) +
               (cap.kind == kCapClipped ? kPi * cap.sinAlpha * cap.sinAlpha * cap.sinBeta : 0.0f);
    return cap.kind;
}

/// The least height of a sampled direction over the horizon, relative to its distance from the normal: where
/// the region meets the horizon (the crescent's tips) float rounds the true height, of the
/// order of float's precision there, to 0, and a direction with cos = 0 has pdf 0, a dropped sample (0.1 % of
/// the samples at beta = -0.99 alpha). Lifted by at most this, it keeps pdf = cos / F and so its estimate
/// L cos / pdf = L F.
RT_CONST(float, kMinCapLift, 1e-6f)

/// The hemisphere's direction over the point (centre + sin(alpha) sin(beta) ex, sin(alpha) ey) of the
/// ellipse's interior, (ex, ey) in the unit disk; its height z = sqrt(1 - x^2 - y^2) rewritten as
/// (cos(alpha) sin(beta) - sin(alpha) cos(beta) ex)^2 + sin^2(alpha) (1 - ex^2 - ey^2), a sum of non-negative
/// terms (the direct form loses all precision for small caps near the horizon).
RT_FN vec3 liftEllipsePoint(RT_IN(ProjectedCap) cap, vec3 n, float ex, float ey)
{
    const float x = cap.cosAlpha * cap.cosBeta + cap.sinAlpha * cap.sinBeta * ex;
    const float y = cap.sinAlpha * ey;
    const float rim = cap.cosAlpha * cap.sinBeta - cap.sinAlpha * cap.cosBeta * ex;
    const float z = sqrt(rim * rim + cap.sinAlpha * cap.sinAlpha * max(1.0f - ex * ex - ey * ey, 0.0f));
    return normalize(x * cap.x + y * cap.y + z * n);
}

/// The crescent's area right of the chord at cos(theta), theta in [0, tangentTheta]: the disk's segment less
/// the ellipse's part there, (x - centre) / semi-axis = cos(thetaE).
RT_FN float crescentSweptArea(RT_IN(ProjectedCap) cap, float theta, RT_OUT(float) ellipseHeight)
{
    const float semiAxis = cap.sinAlpha * abs(cap.sinBeta);
    // x - centre from 1 - centre and 1 - x, each without cancellation.
    const float oneMinusCentre = (cap.sinAlpha * cap.sinAlpha + cap.cosAlpha * cap.cosAlpha * cap.sinBeta * cap.sinBeta) /
                                 (1.0f + cap.cosAlpha * cap.cosBeta);
    const float sinHalf = preciseSin(0.5f * theta);
    const float t = semiAxis > 0.0f ? (oneMinusCentre - 2.0f * sinHalf * sinHalf) / semiAxis : 2.0f;
    const float tc = clamp(t, -1.0f, 1.0f);
    ellipseHeight = t < 1.0f ? cap.sinAlpha * safeSqrt(1.0f - tc * tc) : 0.0f;
    const float ellipsePart = t < 1.0f ? semiAxis * cap.sinAlpha * diskSegmentArea(preciseAcos(tc)) : 0.0f;
    return diskSegmentArea(theta) - ellipsePart;
}

/// A direction uniform over the projected cap (density cos / cap.area per unit solid angle) for u in [0,1)^2;
/// cap.kind is kCapWhole, kCapClipped or kCapCrescent.
RT_FN vec3 sampleProjectedCap(RT_IN(ProjectedCap) cap, vec3 n, vec2 u)
{
    if (cap.kind == kCapWhole)
    {
        // The concentric map scaled to the ellipse: area-preserving, so stratification survives.
        const vec2 disk = sampleUniformDiskConcentric(u);
        return liftEllipsePoint(cap, n, disk.x, disk.y);
    }
    // The clipped shape is the whole ellipse and the crescent side by side: right of the horizon chord the disk's
    // segment is all visible, and that segment is the ellipse's part there and the crescent of -beta, whose shape
    // does not depend on beta's sign (its area is the G of the header: F = pi sin^2(alpha) sin(beta) + G). u.x
    // picks one of the two by area; the ellipse takes the concentric map, so only the crescent needs a sweep.
    float crescent = cap.area;
    float ux = u.x;
    if (cap.kind == kCapClipped)
    {
        const float ellipseArea = kPi * cap.sinAlpha * cap.sinAlpha * cap.sinBeta;
        const float picked = u.x * cap.area;
        if (picked < ellipseArea)
        {
            const vec2 disk = sampleUniformDiskConcentric(vec2(min(picked / ellipseArea, 0.99999994f), u.y));
            return liftEllipsePoint(cap, n, disk.x, disk.y);
        }
        crescent = cap.area - ellipseArea;
        ux = min((picked - ellipseArea) / crescent, 0.99999994f);
    }
    // The crescent, swept from the disk's edge inwards: its area right of cos(theta) increases with theta, with
    // derivative 2 sin(theta) (sin(theta) - ellipse height); Newton's method kept inside a shrinking bracket
    // (bisection where a step leaves it).
    const float target = ux * crescent;
    float lo = 0.0f;
    float hi = cap.tangentTheta;
    float theta = 0.5f * (lo + hi);
    float ellipseHeight = 0.0f;
    RT_DONT_UNROLL for (int i = 0; i < 24; ++i)
    {
        const float residual = crescentSweptArea(cap, theta, ellipseHeight) - target;
        if (residual > 0.0f)
            hi = theta;
        else
            lo = theta;
        const float slope = 2.0f * preciseSin(theta) * (preciseSin(theta) - ellipseHeight);
        float next = slope > 0.0f ? theta - residual / slope : 0.5f * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5f * (lo + hi);
        // Float's Newton can cycle between neighbours instead of settling: a step below 1e-7 of the bracket ends
        // it (the GPU's warps wait for their slowest thread).
        const bool converged = abs(next - theta) <= 1e-7f * cap.tangentTheta;
        theta = next;
        if (converged)
            break;
    }
    crescentSweptArea(cap, theta, ellipseHeight);
    // Over the chord at cos(theta) the crescent is ellipseHeight <= |y| <= sin(theta): u.y picks the side, and
    // within it the distance from the ellipse (w in [0, 1), so the horizon, z = 0, is never reached; z from the
    // distance to the circle, not from a difference of near-equal squares).
    const float sinTheta = preciseSin(theta);
    const float outer = max(sinTheta - ellipseHeight, 0.0f);
    const float side = u.y < 0.5f ? -1.0f : 1.0f;
    const float w = u.y < 0.5f ? 2.0f * u.y : 2.0f * u.y - 1.0f;
    const float yAbs = ellipseHeight + outer * w;
    const float z = max(sqrt(outer * (1.0f - w) * (sinTheta + yAbs)), kMinCapLift * sinTheta);
    return normalize(preciseCos(theta) * cap.x + side * yAbs * cap.y + z * n);
}

RT_SHADER_NAMESPACE_END

#endif
