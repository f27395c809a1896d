// The window's ray-traced image: the accumulation image's radiance sum over its sample count, clamped and
// sRGB-encoded like a PNG written by the headless mode, or the heatmap of the cost image (ticks per sample).
// The viewport is the image's rectangle in the window (letterboxed, WindowLayout.h): each fragment shows the
// texel under its centre (nearest: magnified pixels stay pixels, as in the CPU window).
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "Shared/HeatmapPalette.h"
#include "Shared/HostDevice.h"
#include "Window/Srgb.glsl"

layout(binding = kDisplayBindingAccumulation, rgba32f) uniform readonly image2D accumulation;
layout(binding = kDisplayBindingCost, r32f) uniform readonly image2D cost;
layout(push_constant, scalar) uniform PushBlock { DisplayPushConstants push; };

layout(location = 0) out vec4 color;

void main()
{
    ivec2 texel = min(ivec2((gl_FragCoord.xy - push.imageOrigin) * push.texelsPerPixel), imageSize(accumulation) - 1);
    vec4 sum = imageLoad(accumulation, texel);
    float samples = max(sum.a, 1.0); // a pixel with no sample yet is black
    vec3 linear = push.mode == DisplayMode_Cost
                      ? heatmapColor(imageLoad(cost, texel).r / samples / push.costScale)
                      : sum.rgb / samples;
    color = displayColor(linear, push.encodeSrgb);
}
