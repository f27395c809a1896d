// One camera sample of one pixel, added to the accumulation image: the work of every ray-generation shader
// (RayGen.rgen, and RayGenCost.rgen, which times it). Needs the payload `payload` and Bindings.glsl.
#ifndef RT_CAMERA_SAMPLE_GLSL
#define RT_CAMERA_SAMPLE_GLSL

#include "Camera.glsl"
#include "Integrator.glsl"

/// Generates the camera ray of (pixel, sampleIndex), estimates its radiance, drops and counts non-finite
/// samples, and adds the rest to the accumulation image (rgb: radiance sum, a: sample count).
void accumulateCameraSample(uvec2 pixel, uint sampleIndex)
{
    Rng rng = rngForSample(uniforms.seed, pixel.y * uniforms.width + pixel.x, sampleIndex);
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
    ivec2 texel = ivec2(pixel);
    imageStore(accumulation, texel, imageLoad(accumulation, texel) + vec4(radiance, 1.0));
}

#endif
