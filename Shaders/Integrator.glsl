// The megakernel's path-tracing estimator of one camera sample (RayGen.rgen): a loop over segments in one
// invocation, iterative (no recursion from hit shaders), each vertex shaded by the path vertex both engines
// share (Shared/Shading/PathVertex.h), NEE's shadow
// ray traced at the end of its vertex: across that trace only the path's own state lives (the hit, its
// material and the light sample are dead by then), which the GPU keeps in registers.
// Needs the payloads `payload` (location kPayloadPath) and `shadowVisible` (kPayloadShadow) and the globals of
// Bindings.glsl.
#ifndef RT_INTEGRATOR_GLSL
#define RT_INTEGRATOR_GLSL

#include "Rays.glsl"
#include "Shared/Shading/PathVertex.h"

/// Radiance along the camera ray (origin, direction). A non-finite direction ends the path with NaN, so the
/// sample is counted like the CPU engine's instead of reaching traversal (undefined for NaN rays).
vec3 traceRadiance(vec3 origin, vec3 direction, inout Rng rng)
{
    PathState path = startPath(origin, direction, rng);
    for (uint segment = 0u; segment < uniforms.depth; ++segment)
    {
        if (!isFiniteVec(path.origin) || !isFiniteVec(path.direction))
            return vec3(uintBitsToFloat(0x7FC00000u)); // a quiet NaN
        traceToFirstHit(path.origin, path.direction, segment == 0u);
        ShadowRay shadow;
        bool goesOn = shadePathVertex(path, segment, payload, shadow, false);
        countLightSample(shadow.lightSample);
        if (shadow.pending && unoccluded(shadow.origin, shadow.direction, shadow.distance))
            path.radiance += shadow.contribution;
        if (!goesOn)
            break;
    }
    rng = path.rng;
    return path.radiance;
}

#endif
