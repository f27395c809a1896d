// Light selection by a light BVH, written once for both engines (Shared/ShaderLang.h): from the root, each
// interior node sends the choice to a child in proportion to the child's importance seen from the shading
// point, an upper bound of what the emitters below it can contribute there (Estevez Conty & Kulla 2018,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG, §4-5; pbrt-v4 §12.6.3,
// BVHLightSampler). The tree is built on the host (Sampling/LightBvh.h); GLSL reads it as the globals
// `lightBvh` and `lightBvhLeaves` (Bindings.glsl), C++ passes them (RT_ARRAY).
//
// An importance of 0 is a proof that nothing below the node reaches the point (every emitter faces away or
// lies below the receiver's horizon), so a light is never denied a sample it could have used: that is what
// keeps the selection unbiased. The pmf of any light (for the MIS weight of an emitter a BSDF ray hits) is
// the product of the same choices, walked up from the light's leaf.
#ifndef RT_SHARED_LIGHT_BVH_H
#define RT_SHARED_LIGHT_BVH_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// The builder keeps every leaf within this many levels of the root (a bound for the shaders' loops).
RT_CONST(uint, kLightBvhMaxDepth, 64u)

/// cos(max(0, a - b)) from the sines and cosines of angles a, b in [0, pi].
RT_FN float cosSubClamped(float sinA, float cosA, float sinB, float cosB)
{
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}

/// Importance of `node` at point p with receiver normal n (0 in a medium: no horizon), when emitters emit
/// from both faces (`twoSided`) or from their front only: the node's power over the squared distance to its
/// box's centre, times the largest emission cosine and the largest
/// receiver cosine any point of the box's bounding sphere can have (Estevez Conty & Kulla 2018, eq. 3; pbrt-v4
/// LightBounds::Importance). The receiver's cosine is signed (our diffuse lobes are one-sided): 0 when the
/// whole sphere is below the horizon.
/// Every selection and every MIS pmf evaluates this twice per tree level, one level after the other, so it is
/// written for a short chain of dependent operations: each sine and cosine is a square root of a difference
/// of squared lengths (taken at once, side by side), scaled by the one reciprocal distance, and the sines of
/// the angle differences are taken only where the difference is not clamped to 0: on the CPU a selection takes
/// 120 ns instead of 144 on cornell-box-lights, 317 instead of 397 on many-lights (`rt_bench
/// --benchmark_filter=SelectLight`, docs/notebook/PERFORMANCE.md §4.5).
RT_FN float lightBvhImportance(RT_IN(LightBvhNode) node, vec3 p, vec3 n, bool twoSided)
{
    const vec3 toCentre = node.centre - p;
    const float distance2 = lengthSquared(toCentre);
    // The squared distance to the centre, floored only near it: flooring it at the squared radius (every point
    // inside the bounding sphere alike) cost many-lights 12 % of its relMSE; pbrt-v4 floors it at half the
    // diagonal's length, which depends on the scene's units.
    const float importance = node.power / max(distance2, 0.1f * node.radius2);
    if (!(importance > 0.0f))
        return 0.0f; // no power, or a distance beyond float's range (its reciprocal below would be 0)
    // p inside the sphere: directions to it fill the sphere of directions, and both cosines bound to 1.
    if (distance2 <= node.radius2)
        return importance;
    const float inverseDistance = 1.0f / sqrt(distance2);
    // The cone of directions from p that can reach the bounding sphere: half-angle theta_b about the
    // direction to the centre, sin theta_b = r / d.
    const float sinB = sqrt(node.radius2) * inverseDistance;
    const float cosB = sqrt(distance2 - node.radius2) * inverseDistance;
    float cosEmission = 1.0f; // a cone of normals filling the sphere (spheres): any direction emits
    if (node.cosThetaO > -1.0f)
    {
        // The angle theta_w between the axis and the direction from the lights to p, less theta_o (the
        // normals' spread) and theta_b; emitters emit nothing beyond theta_e.
        const float axial = -dot(node.axis, toCentre); // d cos theta_w
        const float cosW = twoSided ? abs(axial) * inverseDistance : axial * inverseDistance;
        float cosX = 1.0f; // theta_x = max(0, theta_w - theta_o)
        float sinX = 0.0f;
        if (!(cosW > node.cosThetaO))
        {
            const float sinW = safeSqrt(distance2 - axial * axial) * inverseDistance;
            const float sinO = safeSqrt(1.0f - node.cosThetaO * node.cosThetaO);
            cosX = cosW * node.cosThetaO + sinW * sinO;
            sinX = sinW * node.cosThetaO - cosW * sinO;
        }
        cosEmission = cosSubClamped(sinX, cosX, sinB, cosB);
        if (!(cosEmission > node.cosThetaE))
            return 0.0f;
    }
    if (!(dot(n, n) > 0.0f))
        return importance * cosEmission;
    const float normal = dot(n, toCentre); // d cos theta_i
    const float cosI = normal * inverseDistance;
    const float cosReceiver =
        cosI > cosB ? 1.0f : cosI * cosB + safeSqrt(distance2 - normal * normal) * inverseDistance * sinB;
    return importance * cosEmission * max(cosReceiver, 0.0f);
}

