// Sampling directions towards one light of the scene's world-space light list, and the solid-angle pdf of
// any direction under that strategy, written once for both engines (Shared/ShaderLang.h). Both are needed
// by the book-3 mixture (RTTROYL §9-12): the pdf of a direction must be evaluated for every light, whichever
// strategy produced the direction; and by NEE + MIS, for the emitter a BSDF ray hits.
// Two families: book 3's (sampleLight / lightPdf without a sampler: cones for spheres seen from outside,
// area otherwise), which the mixture uses, and NEE's, chosen by a LightSampler (HostDevice.h).
//
// Conventions: `p` is the shading point (world space), `wi` a unit direction leaving p, pdfs are per unit
// solid angle at p. A pdf is 0 for a direction that cannot be produced (misses the light), never a guess.
#ifndef RT_SHARED_LIGHT_SAMPLING_H
#define RT_SHARED_LIGHT_SAMPLING_H

#include "Shared/HostDevice.h"
#include "Shared/Onb.h"
#include "Shared/ShaderLang.h"
#include "Shared/SphericalRectangle.h"
#include "Shared/SphericalTriangle.h"
#include "Shared/Warps.h"

// Whether the code must handle lights of a shape: always in C++; in the shaders a specialization constant
// (Shaders/Specialization.glsl defines the macro first), false where the pipeline was compiled for a scene
// without that shape, and the driver then drops that shape's code.
#ifndef RT_HAS_LIGHT_SHAPE
#define RT_HAS_LIGHT_SHAPE(Shape) true
#endif
/// shape == LightShape::Shape, false at compile time where the pipeline has no light of that shape.
#define RT_LIGHT_IS(shape, Shape) (RT_HAS_LIGHT_SHAPE(Shape) && (shape) == RT_ENUM(LightShape, Shape))

RT_SHADER_NAMESPACE_BEGIN

struct LightSample
{
    vec3 wi; // unit direction from p towards the sampled point
    float pdf; // per unit solid angle
    vec3 point; // the sampled point y on the light (world space)
    float distance; // |y - p|
    vec3 normal; // unit normal of the light at y, on its front side (outward for spheres)
    vec2 uv; // the light's surface coordinates at y: (a, b) of quads, barycentrics (b1, b2) of triangles, 0 on spheres
};

/// Area-measure pdf 1/area turned into solid angle at squared distance `dist2` with |cos| at the light.
RT_FN float areaToSolidAngle(float dist2, float cosLight, float area)
{
    return cosLight > 0.0f ? dist2 / (cosLight * area) : 0.0f;
}

/// Sphere seen from p: true if p is outside (cone sampling applies), with 1 - cos(theta_max), cos(theta_max)
/// and the unit axis towards the centre.
RT_FN bool sphereCone(RT_IN(LightData) s, vec3 p, RT_OUT(float) oneMinusCos, RT_OUT(float) cosThetaMax,
                      RT_OUT(vec3) axis)
{
    const vec3 toCenter = s.p0 - p;
    const float d2 = lengthSquared(toCenter);
    const float r2 = s.radius * s.radius;
    oneMinusCos = 0.0f;
    cosThetaMax = 1.0f;
    axis = vec3(0.0f, 0.0f, 1.0f);
    if (d2 <= r2 * 1.00001f)
        return false;
    const float sin2 = r2 / d2;
    cosThetaMax = safeSqrt(1.0f - sin2);
    oneMinusCos = sin2 / (1.0f + cosThetaMax); // = 1 - cos without cancellation (research notes §1.2)
    axis = toCenter / sqrt(d2);
    return true;
}

/// lightPdf of a sphere seen from outside, from sphereCone's cone: uniform over the cone, 0 outside it.
RT_FN float conePdf(float oneMinusCos, vec3 axis, vec3 wi)
{
    // In the cone iff the chord |wi - axis| = sqrt(2 (1 - cos)) is at most the cone's: unlike a float cosine,
    // which moves in steps of 6e-8 near 1 (coarser than a small cone's 1 - cos), the chord keeps its precision
    // at every size. The slack is the rounding of a float unit direction (4 ulps of 1 = 4 / 2^24).
    const bool inside = length(wi - axis) <= sqrt(2.0f * oneMinusCos) + 4.0f / 16777216.0f;
    return inside ? uniformConePdf(oneMinusCos) : 0.0f;
}

