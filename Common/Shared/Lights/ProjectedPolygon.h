// Exact projected-solid-angle sampling of a planar polygon light (quads and triangles) for a receiver with
// normal n: directions with density cos(theta) / P, P the polygon's projected solid angle, after C. Peters,
// "BRDF Importance Sampling for Polygonal Lights", ACM TOG 40(4), 2021 (§4: the polygon's orthographic
// projection onto the receiver's tangent plane, bounded by arcs of ellipses centred at the origin; sampled by
// sectors of polar angle between its vertices, the polar angle by inverting each sector's area, the radius
// uniformly in r^2). Both engines (Shared/ShaderLang.h); the algebra in `Real` (Shared/Real.h: double on the
// CPU, float on the GPU).
//
// Frame: local (x, y, z) along (u, v, n), n the receiver's unit normal. The polygon is clipped to z >= 0 first
// (a clipped edge lies on the horizon and projects to the unit circle). An edge between unit directions a, b lies
// on the great circle of normal m = a x b, canonicalised to m.z <= 0; its upper half projects to the half-ellipse
// on the side of axis = (m.x, m.y) / |(m.x, m.y)|, where a direction d of the plane at angle t to the axis
// (cos t >= 0) meets it at radius
//     r^2 = s^2 / (s^2 + (1 - s^2) cos^2 t),   s = |m.z| / |m|,
// and the area swept from the origin, (1/2) integral r^2 dt, is (s / 2) F with F(t) = atan2(s sin t, cos t)
// (F continuous on the half-ellipse: no wrap). A horizon edge (m along z) has s = 1 and sweeps the unit circle.
// The polygon's projected area P is the signed sum of its edges' sweeps (positive for the polygon counter-
// clockwise about n). Sampling: if the zenith n lies inside the polygon, each edge's sweep is a sector from the
// origin and the polar angle inverts in closed form, t = atan2(sin f, s cos f); otherwise every ray from the
// origin meets the region in one interval between a near and a far edge, and a sector between consecutive vertex
// angles inverts the difference of two sweeps by Newton's method kept inside its bracket.
#ifndef RT_SHARED_LIGHTS_PROJECTED_POLYGON_H
#define RT_SHARED_LIGHTS_PROJECTED_POLYGON_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/Lights/Planar.h"
#include "Shared/Onb.h"
#include "Shared/PreciseMath.h"
#include "Shared/Real.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Below this projected solid angle (sr) a polygon is sampled by area (Lights/Planar.h): the edge sweeps that sum
/// to P carry an absolute float error near 1e-8 sr, 1e-4 of P here, and a light this small looks the same to
/// both strategies.
RT_CONST(float, kMinProjectedPolygon, 1e-4f)

/// A quad clipped by the horizon has at most 5 vertices.
RT_CONST(uint, kMaxPolygonVertices, 5u)

struct ProjectedPolygon
{
    vec3 u;              // tangent frame about n
    vec3 v;
    RealVec3 w[5];       // unit directions of the clipped polygon's vertices in (u, v, n), counter-clockwise about n
    uint count;          // vertices above the horizon; 0 when none
    bool zenithInside;   // n within the polygon: every edge bounds a sector from the origin
    Real area;           // P, the projected solid angle (sr)
};

/// An edge's half-ellipse (header): the unit axis of its side of the plane and s = |m.z| / |m|.
struct PolygonEdge
{
    RealVec2 axis;
    Real s;
};

/// The unit 2D direction of w's projection; `fallback` for a direction along n (a vertex at the zenith, whose
/// edges pass through the origin and sweep nothing).
RT_FN RealVec2 planeDirection(RealVec3 w, RealVec2 fallback)
{
    const Real l = sqrt(w.x * w.x + w.y * w.y);
    return l > 1e-30 ? RealVec2(w.x, w.y) / l : fallback;
}

