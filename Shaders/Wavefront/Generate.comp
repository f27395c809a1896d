// The wavefront's first kernel: each path's camera ray (the megakernel's, CameraSample.glsl), its state in
// wavePaths[], and queue 0 (the paths to extend at segment 0): every path with a finite camera ray; the
// others end with NaN radiance, counted when summed.
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_ballot : require

#define RT_COMPUTE_KERNEL
#include "Bindings.glsl"
#include "Shared/Shading/Camera.h"
#include "Shared/Shading/PathVertex.h"
#include "Wavefront/QueueAppend.glsl"
#include "Wavefront/WavePath.glsl"

layout(local_size_x = kWaveGroupSize) in;

void main()
{
    uint p = gl_GlobalInvocationID.x;
    if (p >= push.wavePixelCount * push.sampleCount)
        return;
    uint orderIndex = push.wavePixelBegin + p / push.sampleCount; // in the band order, not the image's
    uint sampleIndex = push.firstSample + p % push.sampleCount;
    uvec2 pixel = bandOrderPixel(orderIndex);
    Rng rng = rngForCameraSample(pixel, sampleIndex);
    CameraSample cs = drawCameraSample(rng, pixel, sampleIndex);
    vec3 origin;
    vec3 direction;
    generateRay(cs, origin, direction);
    PathState path = startPath(origin, direction, rng);
    bool finite = isFiniteVec(origin) && isFiniteVec(direction);
    if (!finite)
        path.radiance = vec3(uintBitsToFloat(0x7FC00000u)); // a quiet NaN, as the megakernel returns
    storePath(p, path, pixel.y * uniforms.width + pixel.x, sampleIndex);
    uint slot = queueSlot(finite, kCounterPushed);
    if (finite)
        setWaveQueueEntry(0u, slot, p);
}
