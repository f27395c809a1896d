// Uniform solid-angle sampling of a triangle and its inverse, written once for both engines
// (Shared/ShaderLang.h): J. Arvo, "Stratified Sampling of Spherical Triangles", SIGGRAPH 1995, pp. 437-438,
// "The Sampling Algorithm": stage one picks the sub-triangle A B C' of area u.x times the whole (Girard's
// formula (1) and the spherical cosine laws for angles (2), (3) solved for the arc A C'), stage two the point
// on the arc B C' whose 1 - cos to B is u.y times the arc's. The solid angle is Van Oosterom & Strackee's,
// "The Solid Angle of a Plane Triangle", IEEE Trans. Biomed. Eng. 30(2), 1983, on un-normalised vectors with
// the triple product taken from the edges (research notes §1.3: Girard's angle sum cancels).
//
// Precision. The algebra runs in `Real`: double on the CPU (research notes §0.2: Arvo's map in float put 5 %
// of the samples off triangles of 2e-5 sr; in double none down to 1e-7 sr), float in GLSL. Its literals are
// written without the f suffix on purpose (double in C++, float in GLSL). Every quantity that vanishes with
// the triangle is computed without cancellation, so float stays usable far below the samplers' 3e-4 sr:
// 1 - cos of a short arc from its sine (sin^2 / (1 + cos)) or chord (|x - y|^2 / 2), the internal angle and
// the tangent towards C from the edge vectors, and Arvo's q = cos(arc A C') as 1 - q (derived below).
//
// Frame: the triangle p0, p0 + e1, p0 + e2 seen from the point o; A, B, C are the unit directions from o to
// these vertices; orientation does not matter (both windings give the same map).
#ifndef RT_SHARED_SPHERICAL_TRIANGLE_H
#define RT_SHARED_SPHERICAL_TRIANGLE_H

#include "Shared/PreciseMath.h"
#include "Shared/Real.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

struct SphericalTriangle
{
    RealVec3 r0;        // p0 - o: un-normalised, for the plane intersection
    RealVec3 e1;        // p1 - p0
    RealVec3 e2;        // p2 - p0
    RealVec3 a;         // unit direction towards p0 (Arvo's A)
    RealVec3 b;         // ... towards p0 + e1 (B)
    RealVec3 c;         // ... towards p0 + e2 (C)
    RealVec3 crossAB;   // a x b, from R0 x e1
    RealVec3 tangentAC; // unit tangent at A of the arc towards C: C = cosArcAC a + sinArcAC tangentAC
    Real cosArcAC;      // Arvo's side b
    Real sinArcAC;
    Real cosArcAB; // Arvo's side c
    Real oneMinusCosArcAB;
    Real alpha;      // internal angle at A, radians
    Real solidAngle; // steradians, in [0, 2 pi)
};

/// 1 - cos(x) for an angle x in [0, pi] given its sine and cosine: sin^2 / (1 + cos), without the
/// cancellation of 1 - cos near 0, where it matters.
RT_FN Real oneMinusCos(Real sinX, Real cosX)
{
    return cosX > 0.0 ? sinX * sinX / (1.0 + cosX) : 1.0 - cosX;
}

