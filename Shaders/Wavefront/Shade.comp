// The wavefront's vertices: one invocation per path extended at segment push.waveSegment, shaded by the path
// vertex both engines share (Shared/Shading/PathVertex.h), the megakernel's own; a path that goes on is queued for the next segment, a shadow
// ray for Shadow.rgen.
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require

#define RT_COMPUTE_KERNEL
#include "Bindings.glsl"
#include "Shared/Shading/PathVertex.h"
#include "RayCount.glsl"
#include "Wavefront/QueueAppend.glsl"
#include "Wavefront/WavePath.glsl"

layout(local_size_x = kWaveGroupSize) in;

/// --count-rays: the subgroup's light samples by outcome (ShadowRay::lightSample), one atomic per outcome a vertex
/// of the subgroup had. Every active invocation of the subgroup must call it.
void countLightSamples(uint lightSample)
{
    const uvec3 outcomes = lightSampleOutcomes(lightSample);
    for (uint outcome = 0u; outcome < 3u; ++outcome)
    {
        const uint n = subgroupBallotBitCount(subgroupBallot(outcomes[outcome] != 0u));
        if (n > 0u && subgroupElect())
            addCount(gl_WorkGroupID.x, kCountLightDrawn + outcome, n);
    }
}

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= waveCounters.extendRays.x)
        return;
    uint p = waveQueueEntry(push.waveSegment & 1u, i);
    PathState path = loadPath(p);
    uint pixel = waveField(kWaveOriginPixel, p).w;
    uint sampleIndex = waveField(kWaveDirectionSample, p).w;
    ShadowRay shadow;
    bool goesOn = shadePathVertex(path, push.waveSegment, loadHit(p), shadow, false);
    if (settingCountRays())
        countLightSamples(shadow.lightSample);
    if (goesOn && !(isFiniteVec(path.origin) && isFiniteVec(path.direction)))
    {
        path.radiance = vec3(uintBitsToFloat(0x7FC00000u)); // a quiet NaN, as the megakernel returns
        goesOn = false;
    }
    if (goesOn)
        storePath(p, path, pixel, sampleIndex);
    else // only its radiance is read again: by Shadow.rgen and Accumulate.comp
        setWaveField(kWaveRadiance, p, packWaveField(path.radiance, path.pendingSurvival));
    if (shadow.pending)
    {
        setWaveField(kWaveShadowOrigin, p, packWaveField(shadow.origin, shadow.distance));
        setWaveField(kWaveShadowDirection, p, packWaveField(shadow.direction, 0u));
        setWaveField(kWaveShadowLight, p, packWaveField(shadow.contribution, 0u));
    }
    uint shadowSlot = queueSlot(shadow.pending, kCounterShadowsPushed);
    if (shadow.pending)
        setWaveQueueEntry(kWaveShadowQueue, shadowSlot, p);
    uint slot = queueSlot(goesOn, kCounterPushed);
    if (goesOn)
        setWaveQueueEntry((push.waveSegment + 1u) & 1u, slot, p);
}
