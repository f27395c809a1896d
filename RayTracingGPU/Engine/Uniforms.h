// The per-render uniforms of the path tracer (HostDevice.h's RenderUniforms): the camera frame of a camera
// description for one image size, the settings and the scene's background. The camera is a parameter, not
// the scene's: the window's interactive camera reaches the next frame without touching the scene or its
// acceleration structures.
#pragma once

#include <cstdint>

#include "Render/RenderSettings.h"
#include "Scene/Scene.h"
#include "Shared/HostDevice.h"

namespace rt::gpu
{
shader::RenderUniforms makeUniforms(const Scene& scene, const CameraDesc& camera, const RenderSettings& settings,
                                    std::uint32_t width, std::uint32_t height);
} // namespace rt::gpu