/// The probability of the first child of interior node `index` at (p, n): its share of the two children's
/// importance, or -1 when neither can contribute.
/// `child` is the node's second child.
RT_FN float lightBvhFirstChildProbability(RT_ARRAY(LightBvhNode, lightBvh) uint index, uint child, vec3 p, vec3 n,
                                          bool twoSided)
{
    const float first = lightBvhImportance(lightBvh[index + 1u], p, n, twoSided);
    const float second = lightBvhImportance(lightBvh[child], p, n, twoSided);
    const float total = first + second;
    return total > 0.0f ? first / total : -1.0f;
}

/// One emitter for NEE at p (receiver normal n, 0 in a medium) from u in [0, 1), and its probability in `pmf`;
/// kNoIndex with pmf 0 when no emitter can contribute at p. u is rescaled at every level, so one number serves
/// the whole descent.
RT_FN uint selectLightBvh(RT_ARRAY(LightBvhNode, lightBvh) vec3 p, vec3 n, bool twoSided, float u,
                          RT_OUT(float) pmf)
{
    pmf = 1.0f;
    uint index = 0u;
    for (uint level = 0u; level < kLightBvhMaxDepth; ++level)
    {
        const uint child = lightBvh[index].child;
        if ((child & kLightBvhLeaf) != 0u)
        {
            if (lightBvh[index].power > 0.0f)
                return child & ~kLightBvhLeaf;
            break; // the tree of a scene without powered emitters
        }
        const float first = lightBvhFirstChildProbability(RT_PASS(lightBvh) index, child, p, n, twoSided);
        if (first < 0.0f)
            break;
        if (u < first)
        {
            u = min(u / first, kOneMinusEpsilon);
            pmf *= first;
            index = index + 1u;
        }
        else
        {
            u = min((u - first) / (1.0f - first), kOneMinusEpsilon);
            pmf *= 1.0f - first;
            index = child;
        }
    }
    pmf = 0.0f;
    return kNoIndex;
}

/// Probability that selectLightBvh picks `light` at (p, n): the product of the choices on the way from the
/// root to its leaf, found from the leaf upwards. 0 for an emitter without power (no leaf).
RT_FN float lightBvhPmf(RT_ARRAY(LightBvhNode, lightBvh) RT_ARRAY(uint, lightBvhLeaves) uint light, vec3 p, vec3 n,
                        bool twoSided)
{
    uint index = lightBvhLeaves[light];
    if (index == kNoIndex)
        return 0.0f;
    float pmf = 1.0f;
    for (uint level = 0u; level < kLightBvhMaxDepth; ++level)
    {
        const uint parent = lightBvh[index].parent;
        if (parent == kNoIndex)
            break;
        const float first =
            lightBvhFirstChildProbability(RT_PASS(lightBvh) parent, lightBvh[parent].child, p, n, twoSided);
        if (first < 0.0f)
            return 0.0f;
        pmf *= index == parent + 1u ? first : 1.0f - first;
        index = parent;
    }
    return pmf;
}

RT_SHADER_NAMESPACE_END

#endif
