// Uniform solid-angle sampling of a rectangle, written once for both engines (Shared/ShaderLang.h):
// C. Ureña, M. Fajardo, A. King, "An Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013
// (Computer Graphics Forum 32(4)), §3 (setup, the solid angle as the sum of the four internal angles minus 2 pi)
// and §4 (the two-step inversion). Research notes §1.5 list the numerical guards used here.
//
// Frame: the rectangle's corner s and orthogonal edges ex, ey, seen from the point o; local axes x = ex/|ex|,
// y = ey/|ey|, z = x cross y turned away from the rectangle, so that it lies in the plane z = z0 <= 0 and
// covers [x0, x1] x [y0, y1] there.
#ifndef RT_SHARED_SPHERICAL_RECTANGLE_H
#define RT_SHARED_SPHERICAL_RECTANGLE_H

#include "Shared/PreciseMath.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

struct SphericalRectangle
{
    vec3 o; // the point it is seen from
    vec3 x;
    vec3 y;
    vec3 z;
    float x0;
    float x1;
    float y0;
    float y1;
    float z0;
    float b0; // z component of the normal of the plane through o and the edge y = y0 (the paper's n0.z)
    float b1; // ... through o and the edge y = y1 (n2.z)
    float c0; // 1 - b0^2 = z0^2 / (z0^2 + y0^2), without the subtraction's cancellation
    float k; // 2 pi - g2 - g3: the angle where the first coordinate's inversion starts
    float solidAngle; // S, steradians
};

/// The rectangle s + a x + b y (a in [0, exLength], b in [0, eyLength]) with orthonormal edge directions x, y and
/// z = x cross y, as seen from o (Ureña et al. 2013, §3, Algorithm 1 "SphQuadInit"). The normals of the four
/// planes through o and an edge each have one zero component, so each internal angle is acos of a product of two
/// z components.
RT_FN SphericalRectangle makeSphericalRectangleInFrame(vec3 o, vec3 s, vec3 x, vec3 y, vec3 z, float exLength,
                                                       float eyLength)
{
    SphericalRectangle r;
    r.o = o;
    r.x = x;
    r.y = y;
    r.z = z;
    const vec3 d = s - o;
    r.z0 = dot(d, r.z);
    if (r.z0 > 0.0f)
    {
        r.z = -r.z;
        r.z0 = -r.z0;
    }
    r.x0 = dot(d, r.x);
    r.y0 = dot(d, r.y);
    r.x1 = r.x0 + exLength;
    r.y1 = r.y0 + eyLength;
    const float z2 = r.z0 * r.z0;
    // z components of the unit normals n0 = (0, z0, -y0), n1 = (-z0, 0, x1), n2 = (0, -z0, y1), n3 = (z0, 0, -x0).
    const float y02 = z2 + r.y0 * r.y0;
    const float n0z = -r.y0 / sqrt(y02);
    const float n1z = r.x1 / sqrt(z2 + r.x1 * r.x1);
    const float n2z = r.y1 / sqrt(z2 + r.y1 * r.y1);
    const float n3z = -r.x0 / sqrt(z2 + r.x0 * r.x0);
    const float g0 = preciseAcos(clamp(-n0z * n1z, -1.0f, 1.0f));
    const float g1 = preciseAcos(clamp(-n1z * n2z, -1.0f, 1.0f));
    const float g2 = preciseAcos(clamp(-n2z * n3z, -1.0f, 1.0f));
    const float g3 = preciseAcos(clamp(-n3z * n0z, -1.0f, 1.0f));
    r.b0 = n0z;
    r.b1 = n2z;
    r.c0 = z2 / y02;
    r.k = 2.0f * kPi - g2 - g3;
    r.solidAngle = g0 + g1 + g2 + g3 - 2.0f * kPi;
    return r;
}

/// Whether r's float setup resolves the rectangle: z0^2 at least 1e-6 of every edge coordinate's square. Nearer the
/// rectangle's plane the planes' normals round toward the plane's own, so the angles lose their digits (u off by
/// 1e-3 and more) and, within about 1e-4 of the plane over the rectangle, round to pi each (S = 2 pi, every sample
/// at one edge; measured against long double, docs/notebook/PERFORMANCE.md §37). The samplers take the area there.
RT_FN bool sphericalRectangleResolved(RT_IN(SphericalRectangle) r)
{
    const float e2 = max(max(r.x0 * r.x0, r.x1 * r.x1), max(r.y0 * r.y0, r.y1 * r.y1));
    return r.z0 * r.z0 >= 1e-6f * e2;
}

