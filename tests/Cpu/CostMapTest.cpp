// --heatmap on the CPU engines (CpuEngine::costMap): each pixel's time per sample, where the work is known to
// differ. In book 3's final Cornell box a path that meets the glass sphere refracts through it and goes on with
// its throughput nearly whole, so Russian roulette keeps it longer than a path off the 0.73-albedo walls.
#include <gtest/gtest.h>

#include <cmath>

#include "Engine/CpuEngine.h"
#include "Error.h"
#include "Render/RenderDriver.h"
#include "Scenes/Catalogue.h"
#include "Support/CostRegions.h"
#include "Support/SmallSettings.h"

namespace rt::test
{
namespace
{

RenderRequest requestOf(const Scene& scene, int width, int spp)
{
    return {.scene = {.id = kGlassScene}, .settings = settingsFor(scene, width, spp, 50)};
}
} // namespace

TEST(CpuCostMap, TheGlassSphereCostsMoreThanTheWallsAroundIt)
{
    const Scene scene = makeScene(kGlassScene);
    for (const EngineKind kind : {EngineKind::Single, EngineKind::Multi})
    {
        cpu::CpuEngine engine(kind);
        engine.setCostRecording(true);
        engine.setScene(scene);
        RenderControl control;
        const RenderResult r = render(engine, requestOf(scene, 64, 64), control);
        const CostMap map = engine.costMap();
        ASSERT_EQ(map.width, 64);
        ASSERT_EQ(map.height, 64);
        EXPECT_EQ(map.unit, "microseconds per sample");
        for (float v : map.perSample)
            ASSERT_TRUE(std::isfinite(v) && v > 0.0f) << "every pixel traced, so every pixel took time";
        // The camera sees the sphere in ~100 of the 4,096 pixels. Measured at 1.5x the walls' cost (one core
        // and two): the bound leaves room for a loaded machine's noise, which the trimmed means mostly drop.
        const CostRegions regions = costAroundSphere(map, placedScene(kGlassScene), kGlassCenter, kGlassRadius);
        ASSERT_GT(regions.spherePixels, 60u);
        ASSERT_GT(regions.surroundingPixels, 2000u);
        EXPECT_GT(regions.sphere, 1.15 * regions.surroundings) << toString(kind);
        // Timing does not touch the image: the same render untimed is the same bit for bit.
        cpu::CpuEngine untimed(kind);
        untimed.setScene(scene);
        RenderControl again;
        const RenderResult plain = render(untimed, requestOf(scene, 64, 64), again);
        EXPECT_EQ(r.image.pixels(), plain.image.pixels()) << toString(kind);
    }
}

TEST(CpuCostMap, NoneUnlessAskedAndNoneForRestir)
{
    const Scene scene = makeScene(kGlassScene);
    cpu::CpuEngine engine(EngineKind::Single);
    engine.setScene(scene);
    RenderControl control;
    render(engine, requestOf(scene, 8, 1), control);
    EXPECT_TRUE(engine.costMap().empty());

    RenderRequest restir = requestOf(scene, 8, 1);
    restir.settings.estimator = Estimator::RestirDi;
    EXPECT_NE(engine.costUnavailable(restir.settings).find("restir-di"), std::string::npos);
    EXPECT_TRUE(engine.costUnavailable(requestOf(scene, 8, 1).settings).empty());
    engine.setCostRecording(true);
    RenderControl again;
    EXPECT_THROW(render(engine, restir, again), UsageError);
}
} // namespace rt::test
