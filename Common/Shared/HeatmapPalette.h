// The heatmap's palette, written once for both sides like HostDevice.h: the display shader paints the cost
// image with it (Shaders/Display.frag) and the window's panel draws its colour scale with it (C++), so the
// legend is the image's own palette.
#ifndef RT_HEATMAP_PALETTE_H
#define RT_HEATMAP_PALETTE_H

#ifdef __cplusplus
#include <glm/glm.hpp>

namespace rt::shader
{
using vec3 = glm::vec3;
using glm::clamp;
#define RT_FUNCTION inline
#else
#define RT_FUNCTION
#endif

/// Linear RGB for t in [0, 1] (clamped): blue (cheap), cyan, green, yellow, red (expensive), linear between.
RT_FUNCTION vec3 heatmapColor(float t)
{
    float x = 4.0f * clamp(t, 0.0f, 1.0f);
    return vec3(clamp(x - 2.0f, 0.0f, 1.0f), clamp(x, 0.0f, 1.0f) - clamp(x - 3.0f, 0.0f, 1.0f),
                1.0f - clamp(x - 1.0f, 0.0f, 1.0f));
}

#undef RT_FUNCTION
#ifdef __cplusplus
} // namespace rt::shader
#endif

#endif // RT_HEATMAP_PALETTE_H
