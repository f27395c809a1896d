// Ray Tracing in One Weekend (Shirley, v4.0.1): the scenes of §12-14.
#include <cmath>

#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
Scene rtowDefault(const SceneOptions&)
{
    SceneBuilder b("rtow-default");
    const std::uint32_t w = b.world();
    b.sphere(w, {0.0f, -100.5f, -1.0f}, 100.0f, b.lambertian({0.8f, 0.8f, 0.0f}));
    b.sphere(w, {0.0f, 0.0f, -1.0f}, 0.5f, b.lambertian({0.1f, 0.2f, 0.5f}));
    b.sphere(w, {-1.0f, 0.0f, -1.0f}, 0.5f, b.dielectric(1.5f));
    b.sphere(w, {-1.0f, 0.0f, -1.0f}, 0.4f, b.dielectric(1.0f / 1.5f)); // the air bubble inside the glass
    b.sphere(w, {1.0f, 0.0f, -1.0f}, 0.5f, b.metal({0.8f, 0.6f, 0.2f}, 1.0f));
    Scene& s = b.scene();
    s.camera.lookFrom = {-2.0f, 2.0f, 1.0f};
    s.camera.lookAt = {0.0f, 0.0f, -1.0f};
    s.camera.vfovDegrees = 20.0f;
    s.camera.defocusAngleDegrees = 10.0f;
    s.camera.focusDistance = 3.4f;
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = false, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};
    setGradientSky(s);
    return b.finish();
}

Scene rtowCameraTest(const SceneOptions&)
{
    SceneBuilder b("rtow-camera-test");
    const std::uint32_t w = b.world();
    const float r = std::cos(kPi / 4.0f);
    b.sphere(w, {-r, 0.0f, -1.0f}, r, b.lambertian({0.0f, 0.0f, 1.0f}));
    b.sphere(w, {r, 0.0f, -1.0f}, r, b.lambertian({1.0f, 0.0f, 0.0f}));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 0.0f, 0.0f};
    s.camera.lookAt = {0.0f, 0.0f, -1.0f};
    s.camera.vfovDegrees = 90.0f;
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = false, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};
    setGradientSky(s);
    return b.finish();
}

Scene rtowFinal(const SceneOptions&)
{
    SceneBuilder b("rtow-final");
    const std::uint32_t w = b.world();
    b.sphere(w, {0.0f, -1000.0f, 0.0f}, 1000.0f, b.lambertian(vec3(0.5f)));
    randomSphereField(b, w, 1u, false);
    b.sphere(w, {0.0f, 1.0f, 0.0f}, 1.0f, b.dielectric(1.5f));
    b.sphere(w, {-4.0f, 1.0f, 0.0f}, 1.0f, b.lambertian({0.4f, 0.2f, 0.1f}));
    b.sphere(w, {4.0f, 1.0f, 0.0f}, 1.0f, b.metal({0.7f, 0.6f, 0.5f}, 0.0f));
    Scene& s = b.scene();
    finalSceneCamera(s, 0.6f);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = false, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};
    setGradientSky(s);
    return b.finish();
}
} // namespace rt::scenes
