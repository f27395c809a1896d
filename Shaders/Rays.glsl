// The rays both integrators trace: path rays to their first hit and NEE's shadow rays.
// Needs the payloads `payload` (location kPayloadPath) and `shadowVisible` (kPayloadShadow), the TLAS and the ray
// counters of Bindings.glsl; ray-generation shaders only (the counters' slot is the launch column).
#ifndef RT_RAYS_GLSL
#define RT_RAYS_GLSL

// Far enough for any scene, finite so that no driver sees an infinite interval.
const float kRayTMax = 3.0e38;

/// Counts one ray of `kind` (kRayCamera, kRayExtension, kRayShadow) in RayCounters where the render counts rays;
/// nothing at all (the constant folds it away) where it does not.
void countRay(uint kind)
{
    if (!settingCountRays())
        return;
    const uint word = ((gl_LaunchIDEXT.x % kRayCounterSlots) * kRayKinds + kind) * 2u;
    if (atomicAdd(rayCounters.words[word], 1u) == 0xFFFFFFFFu)
        atomicAdd(rayCounters.words[word + 1u], 1u);
}

/// Traces the path ray (origin, direction) into `payload`: its closest hit, or the background (Background.rmiss).
/// `camera`: the path's first segment (counted as a camera ray), else an extension ray. The ray must be finite
/// (traversal is undefined for NaN rays).
void traceToFirstHit(vec3 origin, vec3 direction, bool camera)
{
    countRay(camera ? kRayCamera : kRayExtension);
    traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, kMissBackground, origin, 0.0, direction, kRayTMax,
                int(kPayloadPath));
}

/// True when nothing lies between origin and origin + tMax direction: a shadow ray that stops at the first
/// hit and runs no closest-hit shader, with a payload of one word; only its miss shader (Shadow.rmiss) sets
/// it. A medium on the way stops it with the probability 1 - transmittance, as on the CPU.
bool unoccluded(vec3 origin, vec3 direction, float tMax)
{
    countRay(kRayShadow);
    shadowVisible = 0u;
    traceRayEXT(tlas, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT,
                0xFF, 0, 1, kMissShadow, origin, 0.0, direction, tMax, int(kPayloadShadow));
    return shadowVisible != 0u;
}

#endif
