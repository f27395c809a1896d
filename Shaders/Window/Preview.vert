// The rasterised preview: triangles in world space (instance = identity) and spheres as instances of a unit
// sphere mesh. Colours come from the material (PreviewMesh.h); alpha 1: shaded, 0: emitter (drawn flat).
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "Shared/HostDevice.h"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) in vec4 instanceSphere; // centre, radius
layout(location = 4) in vec4 instanceColor;

layout(push_constant, scalar) uniform PushBlock { PreviewPushConstants push; };

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec4 albedo;

void main()
{
    worldPosition = instanceSphere.xyz + instanceSphere.w * position;
    worldNormal = normal;
    albedo = color * instanceColor;
    gl_Position = push.clipFromWorld * vec4(worldPosition, 1.0);
}