/// Near root of the ray p + t wi against a sphere that p is outside of, for wi inside the sphere's cone (a
/// silhouette direction that rounding puts just outside it gets the closest approach instead).
RT_FN float sphereEntryDistance(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = s.p0 - p;
    const float b = dot(f, wi);
    const vec3 l = f - b * wi; // closest approach (Hearn & Baker discriminant, RTG ch. 7)
    return b - safeSqrt(s.radius * s.radius - lengthSquared(l));
}

/// Far root of the ray p + t wi against a sphere that contains p (t > 0 always exists).
RT_FN float sphereExitDistance(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = p - s.p0;
    const float b = dot(f, wi);
    const vec3 l = f - b * wi; // closest approach (Hearn & Baker discriminant, RTG ch. 7)
    const float disc = s.radius * s.radius - lengthSquared(l);
    return -b + safeSqrt(disc);
}

/// Whether the edge coordinates (alpha, beta) lie on the quad ([0, 1]^2) or triangle (alpha, beta >= 0,
/// alpha + beta <= 1), give or take the slacks sa (alpha), sb (beta) and sab (alpha + beta, triangles).
/// Without branches: the mixture evaluates it for every light at every vertex, where a GPU's threads disagree.
RT_FN bool onPlanarLight(RT_TAG(LightShape) shape, float alpha, float beta, float sa, float sb, float sab)
{
    const bool quadInside = alpha <= 1.0f + sa && beta <= 1.0f + sb;
    const bool triangleInside = alpha + beta <= 1.0f + sab;
    return alpha >= -sa && beta >= -sb && (RT_LIGHT_IS(shape, Quad) ? quadInside : triangleInside);
}

/// Parametric hit of the ray p + t wi with the parallelogram / triangle of `light`; returns t or -1.
RT_FN float planarHit(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    // Computed through to one select at the end, without early returns (4 % of book 3's mixture on the H100):
    // a direction along the plane (denom near 0) or away from it (t <= 0, or NaN) gives -1 there.
    const float denom = dot(light.normal, wi);
    const float t = dot(light.normal, light.p0 - p) / denom;
    const bool ahead = abs(denom) >= 1e-9f && t > 0.0f;
    const vec3 planar = p + t * wi - light.p0;
    const float alpha = dot(planar, light.dualU);
    const float beta = dot(planar, light.dualV);
    // A sample on the light's edge must find its own pdf here after rounding (the samplers' pdfs are this
    // one's, or must agree with it). 1e-6 of slack covers a light seen from near by; a point sampled on the
    // edge of a sliver seen from afar comes back from its float direction a few ulps of the distances
    // involved away, more at grazing incidence (the ray slides along the plane by t / cos): 4 ulps of them,
    // turned into edge coordinates by the duals' lengths (1 / the light's heights, stored with the light). The
    // border added has no measure worth a bias: 2e-4 of a 3-unit sliver's height seen across a room. Each
    // slack is at least 1e-6, so this one test accepts whatever a tight test first would: a tight test and a
    // second one behind a branch cost the H100 9 % of book 3's mixture on cornell-box-lights.
    const float slack = 2.4e-7f * (t / abs(denom) + length(p) + light.p0Length);
    const float slackAlpha = 1e-6f + slack * light.dualULength;
    const float slackBeta = 1e-6f + slack * light.dualVLength;
    const float slackSum = 1e-6f + slack * light.dualSumLength;
    return ahead && onPlanarLight(light.shape, alpha, beta, slackAlpha, slackBeta, slackSum) ? t : -1.0f;
}

