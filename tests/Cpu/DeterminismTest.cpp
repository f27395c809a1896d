// Reproducibility: a render depends on (scene, settings, seed) only, never on the thread schedule.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "RenderTestSupport.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"

namespace rt::test
{
namespace
{
TEST(CpuDeterminism, SameSeedTwiceGivesTheSameImage)
{
    const Scene scene = makeScene("rtnw-cornell-smoke"); // media consume random numbers during traversal
    const RenderSettings s = smallSettings(48, 8, 20, Estimator::Mixture);
    EXPECT_TRUE(bitIdentical(renderCpu(scene, s).image, renderCpu(scene, s).image));
}

TEST(CpuDeterminism, AnotherSeedGivesAnotherImage)
{
    const Scene scene = makeScene("rtrol-cornell-box");
    RenderSettings s = smallSettings(32, 4, 10, Estimator::Mixture);
    const Image first = renderCpu(scene, s).image;
    s.seed += 1;
    EXPECT_FALSE(bitIdentical(first, renderCpu(scene, s).image));
}

TEST(CpuDeterminism, SequentialAndParallelAreBitIdentical)
{
    const Scene scene = makeScene("rtnw-final");
    const RenderSettings s = smallSettings(48, 4, 12, Estimator::Mixture);
    EXPECT_TRUE(bitIdentical(renderCpu(scene, s, EngineKind::Single).image, renderCpu(scene, s, EngineKind::Multi).image));
}

TEST(CpuParallel, MultiCoreEngineRunsOnMoreThanOneThread)
{
    // libstdc++ runs std::execution::par on TBB; without TBB linked it silently stays on one thread.
    if (std::thread::hardware_concurrency() < 2)
        GTEST_SKIP() << "this machine has one hardware thread";
    const Scene scene = makeScene("rtrol-cornell-box");
    const RenderResult multi = renderCpu(scene, smallSettings(64, 16, 20, Estimator::Mixture), EngineKind::Multi);
    EXPECT_GT(multi.stats.threadsUsed, 1);
    const RenderResult single = renderCpu(scene, smallSettings(64, 2, 20, Estimator::Mixture), EngineKind::Single);
    EXPECT_EQ(single.stats.threadsUsed, 1);
}

TEST(CpuControl, CancelStopsARenderEarlyAndSaysSo)
{
    const Scene scene = makeScene("rtrol-cornell-glass");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    RenderSettings s = smallSettings(64, 4096, 50, Estimator::Mixture);
    s.sampling = PixelSampling::Accumulate;
    RenderControl control;
    int previews = 0;
    const RenderResult r = renderWithSettings(engine, s, control, [&](const Image&, int spp) {
        ++previews;
        EXPECT_EQ(spp, previews); // one more sample per pixel at each pass
        if (previews == 3)
            control.requestCancel();
    });
    EXPECT_TRUE(r.stats.cancelled);
    EXPECT_EQ(r.stats.trueSpp, 3); // the image holds the finished passes only
    EXPECT_EQ(previews, 3);
}
TEST(CpuControl, CancelInsideABatchKeepsTheFinishedBatchesOnly)
{
    // Batches are sized by time (Render/BatchPlan.h) and the engine polls the cancel before every sample: a
    // cancel lands inside a batch, whose rows (finished or abandoned part way) are put back.
    const Scene scene = makeScene("rtrol-cornell-glass");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    const RenderSettings s = smallSettings(64, 4096, 50, Estimator::Mixture);
    RenderControl control;
    const std::uint64_t quarter = 64ull * 64 * 4096 / 4;
    std::thread canceller([&] { // a quarter of the way, by the engine's per-row progress
        while (control.done() < quarter)
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        control.requestCancel();
    });
    const RenderResult cancelled = renderWithSettings(engine, s, control);
    canceller.join();
    ASSERT_TRUE(cancelled.stats.cancelled);
    EXPECT_GT(cancelled.stats.trueSpp, 0);
    EXPECT_LT(cancelled.stats.trueSpp, 4096);
    EXPECT_GE(control.done(), cancelled.stats.paths) << "progress counts the paths traced, abandoned rows too";
    RenderSettings same = s;
    same.spp = cancelled.stats.trueSpp;
    EXPECT_TRUE(bitIdentical(cancelled.image, renderCpu(scene, same).image))
        << "the image is a complete render of its true spp: no row of the abandoned batch stayed";
}

TEST(CpuControl, ProgressCountsEveryPath)
{
    const Scene scene = makeScene("rtrol-cornell-box");
    cpu::CpuEngine engine(EngineKind::Single);
    engine.setScene(scene);
    RenderControl control;
    const RenderResult r = renderWithSettings(engine, smallSettings(40, 9, 10, Estimator::Mixture), control);
    EXPECT_EQ(control.total(), 40ull * 40 * 9);
    EXPECT_EQ(control.done(), control.total());
    EXPECT_EQ(r.stats.paths, control.total());
}
} // namespace
} // namespace rt::test
