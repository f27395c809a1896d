#include "Render/RenderUniforms.h"

#include "Render/SettingsTable.h"
#include "Scene/Camera.h"

namespace rt
{
shader::RenderUniforms makeUniforms(const Scene& scene, const CameraDesc& cameraDesc, const RenderSettings& settings,
                                    std::uint32_t width, std::uint32_t height)
{
    const Camera camera(cameraDesc, static_cast<int>(width), static_cast<int>(height));
    shader::RenderUniforms u{};
    u.cameraCenter = camera.center;
    u.shutterOpen = camera.shutterOpen;
    u.pixel00 = camera.pixel00;
    u.shutterClose = camera.shutterClose;
    u.pixelDeltaU = camera.pixelDeltaU;
    u.thinLens = camera.thinLens ? 1u : 0u;
    u.pixelDeltaV = camera.pixelDeltaV;
    u.width = width;
    u.defocusDiskU = camera.defocusDiskU;
    u.height = height;
    u.defocusDiskV = camera.defocusDiskV;
    u.background0 = scene.background.color0;
    u.backgroundType = scene.background.type;
    u.background1 = scene.background.color1;
    u.strata = static_cast<std::uint32_t>(settings.strata());
    u.lightCount = static_cast<std::uint32_t>(scene.lights.size());
    u.emitterCount = scene.emitterCount();
    writeSettingUniforms(settings, u); // the settings table's (depth, estimator, samplers, seed, ...)
    return u;
}
} // namespace rt
