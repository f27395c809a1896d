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
/// The sum is Kahan's compensated sum, its compensation kept in its own image between launches: a plain
/// float sum of 2^20 samples of 0.1 ends 1 % off (each addition rounds to an ulp of the sum), this one
/// within 1e-7 (tests/Gpu/GpuStressTest.cpp). `precise` keeps the compiler from simplifying
/// (t - sum) - y to 0.
float accumulateCameraSamples(uvec2 pixel, uint first, uint count)
{
    ivec2 texel = ivec2(pixel);
    vec4 sum = imageLoad(accumulation, texel);
    precise vec3 lost = imageLoad(compensation, texel).rgb;
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
        precise vec3 y = radiance - lost;
        precise vec3 t = sum.rgb + y;
        lost = (t - sum.rgb) - y;
        sum = vec4(t, sum.a + 1.0);
    }
    imageStore(accumulation, texel, sum);
    imageStore(compensation, texel, vec4(lost, 0.0));
    return sum.a;
}

#endif
