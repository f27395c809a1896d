// The wavefront's last kernel: each pixel of the wave adds its paths' radiance to its sum in sample order
// (SampleSum.glsl, as the megakernel does), so the image does not depend on how a render is cut into waves.
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#define RT_COMPUTE_KERNEL
#include "Bindings.glsl"
#include "SampleSum.glsl"

layout(local_size_x = kWaveGroupSize) in;

void main()
{
    uint q = gl_GlobalInvocationID.x;
    if (q >= push.wavePixelCount)
        return;
    uvec2 pixel = bandOrderPixel(push.wavePixelBegin + q);
    ivec2 texel = accumulationTexel(pixel, push.firstSample);
    vec4 sum = imageLoad(accumulation, texel);
    vec3 lost = imageLoad(compensation, texel).rgb;
    for (uint s = 0u; s < push.sampleCount; ++s)
    {
        // A wave's samples may cross into the next seed block: each block's sum apart.
        ivec2 blockTexel = accumulationTexel(pixel, push.firstSample + s);
        if (blockTexel != texel)
        {
            imageStore(accumulation, texel, sum);
            imageStore(compensation, texel, vec4(lost, 0.0));
            texel = blockTexel;
            sum = imageLoad(accumulation, texel);
            lost = imageLoad(compensation, texel).rgb;
        }
        addCameraSample(sum, lost, uintBitsToFloat(waveFields[kWaveRadiance * push.waveCapacity + q * push.sampleCount + s].xyz));
    }
    imageStore(accumulation, texel, sum);
    imageStore(compensation, texel, vec4(lost, 0.0));
}
