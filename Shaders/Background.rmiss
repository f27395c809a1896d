// A ray that leaves the scene: report the background radiance in its direction.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#include "Bindings.glsl"
#include "Payload.glsl"
#include "Background.glsl"

layout(location = kPayloadPath) rayPayloadInEXT HitPayload payload;

void main()
{
    payload.material = kNoIndex;
    payload.background = background(gl_WorldRayDirectionEXT);
}