/// Solid-angle pdf with which sampleLight(light, p, .) produces the unit direction `wi`; 0 if it cannot.
RT_FN float lightPdf(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    if (RT_LIGHT_IS(light.shape, Sphere))
    {
        float oneMinusCos;
        float cosThetaMax;
        vec3 axis;
        if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
            return conePdf(oneMinusCos, axis, wi);
        const float t = sphereExitDistance(light, p, wi);
        if (!(t > 0.0f))
            return 0.0f;
        const vec3 n = (p + t * wi - light.p0) / light.radius;
        const float area = 4.0f * kPi * light.radius * light.radius;
        return areaToSolidAngle(t * t, abs(dot(n, wi)), area);
    }
    if (!RT_HAS_LIGHT_SHAPE(Quad) && !RT_HAS_LIGHT_SHAPE(Triangle))
        return 0.0f; // only spheres: the code below is dead
    const float t = planarHit(light, p, wi);
    if (t < 0.0f)
        return 0.0f;
    return areaToSolidAngle(t * t, abs(dot(light.normal, wi)), light.area);
}

/// Samples a direction from p towards `light` with uniform-area (quad, triangle, sphere seen from inside) or
/// uniform-cone (sphere seen from outside) density. The pdf it returns is lightPdf(light, p, wi) itself, so
/// a sample and the pdf of its direction can never disagree: a direction that rounding puts outside the light
/// (p in the light's own plane, a cone sample on the silhouette) is dropped instead of being weighted by a pdf
/// the mixture's other terms cannot see (that mismatch biased a closed-box furnace by +0.7 %).
/// Returns false when no direction can be produced.
RT_FN bool sampleLight(RT_IN(LightData) light, vec3 p, vec2 u, RT_OUT(LightSample) ls)
{
    ls.wi = vec3(0.0f);
    ls.pdf = 0.0f;
    ls.point = vec3(0.0f);
    ls.distance = 0.0f;
    ls.normal = light.normal;
    ls.uv = vec2(0.0f);
    if (RT_LIGHT_IS(light.shape, Sphere))
    {
        float oneMinusCos;
        float cosThetaMax;
        vec3 axis;
        if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
        {
            ls.wi = onbToWorld(onbFromNormal(axis), sampleUniformCone(u, oneMinusCos));
            ls.pdf = conePdf(oneMinusCos, axis, ls.wi); // = lightPdf(light, p, ls.wi), cone reused
            ls.distance = sphereEntryDistance(light, p, ls.wi);
            ls.normal = normalize(p + ls.distance * ls.wi - light.p0);
            ls.point = light.p0 + light.radius * ls.normal; // re-projected, as the engines' sphere hits are
            return ls.pdf > 0.0f;
        }
        ls.normal = sampleUniformSphere(u);
        ls.point = light.p0 + light.radius * ls.normal;
    }
    else if (RT_LIGHT_IS(light.shape, Quad))
    {
        ls.uv = u;
        ls.point = light.p0 + u.x * light.p1 + u.y * light.p2;
    }
    else if (RT_HAS_LIGHT_SHAPE(Triangle))
    {
        ls.uv = sampleUniformTriangle(u);
        ls.point = light.p0 + ls.uv.x * light.p1 + ls.uv.y * light.p2; // p1, p2 are edges from p0
    }
    else
        return false; // a shape the pipeline has no light of: never reached
    const vec3 w = ls.point - p;
    const float dist2 = lengthSquared(w);
    if (!(dist2 > 0.0f))
        return false;
    ls.distance = sqrt(dist2);
    ls.wi = w / ls.distance;
    ls.pdf = lightPdf(light, p, ls.wi);
    return ls.pdf > 0.0f;
}

/// Below this solid angle (sr) a rectangle is sampled by area: the float sum of four angles minus 2 pi
/// carries an absolute error near 5e-7 sr, 5e-5 of the density here, and a light this small looks the same
/// to both strategies.
RT_CONST(float, kMinSphericalRectangle, 1e-2f)

