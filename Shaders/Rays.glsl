// The rays both integrators trace: path rays to their first hit and NEE's shadow rays.
// Needs the payloads `payload` (location kPayloadPath) and `shadowVisible` (kPayloadShadow), the TLAS and the ray
// counters of Bindings.glsl; ray-generation shaders only (the counters' slot is the launch column).
#ifndef RT_RAYS_GLSL
#define RT_RAYS_GLSL

// Far enough for any scene, finite so that no driver sees an infinite interval.
const float kRayTMax = 3.0e38;

#include "RayCount.glsl"
#include "Shared/Lights/LightSample.h"

// This invocation's rays by kind (kRayCamera, kRayExtension, kRayShadow) and light samples (NEE's, restir-di's
// candidates') by outcome (drawn, fallback, declined: kCountLight*) since it began, for flushRayCounts.
uvec3 tracedRays = uvec3(0u);
uvec3 lightSamples = uvec3(0u);

/// Counts one ray of `kind` where the render counts rays (--count-rays) and the wavefront does not count its
/// queues instead; nothing at all (the constants fold it away) elsewhere.
void countRay(uint kind)
{
    if (settingCountRays() && !kWavefront)
        tracedRays[kind] += 1u;
}

/// Counts a vertex's light sample (ShadowRay::lightSample, Shared/PathState.h) as countRay counts rays.
void countLightSample(uint lightSample)
{
    if (settingCountRays() && !kWavefront)
        lightSamples += lightSampleOutcomes(lightSample);
}

/// Adds this invocation's counted rays and light samples to TraceCounters: the last thing every ray-generation
/// shader that traces does (the wavefront's are counted by Prepare.comp and Shade.comp).
void flushRayCounts()
{
    if (!settingCountRays() || kWavefront)
        return;
    for (uint kind = 0u; kind < kRayKinds; ++kind)
        if (tracedRays[kind] > 0u)
            addCount(gl_LaunchIDEXT.x, kind, tracedRays[kind]);
    for (uint outcome = 0u; outcome < 3u; ++outcome)
        if (lightSamples[outcome] > 0u)
            addCount(gl_LaunchIDEXT.x, kCountLightDrawn + outcome, lightSamples[outcome]);
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
