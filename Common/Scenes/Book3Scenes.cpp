// Ray Tracing: The Rest of Your Life (Shirley, v4.0.1): the Cornell boxes of §12.
#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
namespace
{
constexpr SceneDefaults kBook3{.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};

/// Walls, the ceiling light (faces down) and the tall box with `tallMaterial`; returns the world group.
std::uint32_t book3Box(SceneBuilder& b, std::uint32_t tallMaterial)
{
    const std::uint32_t w = b.world();
    rtrolCornellWalls(b, w);
    b.quad(w, {213, 554, 227}, {130, 0, 0}, {0, 0, 105}, b.diffuseLight(vec3(15.0f)));
    const std::uint32_t tall = b.group("tall box");
    b.box(tall, vec3(0.0f), {165, 330, 165}, tallMaterial);
    b.instance(tall, Transform::translate({265, 0, 295}) * Transform::rotateY(15.0f));
    return w;
}

void shortBox(SceneBuilder& b)
{
    const std::uint32_t g = b.group("short box");
    b.box(g, vec3(0.0f), {165, 165, 165}, b.lambertian(vec3(0.73f)));
    b.instance(g, Transform::translate({130, 0, 65}) * Transform::rotateY(-18.0f));
}

Scene finishBook3(SceneBuilder& b)
{
    cornellCamera(b.scene());
    b.scene().defaults = kBook3;
    return b.finish();
}
} // namespace

Scene rtrolCornellBox(const SceneOptions&)
{
    SceneBuilder b("rtrol-cornell-box");
    book3Box(b, b.lambertian(vec3(0.73f)));
    shortBox(b);
    return finishBook3(b);
}

Scene rtrolCornellMirror(const SceneOptions&)
{
    SceneBuilder b("rtrol-cornell-mirror");
    book3Box(b, b.metal({0.8f, 0.85f, 0.88f}, 0.0f));
    shortBox(b);
    return finishBook3(b);
}

Scene rtrolCornellGlass(const SceneOptions&)
{
    SceneBuilder b("rtrol-cornell-glass");
    const std::uint32_t w = book3Box(b, b.lambertian(vec3(0.73f)));
    b.sphere(w, {190, 90, 190}, 90.0f, b.dielectric(1.5f));
    b.samplingTargetSphere({190, 90, 190}, 90.0f); // RTTROYL §12.5: aim light samples at the glass too
    return finishBook3(b);
}
} // namespace rt::scenes
