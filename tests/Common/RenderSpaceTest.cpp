// Render space (Scene/RenderSpace.h, issue 41): the camera at the origin of the coordinates both engines trace
// in, the scene's placement in the world kept in Scene::origin (double). What moves, what stays, and that a scene
// placed 1e6 units away has the very same render-space data as at the world's origin. The images are the stress
// suites' business (tests/Cpu/StressTest.cpp, tests/Gpu/GpuStressTest.cpp).
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "Error.h"
#include "Scene/RenderSpace.h"
#include "Scene/SceneBuilder.h"
#include "Scene/SceneTransform.h"
#include "SceneFile/JsonSceneWriter.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/Catalogue.h"
#include "Support/ScratchDir.h"

namespace rt::test
{
namespace
{
template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameCamera(const CameraDesc& a, const CameraDesc& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Everything the engines read, compared bit for bit.
void expectSameRenderData(const Scene& a, const Scene& b, const std::string& what)
{
    EXPECT_TRUE(sameCamera(a.camera, b.camera)) << what;
    EXPECT_TRUE(sameBytes(a.instances, b.instances)) << what;
    EXPECT_TRUE(sameBytes(a.lights, b.lights)) << what;
    EXPECT_TRUE(sameBytes(a.textures, b.textures)) << what;
    ASSERT_EQ(a.groups.size(), b.groups.size()) << what;
    for (std::size_t g = 0; g < a.groups.size(); ++g)
        EXPECT_TRUE(sameBytes(a.groups[g].quads, b.groups[g].quads) && sameBytes(a.groups[g].spheres, b.groups[g].spheres))
            << what << ": group " << g;
}

bool isSolidPattern(TextureType t)
{
    return t == TextureType::Checker || t == TextureType::Noise || t == TextureType::Turbulence ||
           t == TextureType::Marble;
}

TEST(RenderSpace, PutsTheCameraAtTheOriginAndTheWorldInScenesOrigin)
{
    const Scene placed = placedScene("rtrol-cornell-glass"); // quads, rotated instances, a sampling target
    const Scene rendered = makeScene("rtrol-cornell-glass");
    const vec3 eye = placed.camera.lookFrom;
    ASSERT_NE(eye, vec3(0.0f));
    EXPECT_EQ(rendered.camera.lookFrom, vec3(0.0f));
    EXPECT_EQ(rendered.camera.lookAt, placed.camera.lookAt - eye);
    EXPECT_EQ(rendered.origin, dvec3(eye));
    EXPECT_EQ(placed.origin, dvec3(0.0));
    ASSERT_EQ(rendered.lights.size(), placed.lights.size());
    for (std::size_t i = 0; i < rendered.lights.size(); ++i)
    {
        const vec3 back = rendered.lights[i].p0 + eye;
        EXPECT_NEAR(glm::length(back - placed.lights[i].p0), 0.0f, 1e-3f) << "light " << i;
        EXPECT_EQ(rendered.lights[i].normal, placed.lights[i].normal) << "light " << i;
    }
    const Aabb a = placed.bounds(), b = rendered.bounds();
    EXPECT_NEAR(glm::length(b.min + eye - a.min), 0.0f, 1e-3f);
    EXPECT_NEAR(glm::length(b.max + eye - a.max), 0.0f, 1e-3f);
}

TEST(RenderSpace, ASceneTranslatedFarAwayHasTheSameRenderDataBitForBit)
{
    for (const std::string id : {"rtrol-cornell-box", "cornell-box-lights", "rtnw-final"})
    {
        const Scene home = makeScene(id);
        for (const vec3 t : {vec3(1e6f, -1e6f, 1e6f), vec3(-3e9f, 7.5f, 1e12f)})
        {
            SceneOptions options;
            options.transform.translation = t;
            const Scene far = makeScene(id, options);
            expectSameRenderData(home, far, id);
            EXPECT_EQ(far.origin - home.origin, dvec3(t)) << id << ": the placement, exactly, in double";
        }
    }
}

TEST(RenderSpace, ScaleThenTranslationPlaceTheOriginInDouble)
{
    SceneOptions options;
    options.transform = {vec3(1e6f, 2.0f, -3.0f), 4.0f};
    const Scene placed = placedScene("rtrol-cornell-box", options);
    EXPECT_EQ(placed.origin, dvec3(1e6, 2.0, -3.0)); // 4 * 0 + the translation
    const Scene rendered = makeScene("rtrol-cornell-box", options);
    EXPECT_EQ(rendered.origin, placed.origin + dvec3(placed.camera.lookFrom));
    // The scale is in the coordinates: the camera 4 times as far from the box's corner as unscaled.
    const Scene unscaled = placedScene("rtrol-cornell-box");
    EXPECT_FLOAT_EQ(glm::length(placed.camera.lookFrom), 4.0f * glm::length(unscaled.camera.lookFrom));
}

TEST(RenderSpace, SolidTexturesKeepTheirPatternOnTheScenesCoordinates)
{
    for (const std::string id : {"rtnw-final", "rtnw-checker-spheres"})
    {
        const Scene placed = placedScene(id);
        const Scene rendered = makeScene(id);
        ASSERT_EQ(placed.textures.size(), rendered.textures.size());
        bool sawPattern = false;
        for (std::size_t i = 0; i < placed.textures.size(); ++i)
        {
            const TextureType type = placed.textures[i].type;
            sawPattern = sawPattern || isSolidPattern(type);
            // The pattern point p_render + origin is p_scene = p_render + look-from.
            EXPECT_EQ(rendered.textures[i].origin, isSolidPattern(type) ? placed.camera.lookFrom : vec3(0.0f))
                << id << " texture " << i;
        }
        EXPECT_TRUE(sawPattern) << id << " has no checker or Perlin texture to test";
    }
}

TEST(RenderSpace, ASceneFarFromItsCameraIsStillRefused)
{
    SceneBuilder b("far-from-camera");
    b.sphere(b.world(), vec3(1e6f, 0.0f, 0.0f), 1.0f, b.lambertian(vec3(0.5f)));
    Scene& s = b.scene();
    s.camera.lookFrom = vec3(0.0f, 0.0f, 5.0f);
    s.camera.lookAt = vec3(1e6f, 0.0f, 0.0f);
    Scene scene = b.finish();
    toRenderSpace(scene);
    try
    {
        checkFloatReach(scene, "far-from-camera");
        ADD_FAILURE() << "a sphere of radius 1, 1e6 units from its camera, was accepted";
    }
    catch (const SceneError& e)
    {
        EXPECT_NE(std::string(e.what()).find("from the origin of its coordinates (the camera, as rendered)"),
                  std::string::npos)
            << e.what();
    }
}

/// A scene file with its content at the world's origin, or placed 1e6 units away by "origin": the same render data.
TEST(RenderSpace, ASceneFilesOriginPlacesItInDoubleAndItsTexturesOffsetTheirPattern)
{
    const ScratchDir dir;
    const auto scene = [](const std::string& extra) {
        return R"({)" + extra + R"("camera": {"look_from": [0, 1, 5], "look_at": [0, 1, 0], "vfov": 40},
            "textures": [{"name": "c", "type": "checker", "scale": 0.5, "even": [1, 1, 1], "odd": [0, 0, 0],
                          "offset": [0.25, 0, 0]}],
            "materials": [{"name": "lamp", "type": "diffuse_light", "radiance": [4, 4, 4]},
                          {"name": "floor", "type": "lambertian", "albedo_texture": "c"}],
            "shapes": [{"type": "sphere", "center": [0, 2, 0], "radius": 0.5, "material": "lamp"},
                       {"type": "quad", "q": [-2, 0, 2], "u": [4, 0, 0], "v": [0, 0, -4], "material": "floor"}]})";
    };
    const Scene home = makeScene(dir.write("home.json", scene("")).string());
    const Scene far = makeScene(dir.write("far.json", scene(R"("origin": [1000000.3, -2e7, 5e11],)")).string());
    expectSameRenderData(home, far, "origin");
    EXPECT_EQ(far.origin - home.origin, dvec3(1000000.3, -2e7, 5e11));
    EXPECT_EQ(home.textures[0].origin, vec3(0.25f, 1.0f, 5.0f)); // the offset plus the look-from

    std::string e;
    try
    {
        makeScene(dir.write("bad.json", scene(R"("origin": [1, "two", 3],)")).string());
    }
    catch (const SceneError& error)
    {
        e = error.what();
    }
    EXPECT_NE(e.find("bad.json: /origin/1: expected a number"), std::string::npos) << e;
}

/// --export-scene of a scene placed far away writes its coordinates as they are and the placement as "origin":
/// read back, the same render data bit for bit.
TEST(RenderSpace, AnExportedFarSceneReadsBackWithTheSameRenderData)
{
    const ScratchDir dir;
    SceneOptions options;
    options.transform.translation = vec3(1e6f, -1e6f, 1e6f);
    for (const std::string id : {"rtrol-cornell-box", "rtnw-final"})
    {
        const auto file = dir / (id + ".json");
        exportScene(placedScene(id, options), file);
        const Scene copy = makeScene(file.string());
        const Scene original = makeScene(id, options);
        expectSameRenderData(original, copy, id);
        EXPECT_EQ(copy.origin, original.origin) << id;
    }
}
} // namespace
} // namespace rt::test
