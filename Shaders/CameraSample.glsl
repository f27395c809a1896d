// Camera samples of one pixel, added to the accumulation image: the megakernel's work (RayGen.rgen, and
// RayGenCost.rgen, which times it). Needs the payload `payload` and Bindings.glsl.
#ifndef RT_CAMERA_SAMPLE_GLSL
#define RT_CAMERA_SAMPLE_GLSL

#include "Integrator.glsl"
#include "Shared/Shading/Camera.h"
#include "SampleSum.glsl"

/// Estimates the camera samples first .. first + count - 1 of `pixel` and adds them to its accumulation
/// texel in sample order (SampleSum.glsl; a launch's samples lie in one seed block: PathTracingPipeline).
/// Returns the texel's sample count afterwards.
float accumulateCameraSamples(uvec2 pixel, uint first, uint count)
{
    ivec2 texel = accumulationTexel(pixel, first);
    vec4 sum = imageLoad(accumulation, texel);
    vec3 lost = imageLoad(compensation, texel).rgb;
    // The launch's seed block worked out once (rngForBlockSample).
    const uint seed = cameraSampleSeed(first);
    const uint begin = sampleInSeedBlock(first);
    for (uint index = begin; index < begin + count; ++index)
    {
        Rng rng = rngForBlockSample(pixel, seed, index);
        CameraSample cs = drawBlockSample(rng, pixel, index);
        vec3 origin;
        vec3 direction;
        generateRay(cs, origin, direction);
        addCameraSample(sum, lost, traceRadiance(origin, direction, rng));
    }
    imageStore(accumulation, texel, sum);
    imageStore(compensation, texel, vec4(lost, 0.0));
    return sum.a;
}

#endif
