// Every scene of the catalogue renders on the GPU engine: finite radiance everywhere, light where light is
// expected, and no Vulkan validation message. Tiny images (lavapipe is slow), every material, texture and
// primitive kind of the catalogue on the way.
#include <gtest/gtest.h>

#include "GpuTestEnvironment.h"
#include "Scenes/Catalogue.h"
#include "Support/CatalogueCases.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
class GpuCatalogue : public ::testing::TestWithParam<std::string>
{
};

TEST_P(GpuCatalogue, RendersFiniteWithoutValidationMessages)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    ASSERT_TRUE(engine.validationEnabled());
    const std::uint64_t messagesBefore = engine.validationMessages();

    const Scene scene = makeScene(GetParam());
    const RenderResult r = renderOnGpu(scene, ::rt::test::settingsFor(scene, 32, 4, 8));

    EXPECT_EQ(r.stats.nanSamples, 0u);
    EXPECT_EQ(r.stats.infSamples, 0u);
    EXPECT_EQ(r.stats.trueSpp, 4);
    EXPECT_GT(r.image.mean().x + r.image.mean().y + r.image.mean().z, 0.0f) << "an all-black image";
    for (const vec3& p : r.image.pixels())
        ASSERT_TRUE(isFinite(p) && p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f);
    EXPECT_EQ(engine.validationMessages(), messagesBefore) << "Vulkan validation messages";
}

INSTANTIATE_TEST_SUITE_P(EveryScene, GpuCatalogue, ::testing::ValuesIn(::rt::test::catalogueIds()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             return ::rt::test::testNameOf(param.param);
                         });
} // namespace
} // namespace rt::gpu::test
