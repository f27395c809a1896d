// transformScene (the stress knobs --translate-scene, --scale-scene): what moves with the scene, what scales
// with it, what is refused, and how the flags reach it. Whether the moved scene renders the same image is
// the stress suite's business (tests/Cpu/StressTest.cpp, tests/Gpu/GpuStressTest.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "Cli/CommonOptions.h"
#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Scene/SceneTransform.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
void expectNear(const vec3& a, const vec3& b, float tolerance)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneTransform, MovesCameraInstancesAndLightsTogether)
{
    const Scene original = makeScene("rtrol-cornell-glass"); // quads, rotated instances, a sampling target
    const SceneTransform t{vec3(100.0f, -20.0f, 3.0f), 2.0f};
    Scene moved = original;
    transformScene(moved, t);
    const Transform w = t.worldFromScene();
    expectNear(moved.camera.lookFrom, w.point(original.camera.lookFrom), 1e-3f);
    expectNear(moved.camera.lookAt, w.point(original.camera.lookAt), 1e-3f);
    EXPECT_FLOAT_EQ(moved.camera.focusDistance, 2.0f * original.camera.focusDistance);
    EXPECT_EQ(moved.camera.defocusAngleDegrees, original.camera.defocusAngleDegrees);
    ASSERT_EQ(moved.lights.size(), original.lights.size());
    for (std::size_t i = 0; i < moved.lights.size(); ++i)
    {
        const LightData &a = original.lights[i], &b = moved.lights[i];
        EXPECT_EQ(a.shape, b.shape);
        EXPECT_EQ(a.material, b.material);
        expectNear(b.p0, w.point(a.p0), 1e-3f);
        if (a.shape == shader::LightShape::Sphere)
        {
            EXPECT_FLOAT_EQ(b.radius, 2.0f * a.radius);
        }
        else
        {
            EXPECT_NEAR(b.area, 4.0f * a.area, 1e-3f * a.area);
            expectNear(b.normal, a.normal, 1e-6f);
        }
    }
    const Aabb before = original.bounds(), after = moved.bounds();
    expectNear(after.min, w.point(before.min), 1e-2f);
    expectNear(after.max, w.point(before.max), 1e-2f);
    EXPECT_EQ(moved.background.color0, original.background.color0);
}

TEST(SceneTransform, MediaAndProceduralTexturesKeepTheirLookPerSceneUnit)
{
    const Scene original = makeScene("rtnw-final"); // media, a noise texture
    Scene moved = original;
    transformScene(moved, {vec3(0.0f), 4.0f});
    for (std::size_t g = 0; g < moved.groups.size(); ++g)
        for (std::size_t m = 0; m < moved.groups[g].media.size(); ++m)
            EXPECT_FLOAT_EQ(moved.groups[g].media[m].density, original.groups[g].media[m].density / 4.0f);
    for (std::size_t i = 0; i < moved.textures.size(); ++i)
    {
        if (moved.textures[i].type == TextureType::Noise)
        {
            EXPECT_FLOAT_EQ(moved.textures[i].scale, original.textures[i].scale / 4.0f);
        }
    }
}

TEST(SceneTransform, RefusesBadValuesAndWhatFloat32CannotRender)
{
    const Scene original = makeScene("rtrol-cornell-box");
    const auto refused = [&](const SceneTransform& t) {
        Scene s = original;
        EXPECT_THROW(transformScene(s, t), UsageError) << t.translation.x << " " << t.scale;
    };
    refused({vec3(0.0f), 0.0f});
    refused({vec3(0.0f), -1.0f});
    refused({vec3(0.0f), std::nanf("")});
    refused({vec3(std::numeric_limits<float>::infinity(), 0.0f, 0.0f), 1.0f});
    refused({vec3(1e6f, 0.0f, 0.0f), 1.0f}); // ~1000 times the box's size
    refused({vec3(0.0f), 1e-6f}); // 1e-3 units across
    refused({vec3(1e5f, 0.0f, 0.0f), 1.0f}); // ~100 times
    refused({vec3(0.0f), 1e7f}); // 1e10 units across
    Scene ok = original;
    EXPECT_NO_THROW(transformScene(ok, {vec3(2e4f, 0.0f, 0.0f), 1.0f})); // ~21 times: inside the limit
    Scene ignored = original;
    EXPECT_NO_THROW(transformScene(ignored, {vec3(1e6f, 0.0f, 0.0f), 1.0f}, FloatLimits::Ignore));
}

TEST(SceneTransform, FlagsReachTheSceneRef)
{
    CommonOptions o;
    o.translateScene = "1e4,-2.5,0";
    o.scaleScene = "1e-3";
    const SceneRef ref = o.sceneRef();
    EXPECT_EQ(ref.options.transform.translation, vec3(1e4f, -2.5f, 0.0f));
    EXPECT_EQ(ref.options.transform.scale, 1e-3f);
    EXPECT_TRUE(CommonOptions().sceneRef().options.transform.isIdentity());
    for (const char* bad : {"1,2", "1,2,3,4", "1,,3", "a,b,c", "1,2,3,", " 1,2,3", "nan,0,0", "0,inf,0"})
    {
        CommonOptions b;
        b.translateScene = bad;
        EXPECT_THROW(b.sceneRef(), UsageError) << bad;
    }
    for (const char* bad : {"0", "-1", "inf", "nan", "2x", ""})
    {
        CommonOptions b;
        b.scaleScene = bad;
        if (std::string(bad).empty())
        {
            EXPECT_NO_THROW(b.sceneRef()); // empty: the flag was not given
        }
        else
        {
            EXPECT_THROW(b.sceneRef(), UsageError) << bad;
        }
    }
}

TEST(ValueParsing, RealTriples)
{
    EXPECT_EQ(parseRealTriple("1,2.5,-3e2"), (std::array<float, 3>{1.0f, 2.5f, -300.0f}));
    EXPECT_FALSE(parseRealTriple("1,2"));
    EXPECT_FALSE(parseRealTriple("1,2,3,4"));
    EXPECT_FALSE(parseRealTriple("1;2;3"));
    EXPECT_FALSE(parseRealTriple(""));
}
} // namespace
} // namespace rt
