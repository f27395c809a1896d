// Closest hit in a medium: scatter where the ray is, with the medium's isotropic phase material.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#include "Bindings.glsl"
#include "Payload.glsl"

layout(location = kPayloadPath) rayPayloadInEXT HitPayload payload;

void main()
{
    MediumRecord medium = media[instances[gl_InstanceCustomIndexEXT].firstMedium + gl_PrimitiveID];
    payload.position = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
    payload.normal = vec3(1.0, 0.0, 0.0); // arbitrary: a medium has no surface
    payload.uv = vec2(0.0);
    payload.material = medium.phaseMaterial;
    payload.lightSlot = kNoIndex;
    payload.flags = kHitMedium;
    payload.offsetScale = 1.0; // unused: a scattering event inside a medium is not offset
}