/// Triangles are sampled by solid angle (Arvo 1995) between these solid angles (sr), by area outside them
/// (pbrt-v4's bounds, §6.5.4): below, a light this small looks the same to both strategies, and float
/// trigonometry of sub-triangles this thin is where GPUs differ most (Vulkan bounds sin and cos to 2^-11
/// absolute only); above, the triangle fills nearly the whole hemisphere and Arvo's denominators approach 0.
RT_CONST(float, kMinSphericalTriangle, 3e-4f)
RT_CONST(float, kMaxSphericalTriangle, 6.22f)

/// A triangle seen from p within the spherical triangle sampler's bounds, set up in `t`.
RT_FN bool sphericalTriangleApplies(RT_IN(LightData) light, vec3 p, RT_OUT(SphericalTriangle) t)
{
    if (!RT_LIGHT_IS(light.shape, Triangle))
        return false;
    t = makeSphericalTriangle(p, light.p0, light.p1, light.p2);
    return t.solidAngle >= Real(kMinSphericalTriangle) && t.solidAngle <= Real(kMaxSphericalTriangle);
}

/// A quad whose edges are orthogonal (to float precision): what spherical-rectangle sampling needs.
RT_FN bool isRectangle(RT_IN(LightData) light)
{
    return RT_LIGHT_IS(light.shape, Quad) &&
           abs(dot(light.p1, light.p2)) <= 1e-5f * length(light.p1) * length(light.p2);
}

/// Near root of the ray p + t wi against a sphere that p is outside of, or -1 when the ray misses it.
RT_FN float sphereNearHit(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = s.p0 - p;
    const float b = dot(f, wi);
    const float disc = s.radius * s.radius - lengthSquared(f - b * wi);
    if (!(disc >= 0.0f) || b <= 0.0f)
        return -1.0f;
    return b - sqrt(disc);
}

/// The cosine to the receiver normal n at the rectangle's four corners, seen from r.o, floored at 0.01 (a
/// corner below the horizon still gets samples near it, where the cosine rises): (w00, w10, w01, w11), the
/// weights of the bilinear warp that makes spherical-rectangle samples follow the cosine (pbrt-v4 §6.5.4,
/// after Hart et al. 2020, "Practical Product Sampling by Fitting and Composing Warps").
RT_FN vec4 rectangleCosineWeights(RT_IN(SphericalRectangle) r, vec3 n)
{
    const vec3 zn = r.z0 * r.z;
    const float w00 = max(dot(n, normalize(r.x0 * r.x + r.y0 * r.y + zn)), 0.01f);
    const float w10 = max(dot(n, normalize(r.x1 * r.x + r.y0 * r.y + zn)), 0.01f);
    const float w01 = max(dot(n, normalize(r.x0 * r.x + r.y1 * r.y + zn)), 0.01f);
    const float w11 = max(dot(n, normalize(r.x1 * r.x + r.y1 * r.y + zn)), 0.01f);
    return vec4(w00, w10, w01, w11);
}

/// The bilinear cosine warp's corner weights for a spherical triangle (pbrt-v4 §6.5.4, after Hart et al.
/// 2020): the cosine to the receiver normal n of the vertex directions, floored at 0.01 as the rectangle's,
/// at the corners of u where Arvo's map puts them: (w00, w10, w01, w11) = (B, B, A, C), since u.y = 0 is
/// the vertex B for every u.x and u.y = 1 runs from A (u.x = 0) to C (u.x = 1). pbrt takes |cos| as its
/// normal may face either way; here n faces the side the receiver takes light from (NEE's BSDF is 0 on the
/// other), so a vertex below its horizon gets the floor, as in rectangleCosineWeights.
RT_FN vec4 triangleCosineWeights(RT_IN(SphericalTriangle) t, vec3 n)
{
    const RealVec3 normal = RealVec3(n);
    const float wa = float(max(dot(normal, t.a), 0.01));
    const float wb = float(max(dot(normal, t.b), 0.01));
    const float wc = float(max(dot(normal, t.c), 0.01));
    return vec4(wb, wb, wa, wc);
}