RT_FN PolygonEdge polygonEdge(RealVec3 a, RealVec3 b)
{
    PolygonEdge e;
    RealVec3 m = cross(a, b);
    const Real length3 = length(m);
    e.s = length3 > 0.0 ? abs(m.z) / length3 : 0.0;
    if (m.z > 0.0)
        m = -m;
    const Real rho = sqrt(m.x * m.x + m.y * m.y);
    // A horizon edge (m along z) sweeps the unit circle: any axis on its side will do, its midpoint's.
    e.axis = rho > 1e-7 * length3 ? RealVec2(m.x, m.y) / rho
                                  : planeDirection(a + b, planeDirection(a, RealVec2(1.0, 0.0)));
    return e;
}

/// F(t) of the header for the plane direction d.
RT_FN Real edgeSweepAngle(RT_IN(PolygonEdge) e, RealVec2 d)
{
    const Real c = dot(e.axis, d);
    const Real sn = e.axis.x * d.y - e.axis.y * d.x;
    return preciseAtan(e.s * sn, c);
}

/// The area swept by the edge's half-ellipse from the plane direction da to db (signed, counter-clockwise
/// positive).
RT_FN Real edgeSweep(RT_IN(PolygonEdge) e, RealVec2 da, RealVec2 db)
{
    return 0.5 * e.s * (edgeSweepAngle(e, db) - edgeSweepAngle(e, da));
}

/// r^2 where the direction d meets the edge's half-ellipse, and 1 - r^2 (without cancellation near the horizon).
RT_FN Real edgeRadius2(RT_IN(PolygonEdge) e, RealVec2 d, RT_OUT(Real) oneMinus)
{
    const Real c = dot(e.axis, d);
    const Real s2 = e.s * e.s;
    const Real denominator = s2 + (1.0 - s2) * c * c;
    if (!(denominator > 0.0))
    {
        oneMinus = 1.0;
        return 0.0;
    }
    oneMinus = (1.0 - s2) * c * c / denominator;
    return s2 / denominator;
}

/// The plane direction at angle t counter-clockwise from d.
RT_FN RealVec2 rotatePlane(RealVec2 d, Real t)
{
    const Real c = preciseCos(t);
    const Real sn = preciseSin(t);
    return RealVec2(c * d.x - sn * d.y, sn * d.x + c * d.y);
}

/// The signed angle from a to b (unit plane directions), in (-pi, pi].
RT_FN Real planeAngle(RealVec2 a, RealVec2 b)
{
    return preciseAtan(a.x * b.y - a.y * b.x, dot(a, b));
}

