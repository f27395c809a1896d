// Descriptor set 0 of the path tracer, as HostDevice.h numbers it. Every stage includes this one declaration;
// the engine makes every binding visible to every ray-tracing stage and to the wavefront's compute kernels.
// With Specialization.glsl it is the shaders' host of the shared shading (Common/Shared/Shading/README.md): the
// globals it names, and the two functions each host writes for itself, emitterOfSlot and imageTexel.
// Needs GL_EXT_scalar_block_layout and GL_EXT_nonuniform_qualifier, and GL_EXT_ray_tracing in a ray-tracing
// stage; a compute kernel defines RT_COMPUTE_KERNEL first (it sees neither the TLAS nor a launch).
#ifndef RT_BINDINGS_GLSL
#define RT_BINDINGS_GLSL

#include "Shared/BandOrder.h"
#include "Shared/HostDevice.h"

#ifndef RT_COMPUTE_KERNEL
layout(binding = kBindingTlas) uniform accelerationStructureEXT tlas;
#endif
layout(binding = kBindingAccumulation, rgba32f) uniform image2D accumulation; // rgb: radiance sum, a: samples
layout(binding = kBindingUniforms, scalar) uniform UniformBlock { RenderUniforms uniforms; };
layout(binding = kBindingMaterials, scalar) readonly buffer MaterialBlock { MaterialData materials[]; };
layout(binding = kBindingTextures, scalar) readonly buffer TextureBlock { TextureData textures[]; };
layout(binding = kBindingLights, scalar) readonly buffer LightBlock { LightData lights[]; };
layout(binding = kBindingPerlin, scalar) readonly buffer PerlinBlock { PerlinData perlinTables; };
layout(binding = kBindingInstances, scalar) readonly buffer InstanceBlock { InstanceRecord instances[]; };
layout(binding = kBindingPositions, scalar) readonly buffer PositionBlock { vec3 positions[]; };
layout(binding = kBindingUvs, scalar) readonly buffer UvBlock { vec2 uvs[]; };
layout(binding = kBindingTriangles, scalar) readonly buffer TriangleBlock { uvec3 triangles[]; };
layout(binding = kBindingTriangleMaterials, scalar) readonly buffer TriangleMaterialBlock { uint triangleMaterials[]; };
layout(binding = kBindingSpheres, scalar) readonly buffer SphereBlock { SphereRecord spheres[]; };
layout(binding = kBindingMedia, scalar) readonly buffer MediumBlock { MediumRecord media[]; };
layout(binding = kBindingCounters, scalar) buffer CounterBlock { SampleCounters counters; };
layout(binding = kBindingTraceCounters, scalar) buffer TraceCounterBlock { TraceCounters traceCounters; };
layout(binding = kBindingPrimitiveLights, scalar) readonly buffer PrimitiveLightBlock { uint primitiveLights[]; };
layout(binding = kBindingLightAlias, scalar) readonly buffer LightAliasBlock { AliasEntry lightAlias[]; };
layout(binding = kBindingLightBvh, scalar) readonly buffer LightBvhBlock { LightBvhNode lightBvh[]; };
layout(binding = kBindingLightBvhLeaves, scalar) readonly buffer LightBvhLeafBlock { uint lightBvhLeaves[]; };
layout(binding = kBindingMixtureLights, scalar) uniform MixtureLightBlock
{
    LightData mixtureLights[kMixtureUniformLights];
};
// rgb: what the float sum above lost to rounding (Kahan), to subtract from the next sample; a: unused.
layout(binding = kBindingCompensation, rgba32f) uniform image2D compensation;
layout(binding = kBindingImages) uniform sampler2D images[];
layout(binding = kBindingWavePaths, std430) buffer WavePathBlock { uvec4 waveFields[]; };
layout(binding = kBindingWaveQueues, scalar) buffer WaveQueueBlock { uint waveQueues[]; };
layout(binding = kBindingWaveCounters, scalar) buffer WaveCounterBlock { WaveCounters waveCounters; };
layout(binding = kBindingRestirSurfaces, scalar) buffer RestirSurfaceBlock { RestirSurface restirSurfaces[]; };
layout(binding = kBindingRestirTemporal, scalar) buffer RestirTemporalBlock { Reservoir restirTemporal[]; };
layout(binding = kBindingRestirFinal, scalar) buffer RestirFinalBlock { Reservoir restirFinal[]; };
layout(binding = kBindingRestirTraced, scalar) buffer RestirTracedBlock { uvec2 restirTraced[]; };

