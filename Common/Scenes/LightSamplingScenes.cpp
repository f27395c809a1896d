// The light-sampling test scenes of shared/spec/scenes.md: one light filling much of the hemisphere of the
// floor near it, where the choice of light sampler matters most.
#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
namespace
{
constexpr float kWhite = 0.73f; // the Cornell box's white (RTTROYL §12)

/// A white Lambertian floor, 4000 x 4000 centred at the origin in y = 0, facing up.
void whiteFloor(SceneBuilder& b, std::uint32_t group)
{
    b.quad(group, {-2000.0f, 0.0f, 2000.0f}, {4000.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -4000.0f}, b.lambertian(vec3(kWhite)));
}

void closeupDefaults(Scene& s)
{
    s.defaults = {.spp = 64, .depth = 50, .width = 800, .aspect = 16.0f / 9.0f, .unidirectionalLight = true};
    setConstantBackground(s, vec3(0.0f));
}
} // namespace

Scene rectLightCloseup(const SceneOptions&)
{
    SceneBuilder b("rect-light-closeup");
    const std::uint32_t w = b.world();
    whiteFloor(b, w);
    // Upright, 5 units above the floor, its front (u x v = -z) towards the camera.
    b.quad(w, {200.0f, 5.0f, 0.0f}, {-400.0f, 0.0f, 0.0f}, {0.0f, 200.0f, 0.0f}, b.diffuseLight(vec3(4.0f)));
    b.sphere(w, {0.0f, 20.0f, -60.0f}, 20.0f, b.lambertian(vec3(kWhite)));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 300.0f, -500.0f};
    s.camera.lookAt = {0.0f, 0.0f, -100.0f};
    s.camera.vfovDegrees = 45.0f;
    closeupDefaults(s);
    return b.finish();
}

Scene sphereLightCloseup(const SceneOptions&)
{
    SceneBuilder b("sphere-light-closeup");
    const std::uint32_t w = b.world();
    whiteFloor(b, w);
    b.sphere(w, {0.0f, 110.0f, 0.0f}, 100.0f, b.diffuseLight(vec3(4.0f)));
    b.sphere(w, {160.0f, 20.0f, 0.0f}, 20.0f, b.lambertian(vec3(kWhite)));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 250.0f, -600.0f};
    s.camera.lookAt = {0.0f, 0.0f, 0.0f};
    s.camera.vfovDegrees = 50.0f;
    closeupDefaults(s);
    return b.finish();
}
} // namespace rt::scenes
