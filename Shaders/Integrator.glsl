// The path-tracing estimator of one camera sample, iterative (no recursion from hit shaders): the twin of
// the CPU engine's integrator. Per segment: trace; on a miss add the background; on a hit add the emission
// (front face only with unidirectional lights), stop on the last segment, else scatter by the material
// (BSDF only, or the book-3 mixture over the light list) and continue from an offset origin.
// Needs the payload `payload` (location 0) and the globals of Bindings.glsl.
#ifndef RT_INTEGRATOR_GLSL
#define RT_INTEGRATOR_GLSL

#include "Materials/Scatter.glsl"
#include "Payload.glsl"
#include "RayOffset.glsl"

// Far enough for any scene, finite so that no driver sees an infinite interval.
const float kRayTMax = 3.0e38;

/// Radiance along the camera ray (origin, direction). A non-finite direction ends the path with NaN, so the
/// sample is counted like the CPU engine's instead of reaching traversal (undefined for NaN rays).
vec3 traceRadiance(vec3 origin, vec3 direction, inout Rng rng)
{
    vec3 radiance = vec3(0.0);
    vec3 beta = vec3(1.0);
    for (uint segment = 0u; segment < uniforms.depth; ++segment)
    {
        if (!isFiniteVec(origin) || !isFiniteVec(direction))
            return vec3(uintBitsToFloat(0x7FC00000u)); // a quiet NaN
        traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, 0, origin, 0.0, direction, kRayTMax, 0);
        if (payload.material == kNoIndex)
        {
            radiance += beta * payload.background;
            break;
        }
        MaterialData m = materials[payload.material];
        bool medium = (payload.flags & kHitMedium) != 0u;
        SurfaceHit hit;
        hit.position = payload.position;
        hit.normal = payload.normal;
        hit.frontFace = medium || dot(direction, payload.normal) < 0.0;
        hit.shadingNormal = hit.frontFace ? payload.normal : -payload.normal;
        hit.uv = payload.uv;
        hit.incoming = direction;

        if (m.emissionTexture != kNoIndex && (uniforms.unidirectionalLight == 0u || hit.frontFace))
            radiance += beta * evaluateTexture(m.emissionTexture, hit.uv, hit.position);
        if (segment + 1u == uniforms.depth)
            break;

        ScatterSample s;
        if (!scatter(m, hit, rng, s))
            break;
        beta *= s.weight;
        origin = medium ? hit.position
                        : offsetRayOrigin(hit.position, dot(s.direction, hit.normal) > 0.0 ? hit.normal : -hit.normal,
                                          payload.offsetScale);
        direction = s.direction;
    }
    return radiance;
}

#endif
