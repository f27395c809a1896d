// A shadow ray (DirectLighting.glsl) that nothing stopped before its light: report it visible.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "Shared/HostDevice.h"

layout(location = kPayloadShadow) rayPayloadInEXT uint shadowVisible;

void main()
{
    shadowVisible = 1u;
}
