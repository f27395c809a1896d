// The scenes the thesis added to the books' (shared/seed, ch. 4-5 and appendix B.1).
#include <cmath>
#include <vector>

#include "Math/Onb.h"
#include "Random/Pcg.h"
#include "Sampling/Warps.h"
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

namespace
{
// cornell-box-lights' emitters: nine strips along the back wall and three coloured spheres at the ceiling.
constexpr float kStripRadiance = 15.0f;
const vec3 kStripEdgeU{-355.0f, 0.0f, 0.0f};
const vec3 kStripEdgeV{0.0f, 10.0f, 0.0f};
constexpr float kLampRadius = 50.0f;
const vec3 kLampRadiance[3] = {{20.0f, 0.7f, 0.7f}, {0.7f, 0.7f, 20.0f}, {0.7f, 20.0f, 0.7f}};

/// The walls and the two big spheres that cornell-box-lights and many-lights share.
void cornellLightsRoom(SceneBuilder& b, std::uint32_t w)
{
    rtrolCornellWalls(b, w);
    b.sphere(w, {405, 100, 277.5f}, 100.0f, b.dielectric(1.5f));
    b.sphere(w, {150, 100, 277.5f}, 100.0f, b.lambertian(vec3(0.73f)));
}

/// Total emitted power of cornell-box-lights' twelve one-sided lights, up to the factor pi: sum of area x
/// luminance of radiance (Sampling/LightPower.h measures the same).
double cornellBoxLightsPower()
{
    const double strips = 9.0 * double(glm::length(glm::cross(kStripEdgeU, kStripEdgeV))) * kStripRadiance;
    double lamps = 0.0;
    for (const vec3& radiance : kLampRadiance)
        lamps += 4.0 * kPi * double(kLampRadius) * kLampRadius * luminance(radiance);
    return strips + lamps;
}

/// Fully saturated hue h in [0, 1) (the HSV hexcone at S = V = 1).
vec3 hueColor(float h)
{
    const vec3 k = glm::fract(vec3(h) + vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f));
    return glm::clamp(glm::abs(6.0f * k - 3.0f) - 1.0f, 0.0f, 1.0f);
}
/// cornell-box-lights as `id`; with `glossy`, glossy-cornell's materials (scenes.md): the floor glTF's
/// metallic-roughness material, the white sphere a rough conductor, the glass sphere rough.
Scene cornellBoxLightsScene(const char* id, bool glossy)
{
    SceneBuilder b(id);
    const std::uint32_t w = b.world();
    rtrolCornellWalls(b, w, glossy ? b.gltfPbr(b.solid(vec3(0.73f)), 0.0f, 0.3f, kNoIndex) : kNoIndex);
    const std::uint32_t strip = b.diffuseLight(vec3(kStripRadiance));
    for (int y = 100; y <= 500; y += 50)
        b.quad(w, {455.0f, static_cast<float>(y), 554.0f}, kStripEdgeU, kStripEdgeV, strip);
    b.sphere(w, {530, 530, 277}, kLampRadius, b.diffuseLight(kLampRadiance[0]));
    b.sphere(w, {277, 530, 277}, kLampRadius, b.diffuseLight(kLampRadiance[1]));
    b.sphere(w, {30, 530, 277}, kLampRadius, b.diffuseLight(kLampRadiance[2]));
    b.sphere(w, {405, 100, 277.5f}, 100.0f, glossy ? b.roughDielectric(0.05f, 1.5f) : b.dielectric(1.5f));
    b.sphere(w, {150, 100, 277.5f}, 100.0f,
             glossy ? b.conductorSchlick(vec3(0.9f), 0.1f, 0.1f) : b.lambertian(vec3(0.73f)));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
    return b.finish();
}
} // namespace

Scene cornellBoxLights(const SceneOptions&) { return cornellBoxLightsScene("cornell-box-lights", false); }

Scene glossyCornell(const SceneOptions&) { return cornellBoxLightsScene("glossy-cornell", true); }

