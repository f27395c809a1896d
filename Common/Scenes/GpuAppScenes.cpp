// The scenes of the thesis' GPU framework (appendix B.2), on our one scene description.
#include "Assets/ObjLoader.h"
#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
namespace
{
/// A unit cube centred at the origin as a 12-triangle mesh, one Lambertian colour per face.
MeshData colouredCube(SceneBuilder& b)
{
    MeshData m;
    m.name = "unit cube";
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f);
    // Faces as corner quadruples, counter-clockwise seen from outside.
    const std::uint32_t faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    const vec3 colours[6] = {{0.8f, 0.1f, 0.1f}, {0.1f, 0.7f, 0.1f}, {0.1f, 0.2f, 0.8f},
                             {0.8f, 0.8f, 0.1f}, {0.7f, 0.1f, 0.7f}, {0.1f, 0.7f, 0.7f}};
    for (int f = 0; f < 6; ++f)
    {
        const std::uint32_t mat = b.lambertian(colours[f]);
        const auto* q = faces[f];
        m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
        m.triangleMaterials.insert(m.triangleMaterials.end(), {mat, mat});
    }
    return m;
}

void threeBigOnes(SceneBuilder& b, const std::uint32_t materials[3], const SceneOptions& options)
{
    const std::uint32_t mesh = b.addMesh(loadObj(options.meshPath));
    const vec3 bases[3] = {{0.0f, 0.0f, 0.0f}, {-4.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}};
    for (int i = 0; i < 3; ++i)
        placeMesh(b, mesh, materials[i], bases[i], 2.0f);
}
} // namespace

Scene cubeAndSpheres(const SceneOptions&)
{
    SceneBuilder b("cube-and-spheres");
    const std::uint32_t cube = b.group("cube");
    b.mesh(cube, b.addMesh(colouredCube(b)), 0);
    b.instance(cube, Transform::identity());
    const std::uint32_t w = b.world();
    b.sphere(w, {1.0f, 0.0f, 0.0f}, 0.5f, b.metal({0.7f, 0.5f, 0.8f}, 0.2f));
    b.sphere(w, {-1.0f, 0.0f, 0.0f}, 0.5f, b.dielectric(1.5f));
    b.sphere(w, {0.0f, 1.0f, 0.0f}, 0.5f, b.lambertianTextured(b.image("textures/earth.jpg")));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 0.0f, 2.0f};
    s.camera.lookAt = vec3(0.0f);
    s.camera.vfovDegrees = 90.0f;
    s.camera.focusDistance = 2.0f;
    s.camera.defocusAngleDegrees = CameraDesc::defocusAngleFromAperture(0.05f, 2.0f);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = true};
    setGradientSky(s);
    return b.finish();
}

Scene planetsInOneWeekend(const SceneOptions&)
{
    SceneBuilder b("planets-in-one-weekend");
    const std::uint32_t w = b.world();
    b.sphere(w, {0.0f, -1000.0f, 0.0f}, 1000.0f, b.lambertian(vec3(0.5f)));
    randomSphereField(b, w, 1u, false);
    b.sphere(w, {0.0f, 1.0f, 0.0f}, 1.0f, b.lambertianTextured(b.image("textures/earth.jpg")));
    b.sphere(w, {-4.0f, 1.0f, 0.0f}, 1.0f, b.lambertianTextured(b.image("textures/sun.jpg")));
    b.sphere(w, {4.0f, 1.0f, 0.0f}, 1.0f, b.lambertianTextured(b.image("textures/night.jpg")));
    Scene& s = b.scene();
    finalSceneCamera(s, 0.6f);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = true};
    setGradientSky(s);
    return b.finish();
}

Scene meshInOneWeekend(const SceneOptions& options)
{
    SceneBuilder b("mesh-in-one-weekend");
    const std::uint32_t w = b.world();
    b.sphere(w, {0.0f, -1000.0f, 0.0f}, 1000.0f, b.lambertian(vec3(0.5f)));
    randomSphereField(b, w, 1u, false);
    const std::uint32_t materials[3] = {b.dielectric(1.5f), b.lambertian({0.4f, 0.2f, 0.1f}),
                                        b.metal({0.7f, 0.6f, 0.5f}, 0.05f)};
    threeBigOnes(b, materials, options);
    Scene& s = b.scene();
    finalSceneCamera(s, 0.0f);
    s.camera.lookAt = {0.0f, 1.0f, 0.0f};
    s.camera.defocusAngleDegrees = CameraDesc::defocusAngleFromAperture(0.05f, 10.0f);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 16.0f / 9.0f, .unidirectionalLight = true};
    setGradientSky(s);
    return b.finish();
}

Scene cornellBoxAndMesh(const SceneOptions& options)
{
    SceneBuilder b("cornell-box-and-mesh");
    const std::uint32_t w = b.world();
    rtnwCornellWalls(b, w);
    b.quad(w, {343, 554, 332}, {-130, 0, 0}, {0, 0, -105}, b.diffuseLight(vec3(15.0f)));
    b.sphere(w, {425.0f, 165.0f, 147.5f}, 80.0f, b.dielectric(1.5f));
    const std::uint32_t mesh = b.addMesh(loadObj(options.meshPath));
    placeMesh(b, mesh, b.lambertian(vec3(0.73f)), {190.0f, 0.0f, 380.0f}, 330.0f, 180.0f);
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
    return b.finish();
}
} // namespace rt::scenes