/// The triangle p0, p0 + e1, p0 + e2 (world space) seen from o. Solid angle (Van Oosterom & Strackee 1983):
/// tan(Omega / 2) = |R0 . (e1 x e2)| / (r0 r1 r2 + (R0.R1) r2 + (R0.R2) r1 + (R1.R2) r0) with Ri the vertices
/// relative to o and ri their lengths; R0 . (R1 x R2) = R0 . (e1 x e2) keeps the triple product accurate for
/// small triangles. The angle at A is the one between the planes (A, B) and (A, C), from their normals
/// R0 x e1 and R0 x e2: |n1 x n2| = |R0 . (e1 x e2)| r0 and n1 . n2 = r0^2 (e1.e2) - (R0.e1)(R0.e2).
RT_FN SphericalTriangle makeSphericalTriangle(vec3 o, vec3 p0, vec3 e1, vec3 e2)
{
    SphericalTriangle t;
    t.r0 = RealVec3(p0) - RealVec3(o);
    t.e1 = RealVec3(e1);
    t.e2 = RealVec3(e2);
    const RealVec3 r1 = t.r0 + t.e1;
    const RealVec3 r2 = t.r0 + t.e2;
    const Real l0 = length(t.r0);
    const Real l1 = length(r1);
    const Real l2 = length(r2);
    t.a = t.r0 / l0;
    t.b = r1 / l1;
    t.c = r2 / l2;
    const Real triple = abs(dot(t.r0, cross(t.e1, t.e2)));
    const Real denominator = l0 * l1 * l2 + dot(t.r0, r1) * l2 + dot(t.r0, r2) * l1 + dot(r1, r2) * l0;
    t.solidAngle = 2.0 * atan(triple, denominator);
    t.alpha = atan(triple * l0, l0 * l0 * dot(t.e1, t.e2) - dot(t.r0, t.e1) * dot(t.r0, t.e2));
    t.crossAB = cross(t.r0, t.e1) / (l0 * l1); // R0 x R1 = R0 x e1
    t.cosArcAB = dot(t.r0, r1) / (l0 * l1);
    t.oneMinusCosArcAB = oneMinusCos(length(t.crossAB), t.cosArcAB);
    // C's component across A is e2's (R2 = R0 + e2 and R0 lies along A): no cancellation for a small
    // triangle.
    const RealVec3 across = t.e2 - dot(t.e2, t.a) * t.a;
    const Real acrossLength = length(across);
    t.tangentAC = acrossLength > 0.0 ? across / acrossLength : RealVec3(0.0);
    t.sinArcAC = acrossLength / l2;
    t.cosArcAC = dot(t.r0, r2) / (l0 * l2);
    return t;
}

/// The unit direction of Arvo's map at u in [0, 1]^2: uniform over the spherical triangle (density
/// 1 / solidAngle). u.x = 0 gives the arc from B to A, u.x = 1 the arc from B to C, u.y = 0 the vertex B
/// itself. Stage one: the point C' = cos(theta) A + sin(theta) tangentAC of the arc A C that cuts off area
/// Ah = u.x Omega. Arvo's q = cos(theta) = (K (1 - cos(alpha) t) - H) / (H - K sin(alpha) s) with
/// s = sin(Ah - alpha), t = cos(Ah - alpha), H = 1 - cos(Ah), K = 1 - cos(c) (his quotient with the factor
/// sin(alpha) cancelled and the sum and difference formulas expanded); then, exactly,
/// 1 - q = H (1 + cos c) / (H - K sin(alpha) s), whose terms have no cancellation while Ah < alpha.
/// Stage two: 1 - cos(arc B P) = u.y (1 - cos(arc B C')), with 1 - cos as half the squared chord.
RT_FN RealVec3 sphericalTriangleDirection(RT_IN(SphericalTriangle) t, vec2 u)
{
    const Real areaPart = Real(u.x) * t.solidAngle;
    const Real halfSine = preciseSin(0.5 * areaPart);
    const Real h = 2.0 * halfSine * halfSine;
    const Real denominator = h - t.oneMinusCosArcAB * preciseSin(t.alpha) * preciseSin(areaPart - t.alpha);
    // The denominator is at least H (1 + cos c) / 2 > 0 in exact arithmetic; rounding can reach 0 only where
    // C' runs to C (a triangle filling the hemisphere), and u.x = 0 gives 0 / 0: C' = A.
    Real oneMinusQ = h > 0.0 ? (denominator > 0.0 ? h * (1.0 + t.cosArcAB) / denominator : 2.0) : 0.0;
    // Never past C (the arc A C ends there), whatever the rounding.
    oneMinusQ = clamp(oneMinusQ, 0.0, oneMinusCos(t.sinArcAC, t.cosArcAC));
    const RealVec3 cutPoint =
        (1.0 - oneMinusQ) * t.a + sqrt(max(oneMinusQ * (2.0 - oneMinusQ), 0.0)) * t.tangentAC;
    const RealVec3 chord = cutPoint - t.b;
    const Real m = Real(u.y) * 0.5 * dot(chord, chord); // 1 - cos(arc B P)
    const RealVec3 across = chord - dot(chord, t.b) * t.b;
    const Real acrossLength = length(across);
    if (!(acrossLength > 0.0))
        return t.b;
    return (1.0 - m) * t.b + sqrt(max(m * (2.0 - m), 0.0)) * (across / acrossLength);
}

