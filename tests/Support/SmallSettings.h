// Render settings for a test (or a benchmark) of a scene: the size, spp and depth the test chooses, the
// scene's own aspect ratio and emitter sidedness, everything else the RenderSettings defaults.
#pragma once

#include "Render/RenderSettings.h"
#include "Scene/Scene.h"

namespace rt::test
{
inline RenderSettings settingsFor(const Scene& scene, int width, int spp, int depth)
{
    RenderSettings s;
    s.width = width;
    s.aspect = scene.defaults.aspect;
    s.spp = spp;
    s.depth = depth;
    s.unidirectionalLight = scene.defaults.unidirectionalLight;
    return s;
}
} // namespace rt::test
