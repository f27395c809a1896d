// Ray Tracing: The Next Week (Shirley, v4.0.1): the scenes of §2-10.
#include "Random/Pcg.h"
#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
namespace
{
constexpr SceneDefaults kWide{.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = false, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};
constexpr SceneDefaults kSquare{.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = false, .estimator = Estimator::Mixture, .sampling = PixelSampling::Random};

/// RTTNW §5's two marble spheres: the ground (radius 1000) and one of radius 2 on it.
void marbleGroundAndSphere(SceneBuilder& b, std::uint32_t group)
{
    const std::uint32_t marble = b.lambertianTextured(b.perlin(TextureType::Marble, 4.0f));
    b.sphere(group, {0.0f, -1000.0f, 0.0f}, 1000.0f, marble);
    b.sphere(group, {0.0f, 2.0f, 0.0f}, 2.0f, marble);
}

void lookFrom13(Scene& s)
{
    s.camera.lookFrom = {13.0f, 2.0f, 3.0f};
    s.camera.lookAt = {0.0f, 0.0f, 0.0f};
    s.camera.vfovDegrees = 20.0f;
}
} // namespace

Scene rtnwMotionBlur(const SceneOptions&)
{
    SceneBuilder b("rtnw-motion-blur");
    const std::uint32_t w = b.world();
    const std::uint32_t checker = b.checker(0.32f, {0.2f, 0.3f, 0.1f}, vec3(0.9f));
    b.sphere(w, {0.0f, -1000.0f, 0.0f}, 1000.0f, b.lambertianTextured(checker));
    randomSphereField(b, w, 1u, true);
    b.sphere(w, {0.0f, 1.0f, 0.0f}, 1.0f, b.dielectric(1.5f));
    b.sphere(w, {-4.0f, 1.0f, 0.0f}, 1.0f, b.lambertian({0.4f, 0.2f, 0.1f}));
    b.sphere(w, {4.0f, 1.0f, 0.0f}, 1.0f, b.metal({0.7f, 0.6f, 0.5f}, 0.0f));
    Scene& s = b.scene();
    finalSceneCamera(s, 0.02f);
    s.defaults = kWide;
    setConstantBackground(s, kSky);
    return b.finish();
}

Scene rtnwCheckerSpheres(const SceneOptions&)
{
    SceneBuilder b("rtnw-checker-spheres");
    const std::uint32_t w = b.world();
    const std::uint32_t mat = b.lambertianTextured(b.checker(0.8f, {0.2f, 0.3f, 0.1f}, vec3(0.9f)));
    b.sphere(w, {0.0f, -10.0f, 0.0f}, 10.0f, mat);
    b.sphere(w, {0.0f, 10.0f, 0.0f}, 10.0f, mat);
    Scene& s = b.scene();
    lookFrom13(s);
    s.defaults = kWide;
    setConstantBackground(s, kSky);
    return b.finish();
}

Scene rtnwEarth(const SceneOptions&)
{
    SceneBuilder b("rtnw-earth");
    const std::uint32_t w = b.world();
    b.sphere(w, vec3(0.0f), 2.0f, b.lambertianTextured(b.image("textures/earth.jpg")));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 0.0f, 12.0f};
    s.camera.lookAt = vec3(0.0f);
    s.camera.vfovDegrees = 20.0f;
    s.defaults = kWide;
    setConstantBackground(s, kSky);
    return b.finish();
}

Scene rtnwPerlinSpheres(const SceneOptions&)
{
    SceneBuilder b("rtnw-perlin-spheres");
    const std::uint32_t w = b.world();
    marbleGroundAndSphere(b, w);
    Scene& s = b.scene();
    lookFrom13(s);
    s.defaults = kWide;
    setConstantBackground(s, kSky);
    return b.finish();
}

Scene rtnwQuads(const SceneOptions&)
{
    SceneBuilder b("rtnw-quads");
    const std::uint32_t w = b.world();
    b.quad(w, {-3, -2, 5}, {0, 0, -4}, {0, 4, 0}, b.lambertian({1.0f, 0.2f, 0.2f}));
    b.quad(w, {-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, b.lambertian({0.2f, 1.0f, 0.2f}));
    b.quad(w, {3, -2, 1}, {0, 0, 4}, {0, 4, 0}, b.lambertian({0.2f, 0.2f, 1.0f}));
    b.quad(w, {-2, 3, 1}, {4, 0, 0}, {0, 0, 4}, b.lambertian({1.0f, 0.5f, 0.0f}));
    b.quad(w, {-2, -3, 5}, {4, 0, 0}, {0, 0, -4}, b.lambertian({0.2f, 0.8f, 0.8f}));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 0.0f, 9.0f};
    s.camera.lookAt = vec3(0.0f);
    s.camera.vfovDegrees = 80.0f;
    s.defaults = kSquare;
    setConstantBackground(s, kSky);
    return b.finish();
}

Scene rtnwSimpleLight(const SceneOptions&)
{
    SceneBuilder b("rtnw-simple-light");
    const std::uint32_t w = b.world();
    marbleGroundAndSphere(b, w);
    const std::uint32_t light = b.diffuseLight(vec3(4.0f));
    b.sphere(w, {0.0f, 7.0f, 0.0f}, 2.0f, light);
    b.quad(w, {3, 1, -2}, {2, 0, 0}, {0, 2, 0}, light);
    Scene& s = b.scene();
    s.camera.lookFrom = {26.0f, 3.0f, 6.0f};
    s.camera.lookAt = {0.0f, 2.0f, 0.0f};
    s.camera.vfovDegrees = 20.0f;
    s.defaults = kWide;
    setConstantBackground(s, vec3(0.0f));
    return b.finish();
}