/// The rectangle s + a ex + b ey (a, b in [0, 1], ex . ey = 0) as seen from o: makeSphericalRectangleInFrame
/// with the frame of its edges.
RT_FN SphericalRectangle makeSphericalRectangle(vec3 o, vec3 s, vec3 ex, vec3 ey)
{
    const float exLength = length(ex);
    const float eyLength = length(ey);
    const vec3 x = ex / exLength;
    const vec3 y = ey / eyLength;
    return makeSphericalRectangleInFrame(o, s, x, y, cross(x, y), exLength, eyLength);
}

/// The point of the rectangle for u in [0, 1)^2, uniform in solid angle as seen from r.o (density 1 / S)
/// (Ureña et al. 2013, §4, Algorithm 2 "SphQuadSample"): u.x fixes the vertical line x = xu that cuts off
/// u.x S of the solid angle, u.y the height on it through h(y) = y / sqrt(d^2 + y^2), which is linear in the
/// solid angle along that line.
RT_FN vec3 sampleSphericalRectangle(RT_IN(SphericalRectangle) r, vec2 u)
{
    const float au = u.x * r.solidAngle + r.k;
    const float sinAu = sin(au);
    // The paper's fu = (cos(au) b0 - b1) / sin(au), cu = sign(fu) / sqrt(fu^2 + b0^2) and xu = -cu z0 / sqrt(1 -
    // cu^2), multiplied through by sin(au) with 1 - b0^2 = c0: xu = -sign(a) sin(au) z0 / sqrt(a^2 - c0 sin(au)^2)
    // for a = fu sin(au). One square root and one division where the paper's form chains three divisions and two
    // roots, each waiting on the last (docs/notebook/PERFORMANCE.md §37), and none by sin(au), which may be 0.
    // q = (sin(au) z0 / xu)^2 > 0 in exact arithmetic; <= 0 only by rounding, where the cut plane through o is all
    // but parallel to the rectangle's (|cu| = 1): xu is then infinite, toward sign(a sin(au)).
    const float a = cos(au) * r.b0 - r.b1;
    const float q = a * a - r.c0 * sinAu * sinAu;
    const float xu = q > 0.0f ? clamp(-signNotZero(a) * sinAu * r.z0 / sqrt(q), r.x0, r.x1)
                              : (a * sinAu > 0.0f ? r.x1 : r.x0);
    // d^2 from xu, not from d: the two heights need not wait for d's square root.
    const float d2 = xu * xu + r.z0 * r.z0;
    const float d = sqrt(d2);
    const float h0 = r.y0 / sqrt(d2 + r.y0 * r.y0);
    const float h1 = r.y1 / sqrt(d2 + r.y1 * r.y1);
    const float hv = h0 + u.y * (h1 - h0);
    const float hv2 = hv * hv;
    const float yv = hv2 < 1.0f - 1e-6f ? clamp(hv * d / sqrt(1.0f - hv2), r.y0, r.y1) : r.y1;
    return r.o + xu * r.x + yv * r.y + r.z0 * r.z;
}

/// The (u, v) with which sampleSphericalRectangle gives the rectangle's point with local coordinates
/// (px, py) (in [x0, x1] x [y0, y1]): u is the solid angle of the part [x0, px] over the whole (how the first
/// coordinate was drawn), v where h(py) lies between h(y0) and h(y1) on the line x = px.
RT_FN vec2 invertSphericalRectangle(RT_IN(SphericalRectangle) r, float px, float py)
{
    float u = 0.0f;
    const float z2 = r.z0 * r.z0;
    if (px > r.x0)
    {
        // The part [x0, px] x [y0, y1] shares three of the rectangle's four planes through o: only n1's changes,
        // so its solid angle g0' + g1' + g2 + g3 - 2 pi is g0' + g1' - k (two angles, not a second setup).
        const float n1z = px / sqrt(z2 + px * px);
        const float g0 = preciseAcos(clamp(-r.b0 * n1z, -1.0f, 1.0f));
        const float g1 = preciseAcos(clamp(-n1z * r.b1, -1.0f, 1.0f));
        u = clamp((g0 + g1 - r.k) / r.solidAngle, 0.0f, 1.0f);
    }
    const float d2 = px * px + z2;
    const float h0 = r.y0 / sqrt(d2 + r.y0 * r.y0);
    const float h1 = r.y1 / sqrt(d2 + r.y1 * r.y1);
    const float hv = py / sqrt(d2 + py * py);
    const float v = h1 > h0 ? clamp((hv - h0) / (h1 - h0), 0.0f, 1.0f) : 0.5f;
    return vec2(u, v);
}

RT_SHADER_NAMESPACE_END

#endif