layout(push_constant, scalar) uniform PushBlock { TracePushConstants push; };

#include "Specialization.glsl"

/// The image pixel at `index` = position * width + x of the frame's row order (push.rowInterleave's:
/// Shared/BandOrder.h), where a band's pixels lie from push.firstRow * width on.
uvec2 bandOrderPixel(uint index)
{
    return uvec2(index % uniforms.width, bandOrderRow(index / uniforms.width, uniforms.height, push.rowInterleave));
}

#ifndef RT_COMPUTE_KERNEL
/// The image pixel of this invocation of the megakernel (RayGen.rgen): a launch covers a band of rows, from
/// position push.firstRow on in the frame's row order, so that one submit of a large image on a slow device
/// stays short (cancellation waits for a submit).
uvec2 launchPixel()
{
    return uvec2(gl_LaunchIDEXT.x,
                 bandOrderRow(gl_LaunchIDEXT.y + push.firstRow, uniforms.height, push.rowInterleave));
}

/// The pixel and the sample index of the path whose ray this invocation traces, for the intersection shaders,
/// which cannot read the payload: in the wavefront, the path of the launch's queue entry; in restir-di's passes,
/// the camera sample its launch pixel's slot of restirTraced names (Restir/RestirHost.glsl); in the megakernel,
/// the launch's pixel and first sample (a scene whose intersection shaders need the sample, a moving one, is
/// traced there one sample per launch; the media's need only its seed block, and a launch stays within one).
uint tracedWavePath() { return waveQueues[push.waveQueue * push.waveCapacity + gl_LaunchIDEXT.x]; }
uint restirTracedSlot()
{
    uvec2 pixel = launchPixel();
    return pixel.y * uniforms.width + pixel.x;
}
uvec2 tracedPixel()
{
    if (kRestirPass)
    {
        uint pixel = restirTraced[restirTracedSlot()].x;
        return uvec2(pixel % uniforms.width, pixel / uniforms.width);
    }
    if (kWavefront)
    {
        uint pixel = waveFields[kWaveOriginPixel * push.waveCapacity + tracedWavePath()].w;
        return uvec2(pixel % uniforms.width, pixel / uniforms.width);
    }
    return launchPixel();
}
uint tracedSample()
{
    if (kRestirPass)
        return restirTraced[restirTracedSlot()].y;
    if (kWavefront)
        return waveFields[kWaveDirectionSample * push.waveCapacity + tracedWavePath()].w;
    return push.firstSample;
}
#endif

/// Where primitiveLights[] says which light primitive `primitive` of a record is (its entry may be kNoIndex),
/// or kNoIndex when no primitive of the record is a light (InstanceRecord::firstPrimitiveLight) or the
/// estimator is not NEE. Hit shaders hand this on and raygen reads the entry only when it needs the light (an
/// emitter hit after NEE, weighted by MIS or by 0): the load in every closest-hit cost the H100 3 % of book 3's
/// mixture, which never needs it, and the record's field alone up to 3 % on the H200 (docs/notebook/PERFORMANCE.md §8.10).
uint primitiveLightSlot(InstanceRecord record, uint primitive)
{
    if (!settingUsesNee())
        return kNoIndex;
    return record.firstPrimitiveLight == kNoIndex ? kNoIndex : record.firstPrimitiveLight + primitive;
}

/// Whether the mixture reads the scene's first lights from mixtureLights, a uniform buffer (HostDevice.h
/// kMixtureUniformLights).
const bool kHostHasMixtureLights = true;

/// The light of a hit's primitive (HitPayload::lightSlot, from primitiveLightSlot), or kNoIndex.
uint emitterOfSlot(uint slot)
{
    return slot == kNoIndex ? kNoIndex : primitiveLights[slot];
}

#include "Textures/ImageTexture.glsl"

#endif
