#include "Scenes/SceneFactories.h"

#include "Random/Pcg.h"

namespace rt::scenes
{
void setGradientSky(Scene& scene)
{
    scene.background = {BackgroundType::Gradient, vec3(1.0f), vec3(0.5f, 0.7f, 1.0f)};
}

void setConstantBackground(Scene& scene, const vec3& color)
{
    scene.background = {BackgroundType::Constant, color, color};
}

void randomSphereField(SceneBuilder& b, std::uint32_t g, std::uint32_t seed, bool moving)
{
    SceneRandom rnd(seed);
    const auto rnd3 = [&rnd](float lo, float hi) {
        const float x = rnd.uniform(lo, hi);
        const float y = rnd.uniform(lo, hi);
        const float z = rnd.uniform(lo, hi);
        return vec3(x, y, z);
    };
    for (int a = -11; a < 11; ++a)
        for (int c = -11; c < 11; ++c)
        {
            const float choose = rnd.uniform();
            const float dx = rnd.uniform();
            const float dz = rnd.uniform();
            const vec3 center(static_cast<float>(a) + 0.9f * dx, 0.2f, static_cast<float>(c) + 0.9f * dz);
            if (glm::length(center - vec3(4.0f, 0.2f, 0.0f)) <= 0.9f)
                continue;
            if (choose < 0.8f)
            {
                const vec3 c1 = rnd3(0.0f, 1.0f);
                const vec3 c2 = rnd3(0.0f, 1.0f);
                const std::uint32_t mat = b.lambertian(c1 * c2);
                if (moving)
                {
                    const float rise = rnd.uniform(0.0f, 0.5f);
                    b.movingSphere(g, center, center + vec3(0.0f, rise, 0.0f), 0.2f, mat);
                }
                else
                    b.sphere(g, center, 0.2f, mat);
            }
            else if (choose < 0.95f)
            {
                const vec3 albedo = rnd3(0.5f, 1.0f);
                const float fuzz = rnd.uniform(0.0f, 0.5f);
                b.sphere(g, center, 0.2f, b.metal(albedo, fuzz));
            }
            else
                b.sphere(g, center, 0.2f, b.dielectric(1.5f));
        }
}

void finalSceneCamera(Scene& scene, float defocusAngle)
{
    scene.camera.lookFrom = {13.0f, 2.0f, 3.0f};
    scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
    scene.camera.vfovDegrees = 20.0f;
    scene.camera.defocusAngleDegrees = defocusAngle;
    scene.camera.focusDistance = 10.0f;
    scene.defaults.aspect = 16.0f / 9.0f;
}

void rtnwCornellWalls(SceneBuilder& b, std::uint32_t g)
{
    const std::uint32_t red = b.lambertian({0.65f, 0.05f, 0.05f});
    const std::uint32_t white = b.lambertian(vec3(0.73f));
    const std::uint32_t green = b.lambertian({0.12f, 0.45f, 0.15f});
    b.quad(g, {555, 0, 0}, {0, 555, 0}, {0, 0, 555}, green);
    b.quad(g, {0, 0, 0}, {0, 555, 0}, {0, 0, 555}, red);
    b.quad(g, {0, 0, 0}, {555, 0, 0}, {0, 0, 555}, white);
    b.quad(g, {555, 555, 555}, {-555, 0, 0}, {0, 0, -555}, white);
    b.quad(g, {0, 0, 555}, {555, 0, 0}, {0, 555, 0}, white);
}

void rtrolCornellWalls(SceneBuilder& b, std::uint32_t g, std::uint32_t floor)
{
    const std::uint32_t red = b.lambertian({0.65f, 0.05f, 0.05f});
    const std::uint32_t white = b.lambertian(vec3(0.73f));
    const std::uint32_t green = b.lambertian({0.12f, 0.45f, 0.15f});
    b.quad(g, {555, 0, 0}, {0, 0, 555}, {0, 555, 0}, green);
    b.quad(g, {0, 0, 555}, {0, 0, -555}, {0, 555, 0}, red);
    b.quad(g, {0, 555, 0}, {555, 0, 0}, {0, 0, 555}, white);
    b.quad(g, {0, 0, 555}, {555, 0, 0}, {0, 0, -555}, floor != kNoIndex ? floor : white);
    b.quad(g, {555, 0, 555}, {-555, 0, 0}, {0, 555, 0}, white);
}

void cornellCamera(Scene& scene)
{
    scene.camera.lookFrom = {278.0f, 278.0f, -800.0f};
    scene.camera.lookAt = {278.0f, 278.0f, 0.0f};
    scene.camera.vfovDegrees = 40.0f;
    scene.camera.defocusAngleDegrees = 0.0f;
    scene.defaults.aspect = 1.0f;
    scene.defaults.width = 600;
    setConstantBackground(scene, vec3(0.0f));
}

std::uint32_t placeMesh(SceneBuilder& b, std::uint32_t mesh, std::uint32_t material, const vec3& base, float height,
                        float rotateYDegrees)
{
    // No division by the mesh's own extent here: in float that re-creates what the loader's double fit avoided.
    const std::uint32_t g = b.group(b.scene().meshes.at(mesh).name);
    b.mesh(g, mesh, material);
    b.instance(g, Transform::translate(base) * Transform::rotateY(rotateYDegrees) * Transform::scale(vec3(height)));
    return g;
}
} // namespace rt::scenes