/// The polygon light (a quad: corners p0, p0 + p1, p0 + p1 + p2, p0 + p2; a triangle: p0, p0 + p1, p0 + p2)
/// seen from p over the horizon of the unit normal n: clipped, oriented, its projected solid angle.
RT_FN ProjectedPolygon makeProjectedPolygon(RT_IN(LightData) light, vec3 p, vec3 n)
{
    ProjectedPolygon g;
    const Onb onb = onbFromNormal(n);
    g.u = onb.u;
    g.v = onb.v;
    const bool quad = RT_LIGHT_IS(light.shape, Quad);
    const uint corners = quad ? 4u : 3u;
    RealVec3 c[4];
    vec3 world[4];
    world[0] = light.p0;
    world[1] = light.p0 + light.p1;
    world[2] = quad ? light.p0 + light.p1 + light.p2 : light.p0 + light.p2;
    world[3] = light.p0 + light.p2;
    for (uint i = 0u; i < 4u; ++i)
    {
        const RealVec3 d = RealVec3(world[i]) - RealVec3(p);
        c[i] = RealVec3(dot(d, RealVec3(g.u)), dot(d, RealVec3(g.v)), dot(d, RealVec3(n)));
    }
    // Sutherland-Hodgman against z >= 0; a crossing point lies on the horizon (z = 0 exactly).
    g.count = 0u;
    for (uint i = 0u; i < corners; ++i)
    {
        const RealVec3 a = c[i];
        const RealVec3 b = c[(i + 1u) % corners];
        if (a.z >= 0.0)
            g.w[g.count++] = a;
        if ((a.z >= 0.0) != (b.z >= 0.0))
        {
            const Real t = a.z / (a.z - b.z);
            g.w[g.count++] = RealVec3(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0);
        }
    }
    g.zenithInside = false;
    g.area = 0.0;
    if (g.count < 3u)
    {
        g.count = 0u;
        return g;
    }
    for (uint i = 0u; i < g.count; ++i)
        g.w[i] = normalize(g.w[i]);
    // Orientation and P: the edges' signed sweeps; the zenith is inside when every edge's plane has it on the
    // same side (all m.z of one sign).
    Real sum = 0.0;
    uint positive = 0u;
    uint negative = 0u;
    for (uint i = 0u; i < g.count; ++i)
    {
        const RealVec3 a = g.w[i];
        const RealVec3 b = g.w[(i + 1u) % g.count];
        const PolygonEdge e = polygonEdge(a, b);
        const RealVec2 da = planeDirection(a, planeDirection(b, e.axis));
        const RealVec2 db = planeDirection(b, da);
        sum += edgeSweep(e, da, db);
        const Real mz = a.x * b.y - a.y * b.x;
        positive += mz > 0.0 ? 1u : 0u;
        negative += mz < 0.0 ? 1u : 0u;
    }
    g.zenithInside = positive == g.count || negative == g.count;
    if (sum < 0.0)
    {
        for (uint i = 0u; i < g.count / 2u; ++i)
        {
            const RealVec3 t = g.w[i];
            g.w[i] = g.w[g.count - 1u - i];
            g.w[g.count - 1u - i] = t;
        }
    }
    g.area = abs(sum);
    return g;
}

/// The local direction over the plane point r d, r^2 = r2, with 1 - r^2 = oneMinus given without cancellation.
/// Its height is at least 1e-6 r: where the region meets the horizon float rounds the true height to 0, and a
/// direction with cos = 0 has pdf 0, a dropped sample (as Lights/ProjectedCap.h's kMinCapLift).
RT_FN RealVec3 liftPlanePoint(RealVec2 d, Real r2, Real oneMinus)
{
    const Real r = sqrt(max(r2, 0.0));
    return RealVec3(r * d.x, r * d.y, max(sqrt(max(oneMinus, 0.0)), 1e-6 * r));
}

