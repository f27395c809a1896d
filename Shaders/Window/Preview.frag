// Head-light shading: the albedo scaled by how squarely the surface faces the camera, both sides lit (quads
// and open meshes are seen from either side); emitters flat.
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "Shared/HostDevice.h"
#include "Window/Srgb.glsl"

layout(push_constant, scalar) uniform PushBlock { PreviewPushConstants push; };

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec4 albedo;

layout(location = 0) out vec4 color;

void main()
{
    float facing = abs(dot(normalize(worldNormal), normalize(push.eye - worldPosition)));
    float light = mix(1.0, 0.2 + 0.8 * facing, albedo.a);
    color = displayColor(albedo.rgb * light, push.encodeSrgb);
}
