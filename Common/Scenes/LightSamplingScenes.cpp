// The light-sampling test scenes of shared/spec/scenes.md: one light filling much of the hemisphere of the
// floor near it, where the choice of light sampler matters most; triangle lights of every proportion.
#include <utility>

#include "Assets/ObjLoader.h"
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

Scene triangleLights(const SceneOptions& options)
{
    SceneBuilder b("triangle-lights");
    const std::uint32_t w = b.world();
    rtrolCornellWalls(b, w);
    // Two panels of triangles: the book-3 ceiling light Q (213, 554, 227), u (130, 0, 0), v (0, 0, 105) cut
    // along its diagonal (both halves face down, along u x v), and a 300 x 3 sliver on the back wall at
    // y = 400 facing the camera (-z).
    const vec3 q(213.0f, 554.0f, 227.0f);
    const vec3 u(130.0f, 0.0f, 0.0f);
    const vec3 v(0.0f, 0.0f, 105.0f);
    const std::uint32_t ceiling = b.diffuseLight(vec3(15.0f));
    MeshData panels;
    panels.name = "triangle-lights panels";
    panels.positions = {q, q + u, q + u + v, q + v, {428.0f, 400.0f, 554.0f}, {128.0f, 400.0f, 554.0f},
                        {278.0f, 403.0f, 554.0f}};
    panels.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    panels.triangleMaterials = {ceiling, ceiling, b.diffuseLight(vec3(8.0f))};
    b.mesh(w, b.addMesh(std::move(panels)), ceiling);
    // The mesh scenes' mesh, every triangle a light.
    const std::uint32_t mesh = b.addMesh(loadObj(options.meshPath));
    placeMesh(b, mesh, b.diffuseLight(vec3(2.0f)), {278.0f, 0.0f, 278.0f}, 150.0f);
    // cornell-box-lights' white sphere.
    b.sphere(w, {150.0f, 100.0f, 277.5f}, 100.0f, b.lambertian(vec3(kWhite)));
    Scene& s = b.scene();
    cornellCamera(s);
    s.defaults = {.spp = 100, .depth = 50, .width = 600, .aspect = 1.0f, .unidirectionalLight = true};
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
