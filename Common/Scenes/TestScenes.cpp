// Scenes with known answers, for the accuracy tests of both engines.
#include "Scenes/SceneFactories.h"

namespace rt
{
Scene makeFurnace(float albedo, float radiance)
{
    SceneBuilder b("furnace");
    const std::uint32_t w = b.world();
    b.sphere(w, vec3(0.0f), 1.0f, b.emissiveLambertian(vec3(albedo), vec3(radiance)));
    Scene& s = b.scene();
    s.camera.lookFrom = vec3(0.0f);
    s.camera.lookAt = {0.0f, 0.0f, -1.0f};
    s.camera.vfovDegrees = 90.0f;
    s.defaults = {.spp = 64, .depth = 50, .width = 64, .aspect = 1.0f, .unidirectionalLight = false};
    scenes::setConstantBackground(s, vec3(0.0f));
    return b.finish();
}

namespace scenes
{
Scene furnace(const SceneOptions&) { return makeFurnace(0.5f, 0.5f); }
} // namespace scenes
} // namespace rt