/// Barycentrics (b1, b2) (the point p0 + b1 e1 + b2 e2) where the ray from o along w meets the triangle's
/// plane (Moller & Trumbore 1997), clamped into the triangle and renormalised, so that a direction rounding
/// put just outside still gives a point on the light (pbrt-v4 §6.5.4 does the same). w parallel to the plane
/// (never for a triangle of some solid angle) gives the centroid.
RT_FN vec2 sphericalTrianglePoint(RT_IN(SphericalTriangle) t, RealVec3 w)
{
    const RealVec3 s1 = cross(w, t.e2);
    const Real det = dot(t.e1, s1);
    if (det == 0.0)
        return vec2(1.0f / 3.0f);
    const RealVec3 fromP0 = -t.r0; // o - p0
    Real b1 = clamp(dot(fromP0, s1) / det, 0.0, 1.0);
    Real b2 = clamp(dot(w, cross(fromP0, t.e1)) / det, 0.0, 1.0);
    const Real sum = b1 + b2;
    if (sum > 1.0)
    {
        b1 /= sum;
        b2 /= sum;
    }
    return vec2(float(b1), float(b2));
}

/// The u with which sphericalTriangleDirection gives the unit direction w of the spherical triangle (the
/// inverse pbrt-v4 credits to Arvo's SphTri.C). C' is where the great circle through B and w meets the arc
/// A C: C' = (mt A - ma tangentAC) / |.|, m = B x w, ma = m.A, mt = m.tangentAC, taking the sign on the arc's
/// side (C' . (A + C) > 0); u.x = area(A, B, C') / Omega (Van Oosterom & Strackee in the frame of A and the
/// tangent), u.y = (1 - w.B) / (1 - C'.B) as a ratio of squared chords. Near B, where C' is undefined, u.y
/// is 0 and u.x irrelevant to the cosine warp (whose weights at u = (0, 0) and (1, 0) agree).
RT_FN vec2 invertSphericalTriangle(RT_IN(SphericalTriangle) t, RealVec3 direction)
{
    const RealVec3 w = normalize(direction); // a float direction's length is 1 only to its rounding
    const RealVec3 m = cross(t.b, w);
    Real cosTheta = dot(m, t.tangentAC);
    Real sinTheta = -dot(m, t.a);
    const Real r = sqrt(cosTheta * cosTheta + sinTheta * sinTheta);
    if (!(r > 0.0) || !(t.solidAngle > 0.0))
        return vec2(0.0f);
    const Real side = cosTheta * (1.0 + t.cosArcAC) + sinTheta * t.sinArcAC >= 0.0 ? 1.0 : -1.0;
    cosTheta *= side / r;
    sinTheta *= side / r;
    if (sinTheta < 0.0) // before A
    {
        cosTheta = 1.0;
        sinTheta = 0.0;
    }
    else if (sinTheta * t.cosArcAC - cosTheta * t.sinArcAC > 0.0) // past C
    {
        cosTheta = t.cosArcAC;
        sinTheta = t.sinArcAC;
    }
    // area(A, B, C') by Van Oosterom & Strackee on unit vectors, with A . (B x C') = sin(theta) (A x B) .
    // tangent.
    const Real tripleABC = sinTheta * abs(dot(t.crossAB, t.tangentAC));
    const Real tangentB = dot(t.tangentAC, t.b);
    const Real areaPart = 2.0 * atan(tripleABC, (1.0 + t.cosArcAB) * (1.0 + cosTheta) + sinTheta * tangentB);
    const RealVec3 cutPoint = cosTheta * t.a + sinTheta * t.tangentAC;
    const RealVec3 toW = w - t.b;
    const RealVec3 toCut = cutPoint - t.b;
    const Real cutChord2 = dot(toCut, toCut);
    const Real v = cutChord2 > 0.0 ? dot(toW, toW) / cutChord2 : 0.0;
    return vec2(float(clamp(areaPart / t.solidAngle, 0.0, 1.0)), float(clamp(v, 0.0, 1.0)));
}

RT_SHADER_NAMESPACE_END

#endif
