// Camera samples of one pixel, added to the accumulation image: the work of every ray-generation shader
// (RayGen.rgen, and RayGenCost.rgen, which times it). Needs the payload `payload` and Bindings.glsl.
#ifndef RT_CAMERA_SAMPLE_GLSL
#define RT_CAMERA_SAMPLE_GLSL

#include "Camera.glsl"
#include "Integrator.glsl"

/// Estimates the camera samples first .. first + count - 1 of `pixel` and adds them to its accumulation
/// texel (rgb: radiance sum, a: sample count) one after the other, in sample order, so the sums do not
/// depend on how many samples a launch traces. Non-finite samples are counted and dropped. Returns the
/// texel's sample count afterwards.
float accumulateCameraSamples(uvec2 pixel, uint first, uint count)
{
    ivec2 texel = ivec2(pixel);
    vec4 sum = imageLoad(accumulation, texel);
    for (uint sampleIndex = first; sampleIndex < first + count; ++sampleIndex)
    {
        Rng rng = rngForCameraSample(pixel, sampleIndex);
        CameraSample cs = drawCameraSample(rng, pixel, sampleIndex);
        vec3 origin;
        vec3 direction;
        generateRay(cs, origin, direction);

        vec3 radiance = traceRadiance(origin, direction, rng);
        if (any(isnan(radiance)))
        {
            atomicAdd(counters.nanSamples, 1u);
            radiance = vec3(0.0);
        }
        else if (any(isinf(radiance)))
        {
            atomicAdd(counters.infSamples, 1u);
            radiance = vec3(0.0);
        }
        sum += vec4(radiance, 1.0);
    }
    imageStore(accumulation, texel, sum);
    return sum.a;
}

#endif