/// A local direction uniform over the polygon's projection (density cos / area per unit solid angle); g.count >= 3.
RT_FN RealVec3 sampleProjectedPolygon(RT_IN(ProjectedPolygon) g, vec2 u)
{
    Real ux = Real(u.x);
    const Real uy = Real(u.y);
    if (g.zenithInside)
    {
        // Sectors are the edges' sweeps: pick one by area, invert its F in closed form, then r^2 uniform in [0, r^2].
        Real target = ux * g.area;
        uint pick = g.count - 1u;
        for (uint i = 0u; i < g.count; ++i)
        {
            const PolygonEdge e = polygonEdge(g.w[i], g.w[(i + 1u) % g.count]);
            const RealVec2 da = planeDirection(g.w[i], e.axis);
            const Real sweep = max(edgeSweep(e, da, planeDirection(g.w[(i + 1u) % g.count], da)), 0.0);
            if (target < sweep || i == g.count - 1u)
            {
                pick = i;
                target = min(target, sweep);
                break;
            }
            target -= sweep;
        }
        const PolygonEdge e = polygonEdge(g.w[pick], g.w[(pick + 1u) % g.count]);
        const RealVec2 da = planeDirection(g.w[pick], e.axis);
        const Real f = edgeSweepAngle(e, da) + (e.s > 0.0 ? 2.0 * target / e.s : 0.0);
        const RealVec2 d = rotatePlane(e.axis, preciseAtan(preciseSin(f), e.s * preciseCos(f)));
        Real oneMinus;
        const Real r2 = edgeRadius2(e, d, oneMinus);
        return liftPlanePoint(d, uy * r2, 1.0 - uy + uy * oneMinus);
    }
    // The zenith outside: plane directions relative to a reference inside the polygon's cone of directions.
    RealVec2 reference = RealVec2(0.0);
    for (uint i = 0u; i < g.count; ++i)
        reference += planeDirection(g.w[i], RealVec2(0.0));
    reference = planeDirection(RealVec3(reference, 0.0), RealVec2(1.0, 0.0));
    Real angle[5];
    Real sorted[5];
    for (uint i = 0u; i < g.count; ++i)
    {
        angle[i] = planeAngle(reference, planeDirection(g.w[i], reference));
        sorted[i] = angle[i];
    }
    for (uint i = 1u; i < g.count; ++i) // insertion sort of at most 5
        for (uint j = i; j > 0u && sorted[j - 1u] > sorted[j]; --j)
        {
            const Real t = sorted[j];
            sorted[j] = sorted[j - 1u];
            sorted[j - 1u] = t;
        }
    // Each sector between consecutive vertex angles: the far edge (counter-clockwise about the origin) and the
    // near edge (clockwise) whose angular spans cover it; its area far sweep - near sweep.
    Real sectorArea[4];
    uint farEdge[4];
    uint nearEdge[4];
    Real total = 0.0;
    for (uint k = 0u; k + 1u < g.count; ++k)
    {
        farEdge[k] = kNoIndex;
        nearEdge[k] = kNoIndex;
        sectorArea[k] = 0.0;
        const Real lo = sorted[k];
        const Real hi = sorted[k + 1u];
        if (!(hi > lo))
            continue;
        const Real mid = 0.5 * (lo + hi);
        for (uint i = 0u; i < g.count; ++i)
        {
            const Real a = angle[i];
            const Real b = angle[(i + 1u) % g.count];
            if (min(a, b) <= mid && mid <= max(a, b) && a != b)
            {
                if (b > a)
                    farEdge[k] = i;
                else
                    nearEdge[k] = i;
            }
        }
        const RealVec2 dlo = rotatePlane(reference, lo);
        const RealVec2 dhi = rotatePlane(reference, hi);
        Real area = 0.0;
        if (farEdge[k] != kNoIndex)
            area += edgeSweep(polygonEdge(g.w[farEdge[k]], g.w[(farEdge[k] + 1u) % g.count]), dlo, dhi);
        if (nearEdge[k] != kNoIndex)
            area -= edgeSweep(polygonEdge(g.w[nearEdge[k]], g.w[(nearEdge[k] + 1u) % g.count]), dlo, dhi);
        sectorArea[k] = max(area, 0.0);
        total += sectorArea[k];
    }
    Real target = ux * total;
    uint pick = 0u;
    for (uint k = 0u; k + 1u < g.count; ++k)
    {
        if (sectorArea[k] > 0.0)
            pick = k;
        if (target < sectorArea[k])
            break;
        target -= sectorArea[k];
    }
    target = clamp(target, 0.0, sectorArea[pick]);
    if (farEdge[pick] == kNoIndex) // no sector with area: a degenerate region, which P >= kMinProjectedPolygon excludes
        return g.w[0];
    const PolygonEdge far = polygonEdge(g.w[farEdge[pick]], g.w[(farEdge[pick] + 1u) % g.count]);
    const bool hasNear = nearEdge[pick] != kNoIndex;
    PolygonEdge near = far;
    if (hasNear)
        near = polygonEdge(g.w[nearEdge[pick]], g.w[(nearEdge[pick] + 1u) % g.count]);
    const RealVec2 dlo = rotatePlane(reference, sorted[pick]);
    const Real width = sorted[pick + 1u] - sorted[pick];
    // The polar angle t in [0, width] from dlo where the swept area reaches the target: Newton's method on a
    // monotone function (derivative (r_far^2 - r_near^2) / 2), bisection where a step leaves the bracket.
    Real lo = 0.0;
    Real hi = width;
    Real t = width * (sectorArea[pick] > 0.0 ? target / sectorArea[pick] : 0.5);
    RT_DONT_UNROLL for (int i = 0; i < 16; ++i)
    {
        const RealVec2 d = rotatePlane(dlo, t);
        Real oneMinusFar = 0.0;
        Real oneMinusNear = 1.0;
        const Real farR2 = edgeRadius2(far, d, oneMinusFar);
        const Real nearR2 = hasNear ? edgeRadius2(near, d, oneMinusNear) : 0.0;
        const Real swept = edgeSweep(far, dlo, d) - (hasNear ? edgeSweep(near, dlo, d) : 0.0);
        const Real residual = swept - target;
        if (residual > 0.0)
            hi = t;
        else
            lo = t;
        const Real slope = 0.5 * (farR2 - nearR2);
        Real next = slope > 0.0 ? t - residual / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        // Newton in float can cycle between neighbours instead of settling: a step below 1e-7 of the sector ends it.
        const bool converged = abs(next - t) <= 1e-7 * width;
        t = next;
        if (converged)
            break;
    }
    const RealVec2 d = rotatePlane(dlo, t);
    Real oneMinusFar = 0.0;
    Real oneMinusNear = 1.0;
    const Real farR2 = edgeRadius2(far, d, oneMinusFar);
    const Real nearR2 = hasNear ? edgeRadius2(near, d, oneMinusNear) : 0.0;
    return liftPlanePoint(d, nearR2 + uy * (farR2 - nearR2), (1.0 - uy) * oneMinusNear + uy * oneMinusFar);
}

