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
    ivec2 texel = ivec2(bandOrderPixel(push.wavePixelBegin + q));
    vec4 sum = imageLoad(accumulation, texel);
    vec3 lost = imageLoad(compensation, texel).rgb;
    for (uint s = 0u; s < push.sampleCount; ++s)
        addCameraSample(sum, lost, uintBitsToFloat(waveFields[kWaveRadiance * push.waveCapacity + q * push.sampleCount + s].xyz));
    imageStore(accumulation, texel, sum);
    imageStore(compensation, texel, vec4(lost, 0.0));
}
