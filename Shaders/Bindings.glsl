// Descriptor set 0 of the ray-tracing pipeline, as HostDevice.h numbers it. Every stage includes this one
// declaration; the engine makes every binding visible to every ray-tracing stage.
// Needs GL_EXT_ray_tracing, GL_EXT_scalar_block_layout and GL_EXT_nonuniform_qualifier.
#ifndef RT_BINDINGS_GLSL
#define RT_BINDINGS_GLSL

#include "Shared/HostDevice.h"

layout(binding = kBindingTlas) uniform accelerationStructureEXT tlas;
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

layout(push_constant, scalar) uniform PushBlock { TracePushConstants push; };

/// The image pixel of this invocation: a launch covers a band of rows from push.firstRow, so that one
/// submit of a large image on a slow device stays short (cancellation waits for a submit).
uvec2 launchPixel() { return gl_LaunchIDEXT.xy + uvec2(0u, push.firstRow); }

#include "Specialization.glsl"

/// Where primitiveLights[] says which light primitive `primitive` of a record is (its entry may be kNoIndex),
/// or kNoIndex when no primitive of the record is a light (InstanceRecord::firstPrimitiveLight). Hit shaders
/// hand this on and raygen reads the entry only when it needs the light (an emitter hit after NEE): the load
/// in every closest-hit cost the H100 3 % of book 3's mixture, which never needs it.
uint primitiveLightSlot(InstanceRecord record, uint primitive)
{
    return record.firstPrimitiveLight == kNoIndex ? kNoIndex : record.firstPrimitiveLight + primitive;
}

#endif