/// A sphere light seen from p over the horizon of the receiver normal n: the orthographic projection of its
/// cap onto the tangent plane, an ellipse (Ureña & Georgiev 2018, "Stratified Sampling of Projected Spherical
/// Caps", EGSR, §3: centre cos(alpha) cos(beta) along the centre's horizontal direction, semi-axes
/// sin(alpha) sin(beta) along it and sin(alpha) across, with sin(alpha) = R / d and beta the centre's
/// elevation). `x` is that horizontal direction.
struct ProjectedCap
{
    vec3 x;
    vec3 y;
    float centerX;
    float axisX;
    float axisY;
};

/// True when p is outside the sphere and its whole cap lies above the horizon of n (beta >= alpha, i.e.
/// sin(beta) = n . axis >= sin(alpha)): then the projected cap is the ellipse. n = 0 (no receiver: a medium)
/// is never above.
RT_FN bool projectedCap(RT_IN(LightData) s, vec3 p, vec3 n, RT_OUT(ProjectedCap) cap)
{
    const vec3 toCenter = s.p0 - p;
    const float d = length(toCenter);
    const vec3 axis = toCenter / d;
    const float sinAlpha = s.radius / d;
    const float sinBeta = dot(n, axis);
    cap.x = vec3(1.0f, 0.0f, 0.0f);
    cap.y = vec3(0.0f, 1.0f, 0.0f);
    cap.centerX = 0.0f;
    cap.axisX = 0.0f;
    cap.axisY = 0.0f;
    if (!(sinAlpha < 1.0f) || !(sinBeta >= sinAlpha))
        return false;
    const vec3 horizontal = axis - sinBeta * n;
    const float h = length(horizontal);
    // Straight overhead the ellipse is a circle about the normal: any horizontal axis will do.
    cap.x = h > 1e-6f ? horizontal / h : onbFromNormal(n).u;
    cap.y = cross(n, cap.x);
    const float cosAlpha = safeSqrt(1.0f - sinAlpha * sinAlpha);
    cap.centerX = cosAlpha * h; // h = cos(beta)
    cap.axisX = sinAlpha * sinBeta;
    cap.axisY = sinAlpha;
    return true;
}

/// Solid-angle pdf with which sampleLight(light, strategy, p, n, .) produces the unit direction wi; 0 if it
/// cannot. SolidAngle: 1 / S over a rectangle (Ureña et al. 2013) of at least kMinSphericalRectangle sr or a
/// triangle (Arvo 1995) of kMinSphericalTriangle to kMaxSphericalTriangle sr, the cone of a sphere seen from
/// outside; Projected: cos / F over a sphere's cap wholly above the horizon of the receiver normal n,
/// F = pi sin^2(alpha) sin(beta) its projected solid angle; over such a rectangle or triangle the bilinear
/// cosine warp's density at the direction's u (the inverse of the spherical map) over 1 / S; SolidAngle's
/// pdf otherwise (and for n = 0); Area: the area density of the point wi reaches first (a sphere's near
/// side). Every other case is area sampling.
RT_FN float lightPdf(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec3 wi)
{
    if (strategy != RT_ENUM(LightSampler, Area) && isRectangle(light))
    {
        const SphericalRectangle r = makeSphericalRectangle(p, light.p0, light.p1, light.p2);
        if (r.solidAngle >= kMinSphericalRectangle)
        {
            const float t = planarHit(light, p, wi);
            if (t < 0.0f)
                return 0.0f;
            if (strategy == RT_ENUM(LightSampler, SolidAngle) || !(dot(n, n) > 0.0f))
                return 1.0f / r.solidAngle;
            const vec3 y = t * wi;
            const vec2 uv = invertSphericalRectangle(r, dot(y, r.x), dot(y, r.y));
            const vec4 w = rectangleCosineWeights(r, n);
            return bilinearPdf(uv, w.x, w.y, w.z, w.w) / r.solidAngle;
        }
    }
    SphericalTriangle tri;
    if (strategy != RT_ENUM(LightSampler, Area) && sphericalTriangleApplies(light, p, tri))
    {
        if (planarHit(light, p, wi) < 0.0f)
            return 0.0f;
        if (strategy == RT_ENUM(LightSampler, SolidAngle) || !(dot(n, n) > 0.0f))
            return 1.0f / float(tri.solidAngle);
        const vec4 w = triangleCosineWeights(tri, n);
        const vec2 uv = invertSphericalTriangle(tri, RealVec3(wi));
        return bilinearPdf(uv, w.x, w.y, w.z, w.w) / float(tri.solidAngle);
    }
    if (strategy == RT_ENUM(LightSampler, Projected) && RT_LIGHT_IS(light.shape, Sphere))
    {
        ProjectedCap cap;
        if (projectedCap(light, p, n, cap))
        {
            float oneMinusCos;
            float cosThetaMax;
            vec3 axis;
            sphereCone(light, p, oneMinusCos, cosThetaMax, axis);
            return conePdf(oneMinusCos, axis, wi) > 0.0f ? max(dot(n, wi), 0.0f) / (kPi * cap.axisX * cap.axisY)
                                                         : 0.0f;
        }
    }
    if (strategy == RT_ENUM(LightSampler, Area) && RT_LIGHT_IS(light.shape, Sphere) &&
        lengthSquared(p - light.p0) > light.radius * light.radius)
    {
        const float t = sphereNearHit(light, p, wi);
        if (!(t > 0.0f))
            return 0.0f;
        const vec3 sphereNormal = (p + t * wi - light.p0) / light.radius;
        return areaToSolidAngle(t * t, abs(dot(sphereNormal, wi)), light.area);
    }
    return lightPdf(light, p, wi);
}

