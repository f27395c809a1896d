// A path ray that leaves the scene: no material, for the path vertex to add the background (Shared/Shading/Background.h).
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
    payload.material = kNoIndex;
}
