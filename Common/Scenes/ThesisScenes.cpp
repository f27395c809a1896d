// The scenes the thesis added to the books' (shared/seed, ch. 4-5 and appendix B.1).
#include "Random/Pcg.h"
#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
Scene whiteSpheres(const SceneOptions& options)
{
    SceneBuilder b("white-spheres");
    const int count = options.count >= 0 ? options.count : 20000;
    const std::uint32_t w = b.world();
    b.quad(w, {400, 554, 100}, {-300, 0, 0}, {0, 0, -100}, b.diffuseLight(vec3(7.0f)));
    const std::uint32_t cluster = b.group("white spheres");
    const std::uint32_t white = b.lambertian(vec3(0.73f));
    SceneRandom rnd(3u);
    for (int i = 0; i < count; ++i)
    {
        const float x = rnd.uniform(0.0f, 500.0f);
        const float y = rnd.uniform(0.0f, 500.0f);
        const float z = rnd.uniform(0.0f, 500.0f);
        b.sphere(cluster, {x, y, z}, 10.0f, white);
    }
    if (count > 0)
        b.instance(cluster, Transform::translate({0, 0, 300}) * Transform::rotateY(15.0f));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
    return b.finish();
}

Scene cornellBoxLights(const SceneOptions&)
{
    SceneBuilder b("cornell-box-lights");
    const std::uint32_t w = b.world();
    rtrolCornellWalls(b, w);
    const std::uint32_t strip = b.diffuseLight(vec3(15.0f));
    for (int y = 100; y <= 500; y += 50)
        b.quad(w, {455.0f, static_cast<float>(y), 554.0f}, {-355, 0, 0}, {0, 10, 0}, strip);
    b.sphere(w, {530, 530, 277}, 50.0f, b.diffuseLight({20.0f, 0.7f, 0.7f}));
    b.sphere(w, {277, 530, 277}, 50.0f, b.diffuseLight({0.7f, 0.7f, 20.0f}));
    b.sphere(w, {30, 530, 277}, 50.0f, b.diffuseLight({0.7f, 20.0f, 0.7f}));
    b.sphere(w, {405, 100, 277.5f}, 100.0f, b.dielectric(1.5f));
    b.sphere(w, {150, 100, 277.5f}, 100.0f, b.lambertian(vec3(0.73f)));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
    return b.finish();
}
} // namespace rt::scenes
