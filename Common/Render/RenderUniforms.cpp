#include "Render/RenderUniforms.h"

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
    u.depth = static_cast<std::uint32_t>(settings.depth);
    u.background0 = scene.background.color0;
    u.backgroundType = scene.background.type;
    u.background1 = scene.background.color1;
    u.estimator = settings.estimator;
    u.sampling = settings.sampling;
    u.strata = static_cast<std::uint32_t>(settings.strata());
    u.seed = settings.seed;
    u.unidirectionalLight = settings.unidirectionalLight ? 1u : 0u;
    u.lightCount = static_cast<std::uint32_t>(scene.lights.size());
    u.emitterCount = scene.emitterCount();
    u.russianRoulette = settings.russianRoulette ? 1u : 0u;
    u.lightSampler = settings.lightSampler;
    u.lightSelection = settings.lightSelection;
    return u;
}
} // namespace rt