Scene rtnwCornellBox(const SceneOptions&)
{
    SceneBuilder b("rtnw-cornell-box");
    const std::uint32_t w = b.world();
    rtnwCornellWalls(b, w);
    b.quad(w, {343, 554, 332}, {-130, 0, 0}, {0, 0, -105}, b.diffuseLight(vec3(15.0f)));
    const std::uint32_t white = b.lambertian(vec3(0.73f));
    const std::uint32_t tall = b.group("tall box");
    b.box(tall, vec3(0.0f), {165, 330, 165}, white);
    b.instance(tall, Transform::translate({265, 0, 295}) * Transform::rotateY(15.0f));
    const std::uint32_t shortBox = b.group("short box");
    b.box(shortBox, vec3(0.0f), {165, 165, 165}, white);
    b.instance(shortBox, Transform::translate({130, 0, 65}) * Transform::rotateY(-18.0f));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = kSquare;
    s.defaults.spp = 200;
    return b.finish();
}

Scene rtnwCornellSmoke(const SceneOptions&)
{
    SceneBuilder b("rtnw-cornell-smoke");
    const std::uint32_t w = b.world();
    rtnwCornellWalls(b, w);
    b.quad(w, {113, 554, 127}, {330, 0, 0}, {0, 0, 305}, b.diffuseLight(vec3(7.0f)));
    const std::uint32_t tall = b.group("tall smoke");
    b.boxMedium(tall, vec3(0.0f), {165, 330, 165}, 0.01f, vec3(0.0f));
    b.instance(tall, Transform::translate({265, 0, 295}) * Transform::rotateY(15.0f));
    const std::uint32_t shortBox = b.group("short fog");
    b.boxMedium(shortBox, vec3(0.0f), {165, 165, 165}, 0.01f, vec3(1.0f));
    b.instance(shortBox, Transform::translate({130, 0, 65}) * Transform::rotateY(-18.0f));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = kSquare;
    s.defaults.spp = 200;
    return b.finish();
}

Scene rtnwFinal(const SceneOptions&)
{
    SceneBuilder b("rtnw-final");
    SceneRandom rnd(2u);
    const std::uint32_t ground = b.lambertian({0.48f, 0.83f, 0.53f});
    const std::uint32_t boxes = b.group("ground boxes");
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
        {
            const float width = 100.0f;
            const float x0 = -1000.0f + static_cast<float>(i) * width;
            const float z0 = -1000.0f + static_cast<float>(j) * width;
            const float y1 = rnd.uniform(1.0f, 101.0f);
            b.box(boxes, {x0, 0.0f, z0}, {x0 + width, y1, z0 + width}, ground);
        }
    b.instance(boxes, Transform::identity());

    const std::uint32_t w = b.world();
    b.quad(w, {123, 554, 147}, {300, 0, 0}, {0, 0, 265}, b.diffuseLight(vec3(7.0f)));
    const vec3 center1(400.0f, 400.0f, 200.0f);
    b.movingSphere(w, center1, center1 + vec3(30.0f, 0.0f, 0.0f), 50.0f, b.lambertian({0.7f, 0.3f, 0.1f}));
    b.sphere(w, {260, 150, 45}, 50.0f, b.dielectric(1.5f));
    b.sphere(w, {0, 150, 145}, 50.0f, b.metal({0.8f, 0.8f, 0.9f}, 1.0f));
    b.sphere(w, {360, 150, 145}, 70.0f, b.dielectric(1.5f));
    b.sphereMedium(w, {360, 150, 145}, 70.0f, 0.2f, {0.2f, 0.4f, 0.9f});
    b.sphereMedium(w, vec3(0.0f), 5000.0f, 0.0001f, vec3(1.0f));
    b.sphere(w, {400, 200, 400}, 100.0f, b.lambertianTextured(b.image("textures/earth.jpg")));
    b.sphere(w, {220, 280, 300}, 80.0f, b.lambertianTextured(b.perlin(TextureType::Marble, 0.1f)));

    const std::uint32_t cluster = b.group("sphere cluster");
    const std::uint32_t white = b.lambertian(vec3(0.73f));
    for (int j = 0; j < 1000; ++j)
    {
        const float x = rnd.uniform(0.0f, 165.0f);
        const float y = rnd.uniform(0.0f, 165.0f);
        const float z = rnd.uniform(0.0f, 165.0f);
        b.sphere(cluster, {x, y, z}, 10.0f, white);
    }
    b.instance(cluster, Transform::translate({-100, 270, 395}) * Transform::rotateY(15.0f));

    Scene& s = b.scene();
    s.camera.lookFrom = {478.0f, 278.0f, -600.0f};
    s.camera.lookAt = {278.0f, 278.0f, 0.0f};
    s.camera.vfovDegrees = 40.0f;
    s.defaults = kSquare;
    setConstantBackground(s, vec3(0.0f));
    return b.finish();
}
} // namespace rt::scenes
