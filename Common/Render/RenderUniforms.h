// A render's uniforms (HostDevice.h's RenderUniforms), what both engines' shading reads besides the scene
// (Shared/Shading/): the camera frame of a camera description for one image size, the settings and the scene's
// background. The camera is a parameter, not the scene's: the GPU window's interactive camera reaches the next
// frame without touching the scene or its acceleration structures.
#pragma once

#include <cstdint>

#include "Render/RenderSettings.h"
#include "Scene/Scene.h"
#include "Shared/HostDevice.h"

namespace rt
{
/// The uniforms of `settings` with `camera`, for an image of width x height pixels.
shader::RenderUniforms makeUniforms(const Scene& scene, const CameraDesc& camera, const RenderSettings& settings,
                                    std::uint32_t width, std::uint32_t height);
} // namespace rt
