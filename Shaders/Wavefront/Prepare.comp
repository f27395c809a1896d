// One invocation between the wavefront's kernels: the paths and shadow rays the last kernel queued become
// the sizes of the next indirect launches (WaveCounters), and the counts start again from 0. The paths are
// those of segment push.waveSegment.
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#define RT_COMPUTE_KERNEL
#include "Bindings.glsl"
#include "RayCount.glsl"

layout(local_size_x = 1) in;

void main()
{
    uint paths = waveCounters.pushed;
    // --count-rays: the next Extend traces these paths' rays (their camera rays at segment 0), the Shadow launch
    // after this kernel the shadow rays the last Shade queued.
    if (settingCountRays())
    {
        if (paths > 0u)
            addCount(0u, push.waveSegment == 0u ? kRayCamera : kRayExtension, paths);
        if (waveCounters.shadowsPushed > 0u)
            addCount(0u, kRayShadow, waveCounters.shadowsPushed);
    }
    waveCounters.extendRays = uvec4(paths, 1u, 1u, 0u);
    waveCounters.shadeGroups = uvec4((paths + kWaveGroupSize - 1u) / kWaveGroupSize, 1u, 1u, 0u);
    waveCounters.shadowRays = uvec4(waveCounters.shadowsPushed, 1u, 1u, 0u);
    waveCounters.pushed = 0u;
    waveCounters.shadowsPushed = 0u;
    if (paths > 0u)
        waveCounters.segments = push.waveSegment + 1u;
}