/// Whether projected-exact sampling applies: a receiver (n != 0) and a visible polygon of at least
/// kMinProjectedPolygon sr; else the caller samples by area (or, without a receiver, by solid angle).
RT_FN bool projectedPolygonApplies(RT_IN(ProjectedPolygon) g)
{
    return g.count >= 3u && g.area >= Real(kMinProjectedPolygon);
}

/// NEE's pdf of wi from p by projected-exact sampling: cos / P for a direction that reaches the light over the
/// horizon of n; the caller has checked projectedPolygonApplies.
RT_FN float projectedPolygonPdf(RT_IN(LightData) light, RT_IN(ProjectedPolygon) g, vec3 p, vec3 n, vec3 wi)
{
    const float cosine = dot(n, wi);
    return cosine > 0.0f && planarHit(light, p, wi) > 0.0f ? cosine / float(g.area) : 0.0f;
}

/// NEE's sample by projected-exact sampling (projectedPolygonApplies holds): the direction, the point where it
/// meets the light's plane, and the pdf projectedPolygonPdf finds again (0 where rounding put it off the light,
/// a sample declined as the spherical samplers decline theirs).
RT_FN bool sampleProjectedPolygonLight(RT_IN(LightData) light, RT_IN(ProjectedPolygon) g, vec3 p, vec3 n, vec2 u,
                                       RT_OUT(LightSample) ls)
{
    clearLightSample(light, ls);
    const RealVec3 local = sampleProjectedPolygon(g, u);
    ls.wi = normalize(float(local.x) * g.u + float(local.y) * g.v + float(local.z) * n);
    const float t = dot(light.normal, light.p0 - p) / dot(light.normal, ls.wi);
    ls.point = p + t * ls.wi;
    ls.distance = t;
    ls.normal = light.normal;
    const vec3 planar = ls.point - light.p0;
    ls.uv = vec2(dot(planar, light.dualU), dot(planar, light.dualV));
    ls.pdf = projectedPolygonPdf(light, g, p, n, ls.wi);
    return keepLightSample(ls);
}

RT_SHADER_NAMESPACE_END

#endif