Scene manyLights(const SceneOptions& options)
{
    // shared/spec/scenes.md: cornell-box-lights' room with N small lights instead of its twelve, their total
    // power equal to the twelve's, spread over three decades, for light selection. Two-sided: the triangles
    // face every way.
    SceneBuilder b("many-lights");
    const std::uint32_t w = b.world();
    cornellLightsRoom(b, w);
    const int count = options.count >= 0 ? options.count : 1000;
    SceneRandom rnd(1u);
    struct Light
    {
        vec3 center;
        float size; // sphere radius, or the triangle's circumradius
        vec3 color;
        float factor;
        vec3 normal; // triangles: the plane's normal
        float angles[3];
        float twist;
    };
    std::vector<Light> lights;
    double power = 0.0;
    for (int i = 0; i < count; ++i)
    {
        Light l{};
        l.center = {rnd.uniform(20.0f, 535.0f), rnd.uniform(200.0f, 535.0f), rnd.uniform(20.0f, 535.0f)};
        l.color = 0.5f * hueColor(rnd.uniform()) + vec3(0.5f);
        l.factor = std::pow(10.0f, 3.0f * rnd.uniform()); // log-uniform over three decades
        double area;
        if (i % 2 == 0)
        {
            l.size = rnd.uniform(3.0f, 8.0f);
            area = 4.0 * kPi * double(l.size) * l.size;
        }
        else
        {
            // Three points on a circle of radius 5-11 about the centre, 120 degrees apart give or take 17:
            // edges of about 8 to 20.
            l.size = rnd.uniform(5.0f, 11.0f);
            l.normal = sampleUniformSphere({rnd.uniform(), rnd.uniform()});
            l.twist = rnd.uniform(0.0f, 2.0f * kPi);
            l.angles[0] = 0.0f;
            l.angles[1] = 2.0f * kPi / 3.0f + rnd.uniform(-0.3f, 0.3f);
            l.angles[2] = 4.0f * kPi / 3.0f + rnd.uniform(-0.3f, 0.3f);
            const Onb frame(l.normal);
            vec3 v[3];
            for (int k = 0; k < 3; ++k)
                v[k] = l.size * frame.toWorld({std::cos(l.angles[k] + l.twist), std::sin(l.angles[k] + l.twist), 0.0f});
            area = 2.0 * 0.5 * double(glm::length(glm::cross(v[1] - v[0], v[2] - v[0]))); // two-sided
        }
        power += area * luminance(l.factor * l.color);
        lights.push_back(l);
    }
    const float scale = power > 0.0 ? static_cast<float>(cornellBoxLightsPower() / power) : 1.0f;
    const std::uint32_t mesh = b.addMesh([&] {
        MeshData m;
        m.name = "many-lights triangles";
        for (int i = 1; i < count; i += 2)
        {
            const Light& l = lights[std::size_t(i)];
            const Onb frame(l.normal);
            for (int k = 0; k < 3; ++k)
                m.positions.push_back(l.center + l.size * frame.toWorld({std::cos(l.angles[k] + l.twist),
                                                                         std::sin(l.angles[k] + l.twist), 0.0f}));
            const auto first = static_cast<std::uint32_t>(m.positions.size() - 3);
            m.indices.insert(m.indices.end(), {first, first + 1, first + 2});
            m.triangleMaterials.push_back(b.diffuseLight(scale * l.factor * l.color));
        }
        return m;
    }());
    if (count > 1)
        b.mesh(w, mesh, b.lambertian(vec3(0.73f))); // every triangle has its own emitting material
    for (int i = 0; i < count; i += 2)
    {
        const Light& l = lights[std::size_t(i)];
        b.sphere(w, l.center, l.size, b.diffuseLight(scale * l.factor * l.color));
    }
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = false};
    return b.finish();
}

Scene lampRoom(const SceneOptions& options)
{
    // shared/spec/scenes.md: N small lamps, each inside a white shade open on one side, so that most lamps are
    // hidden from most points: visibility, not power, decides which light matters (ReSTIR against the light BVH).
    SceneBuilder b("lamp-room");
    const std::uint32_t w = b.world();
    rtrolCornellWalls(b, w);
    b.sphere(w, {150, 100, 277.5f}, 100.0f, b.lambertian(vec3(0.73f)));
    const int count = options.count >= 0 ? options.count : 4096;
    SceneRandom rnd(2u);
    constexpr float kRadius = 3.0f;
    constexpr float kHalfSide = 8.0f; // the shade: a box of side 16 about the lamp
    struct Lamp
    {
        vec3 center;
        int open; // the open face: 0 -y, 1 +x, 2 -x, 3 +z, 4 -z
        vec3 color;
        float factor;
    };
    std::vector<Lamp> lamps;
    double power = 0.0;
    for (int i = 0; i < count; ++i)
    {
        Lamp l{};
        l.center = {rnd.uniform(30.0f, 525.0f), rnd.uniform(60.0f, 525.0f), rnd.uniform(30.0f, 525.0f)};
        l.open = std::min(4, static_cast<int>(rnd.uniform() * 5.0f));
        l.color = 0.5f * hueColor(rnd.uniform()) + vec3(0.5f);
        l.factor = std::pow(10.0f, 2.0f * rnd.uniform()); // log-uniform over two decades
        power += 4.0 * kPi * double(kRadius) * kRadius * luminance(l.factor * l.color);
        lamps.push_back(l);
    }
    const float scale = power > 0.0 ? static_cast<float>(cornellBoxLightsPower() / power) : 1.0f;
    const std::uint32_t shade = b.lambertian(vec3(0.73f));
    const float h = kHalfSide;
    for (const Lamp& l : lamps)
    {
        b.sphere(w, l.center, kRadius, b.diffuseLight(scale * l.factor * l.color));
        const vec3 c = l.center;
        // The six faces as quads, corner and two edges each; the open one is left out.
        const vec3 faces[6][3] = {
            {c + vec3(-h, -h, -h), {2 * h, 0, 0}, {0, 0, 2 * h}}, // -y
            {c + vec3(h, -h, -h), {0, 2 * h, 0}, {0, 0, 2 * h}},  // +x
            {c + vec3(-h, -h, -h), {0, 2 * h, 0}, {0, 0, 2 * h}}, // -x
            {c + vec3(-h, -h, h), {2 * h, 0, 0}, {0, 2 * h, 0}},  // +z
            {c + vec3(-h, -h, -h), {2 * h, 0, 0}, {0, 2 * h, 0}}, // -z
            {c + vec3(-h, h, -h), {2 * h, 0, 0}, {0, 0, 2 * h}},  // +y: never open
        };
        for (int f = 0; f < 6; ++f)
            if (f != l.open)
                b.quad(w, faces[f][0], faces[f][1], faces[f][2], shade);
    }
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
    return b.finish();
}
} // namespace rt::scenes
