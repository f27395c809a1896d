// The glossy test scenes of shared/spec/scenes.md ("Glossy and occlusion test scenes"): Veach's MIS scene
// (glossy-cornell is cornell-box-lights' variant, in ThesisScenes.cpp).
#include <cmath>

#include "Scenes/SceneFactories.h"

namespace rt::scenes
{
namespace
{
/// Unit vector from a to b.
vec3 towards(const vec3& a, const vec3& b) { return glm::normalize(b - a); }
} // namespace

Scene veachMis(const SceneOptions&)
{
    // After Veach 1997 fig. 9.2: four plates from rough (near) to nearly smooth (far), each turned so that the
    // camera sees the light row mirrored across it, and four lights of equal power (radius^2 x radiance = 1).
    SceneBuilder b("veach-mis");
    const std::uint32_t w = b.world();
    const vec3 camera(0.0f, 2.0f, 15.0f);
    const vec3 lightRow(0.0f, 4.0f, -2.0f);
    const float lightX[4] = {-3.75f, -1.25f, 1.25f, 3.75f};
    const float radius[4] = {0.9f, 0.3f, 0.1f, 0.0333f};
    const float radiance[4] = {1.23457f, 11.1111f, 100.0f, 901.803f};
    for (int i = 0; i < 4; ++i)
        b.sphere(w, {lightX[i], lightRow.y, lightRow.z}, radius[i], b.diffuseLight(vec3(radiance[i])));
    const vec3 centre[4] = {{0.0f, -1.6f, 4.0f}, {0.0f, -1.1f, 2.5f}, {0.0f, -0.6f, 1.0f}, {0.0f, -0.1f, -0.5f}};
    const float alpha[4] = {0.1f, 0.05f, 0.02f, 0.005f};
    const vec3 width(8.0f, 0.0f, 0.0f);
    for (int i = 0; i < 4; ++i)
    {
        const vec3 n = glm::normalize(towards(centre[i], camera) + towards(centre[i], lightRow));
        const vec3 depth = glm::normalize(glm::cross(n, vec3(1.0f, 0.0f, 0.0f))); // width x depth along +n
        b.quad(w, centre[i] - 0.5f * width - 0.5f * depth, width, depth,
               b.conductorSchlick(vec3(0.6f), alpha[i], alpha[i]));
    }
    const std::uint32_t grey = b.lambertian(vec3(0.4f));
    b.quad(w, {-20.0f, -2.2f, 20.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -40.0f}, grey); // floor, facing up
    b.quad(w, {-20.0f, -20.0f, -4.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 40.0f, 0.0f}, grey); // back wall, facing +z
    Scene& s = b.scene();
    s.camera.lookFrom = camera;
    s.camera.lookAt = {0.0f, 1.0f, 0.0f};
    s.camera.vfovDegrees = 34.0f;
    s.camera.defocusAngleDegrees = 0.0f;
    s.defaults = {.spp = 64, .depth = 50, .width = 768, .aspect = 1.5f};
    setConstantBackground(s, vec3(0.0f));
    return b.finish();
}

} // namespace rt::scenes
