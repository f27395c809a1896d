// A pixel's running sum of camera samples in the accumulation images (rgb: radiance sum, a: sample count;
// the compensation image: what the sum lost to rounding), one sample after the other in sample order, so the
// sums do not depend on how many samples a launch traces: both integrators add their samples through it.
// The sum is Kahan's compensated sum: a plain float sum of 2^20 samples of 0.1 ends 1 % off (each addition
// rounds to an ulp of the sum), this one within 1e-7 (tests/Gpu/GpuStressTest.cpp). `precise` keeps the
// compiler from simplifying (t - sum) - y to 0.
// Needs the globals of Bindings.glsl.
#ifndef RT_SAMPLE_SUM_GLSL
#define RT_SAMPLE_SUM_GLSL

#include "Shared/Shading/Camera.h"

/// The accumulation texel of camera sample `sampleIndex` of `pixel`: its seed block's image (seedBlockOf), the
/// blocks one below the other.
ivec2 accumulationTexel(uvec2 pixel, uint sampleIndex)
{
    return ivec2(pixel.x, pixel.y + seedBlockOf(sampleIndex) * uniforms.height);
}

/// Adds the camera sample `radiance` to `sum` and its compensation `lost`; a non-finite sample is counted
/// (SampleCounters) and dropped.
void addCameraSample(inout vec4 sum, inout vec3 lost, vec3 radiance)
{
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
    precise vec3 lostNow = (t - sum.rgb) - y;
    lost = lostNow;
    sum = vec4(t, sum.a + 1.0);
}

#endif