/// Samples a point of `light` for NEE from p (receiver normal n, or 0 in a medium) with the density
/// lightPdf(light, strategy, p, n, .) reports (the sample's pdf is that density of its direction). With Area,
/// a sphere seen from outside is sampled over its whole surface: a point on its far side faces away from p
/// and returns false, a sample of zero contribution. With Projected, a sphere over the horizon is sampled
/// uniformly over its projected cap, the ellipse, by the concentric map scaled to it (area-preserving, so
/// stratification survives), and lifted to the hemisphere: density cos / F (Ureña & Georgiev 2018, §3-4).
/// Triangles by SolidAngle: Arvo's map, uniform over the spherical triangle (Shared/SphericalTriangle.h);
/// by Projected: u first warped by the bilinear density of the receiver's cosine at the corners of the
/// square that Arvo's map sends to the vertices (warp product sampling: Hart et al. 2020, "Practical Product
/// Sampling by Fitting and Composing Warps", EGSR; pbrt-v4 §6.5.4), density warp / S. The point is where the
/// sampled direction meets the triangle, clamped onto it.
RT_FN bool sampleLight(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec2 u,
                       RT_OUT(LightSample) ls)
{
    if (strategy != RT_ENUM(LightSampler, Area) && isRectangle(light))
    {
        const SphericalRectangle r = makeSphericalRectangle(p, light.p0, light.p1, light.p2);
        if (r.solidAngle >= kMinSphericalRectangle)
        {
            // Projected warps u toward the receiver's cosine first; SolidAngle (or no receiver) takes u as is.
            const bool warp = strategy == RT_ENUM(LightSampler, Projected) && dot(n, n) > 0.0f;
            const vec4 w = warp ? rectangleCosineWeights(r, n) : vec4(1.0f);
            const vec2 warped = warp ? sampleBilinear(u, w.x, w.y, w.z, w.w) : u;
            ls.point = sampleSphericalRectangle(r, warped);
            ls.normal = light.normal;
            const vec3 planar = ls.point - light.p0;
            ls.uv = vec2(dot(planar, light.dualU), dot(planar, light.dualV));
            const vec3 toPoint = ls.point - p;
            ls.distance = length(toPoint);
            ls.wi = toPoint / ls.distance;
            // The density of the construction at its own (u, v) (the warp's, 1 without it) over 1 / S; 0 where
            // rounding put the direction off the rectangle, as lightPdf finds it.
            const float warpPdf = warp ? bilinearPdf(warped, w.x, w.y, w.z, w.w) : 1.0f;
            ls.pdf = planarHit(light, p, ls.wi) > 0.0f ? warpPdf / r.solidAngle : 0.0f;
            return ls.pdf > 0.0f;
        }
    }
    SphericalTriangle tri;
    if (strategy != RT_ENUM(LightSampler, Area) && sphericalTriangleApplies(light, p, tri))
    {
        // As for rectangles: Projected composes the cosine warp with Arvo's map, SolidAngle takes u as is.
        const bool warp = strategy == RT_ENUM(LightSampler, Projected) && dot(n, n) > 0.0f;
        const vec4 w = warp ? triangleCosineWeights(tri, n) : vec4(1.0f);
        const vec2 warped = warp ? sampleBilinear(u, w.x, w.y, w.z, w.w) : u;
        // The direction becomes a point on the triangle (barycentrics clamped), so the sample never misses.
        ls.uv = sphericalTrianglePoint(tri, sphericalTriangleDirection(tri, warped));
        ls.point = light.p0 + ls.uv.x * light.p1 + ls.uv.y * light.p2;
        ls.normal = light.normal;
        const vec3 toPoint = ls.point - p;
        ls.distance = length(toPoint);
        ls.wi = toPoint / ls.distance;
        const float warpPdf = warp ? bilinearPdf(warped, w.x, w.y, w.z, w.w) : 1.0f;
        // planarHit's slack finds every such point again, so this 0 (the sample dropped, as lightPdf would
        // drop its direction) is a guard the tests check is never taken.
        ls.pdf = planarHit(light, p, ls.wi) > 0.0f ? warpPdf / float(tri.solidAngle) : 0.0f;
        return ls.pdf > 0.0f;
    }
    if (strategy == RT_ENUM(LightSampler, Projected) && RT_LIGHT_IS(light.shape, Sphere))
    {
        ProjectedCap cap;
        if (projectedCap(light, p, n, cap))
        {
            const vec2 disk = sampleUniformDiskConcentric(u);
            const float x = cap.centerX + cap.axisX * disk.x;
            const float y = cap.axisY * disk.y;
            const float z = safeSqrt(1.0f - x * x - y * y);
            ls.wi = normalize(x * cap.x + y * cap.y + z * n);
            ls.uv = vec2(0.0f);
            ls.distance = sphereEntryDistance(light, p, ls.wi);
            ls.normal = normalize(p + ls.distance * ls.wi - light.p0);
            ls.point = light.p0 + light.radius * ls.normal;
            // cos / F, the density of the construction: a rim sample that rounding moved a few ulps out of the
            // cone (where lightPdf's chord test says 0: 3 in 1e6 for a cap of 1e-3 rad) keeps it rather than
            // being dropped; the two differ only on that rim, a set of no measure.
            ls.pdf = max(dot(n, ls.wi), 0.0f) / (kPi * cap.axisX * cap.axisY);
            return ls.pdf > 0.0f;
        }
    }
    if (strategy == RT_ENUM(LightSampler, Area) && RT_LIGHT_IS(light.shape, Sphere) &&
        lengthSquared(p - light.p0) > light.radius * light.radius)
    {
        ls.uv = vec2(0.0f);
        ls.normal = sampleUniformSphere(u);
        ls.point = light.p0 + light.radius * ls.normal;
        const vec3 w = ls.point - p;
        ls.distance = length(w);
        ls.wi = w / ls.distance;
        const float cosLight = -dot(ls.normal, ls.wi);
        ls.pdf = cosLight > 0.0f ? areaToSolidAngle(ls.distance * ls.distance, cosLight, light.area) : 0.0f;
        return ls.pdf > 0.0f;
    }
    return sampleLight(light, p, u, ls);
}

RT_SHADER_NAMESPACE_END

#endif
