// --heatmap on the GPU engine (GpuEngine::costMap, CostTarget.h): each pixel's shader-clock ticks per sample, where
// the work is known to differ (tests/Cpu/CostMapTest.cpp: book 3's glass sphere keeps its paths longer than the
// walls do), and the image the timed ray generation traces, which is the megakernel's.
#include <gtest/gtest.h>

#include <cmath>

#include "Engine/GpuEngine.h"
#include "GpuTestEnvironment.h"
#include "Render/RenderDriver.h"
#include "Scenes/Catalogue.h"
#include "Support/CostRegions.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
using ::rt::test::kGlassCenter;
using ::rt::test::kGlassRadius;
using ::rt::test::kGlassScene;

RenderRequest requestOf(const Scene& scene, int width, int spp)
{
    return {.scene = {.id = kGlassScene}, .settings = ::rt::test::settingsFor(scene, width, spp, 50)};
}

class GpuCostMap : public ::testing::Test
{
protected:
    void SetUp() override { RT_REQUIRE_GPU(); }
    void TearDown() override
    {
        if (sharedEngine())
            sharedEngine()->setCostRecording(false);
    }
};
} // namespace

TEST_F(GpuCostMap, TheGlassSphereCostsMoreThanTheWallsAroundIt)
{
    GpuEngine& engine = *sharedEngine();
    const Scene scene = makeScene(kGlassScene);
    const RenderRequest request = requestOf(scene, 64, 64);
    if (const std::string why = engine.costUnavailable(request.settings); !why.empty())
        GTEST_SKIP() << why;
    engine.setScene(scene);
    RenderControl untimedControl;
    engine.setIntegrator(GpuIntegrator::Megakernel);
    const RenderResult plain = render(engine, request, untimedControl);
    engine.setIntegrator(suiteIntegrator());
    engine.setCostRecording(true);
    RenderControl control;
    const RenderResult timed = render(engine, request, control);
    const CostMap map = engine.costMap();
    ASSERT_EQ(map.width, 64);
    ASSERT_EQ(map.height, 64);
    EXPECT_EQ(map.unit, "shader-clock ticks per sample");
    for (float v : map.perSample)
        ASSERT_TRUE(std::isfinite(v) && v > 0.0f) << "every pixel traced, so every pixel's clock moved";
    // Measured at 1.37x on lavapipe (whose clock moves in steps shared by neighbouring pixels).
    const ::rt::test::CostRegions regions = ::rt::test::costAroundSphere(map, placedScene(kGlassScene), kGlassCenter, kGlassRadius);
    ASSERT_GT(regions.spherePixels, 60u);
    EXPECT_GT(regions.sphere, 1.1 * regions.surroundings);
    // The timed ray generation traces the megakernel's samples: its image is the megakernel's bit for bit.
    EXPECT_EQ(timed.image.pixels(), plain.image.pixels());
    EXPECT_NE(engine.frameConfiguration().find("timed"), std::string::npos);

    engine.setCostRecording(false);
    RenderControl after;
    render(engine, requestOf(scene, 8, 1), after);
    EXPECT_TRUE(engine.costMap().empty()) << "a frame without recording has no cost";
}
} // namespace rt::gpu::test
