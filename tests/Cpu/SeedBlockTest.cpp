// Seed blocks on the CPU engine (RenderEngine::setSeedBlock; Support/SeedBlocks.h): a frame of several seeds, each
// block the render of its seed alone, bit for bit; and the frames that cannot be cut into blocks refused by name.
#include <gtest/gtest.h>

#include <stop_token>
#include <thread>

#include "Engine/CpuEngine.h"
#include "Scenes/Catalogue.h"
#include "Support/SeedBlocks.h"
#include "Support/SmallSettings.h"

namespace rt::test
{
namespace
{
// Random numbers on NEE's paths, Owen-scrambled Sobol (its scramble hashed from the seed), and media, whose
// free-flight distances hash the seed apart from the path's stream (Shared/Medium.h).
TEST(CpuSeedBlocks, EachBlockIsTheRenderOfItsSeedAlone)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    struct Case
    {
        const char* scene;
        Estimator estimator;
        PixelSampling sampling;
    };
    for (const Case& c : {Case{"cornell-box-lights", Estimator::NeeMis, PixelSampling::Random},
                          Case{"rtrol-cornell-box", Estimator::Mixture, PixelSampling::Sobol},
                          Case{"rtnw-cornell-smoke", Estimator::NeeMis, PixelSampling::Sobol}})
    {
        const Scene scene = makeScene(c.scene);
        engine.setScene(scene);
        RenderSettings s = settingsFor(scene, 16, 4, 8);
        s.estimator = c.estimator;
        s.sampling = c.sampling;
        s.seed = 77;
        expectSeedBlocksAreTheirSeedsRenders(engine, s, c.scene);
    }
}

// A batch cancelled part way, which crosses from the first block into the second, puts every block back: the
// estimate after it is that of the batch before, bit for bit, and the batch taken again completes the frame's image.
TEST(CpuSeedBlocks, ACancelledBatchPutsEveryBlockBack)
{
    const Scene scene = makeScene("cornell-box-lights");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    const RenderSettings s = settingsFor(scene, 32, 512, 8); // two blocks of 256
    const std::uint64_t pixels = 32ull * 32ull;
    engine.setSeedBlock(256);
    auto traced = [&](RenderControl& control, std::uint32_t first, std::uint32_t count) {
        return engine.traceSamples(first, count, control).complete;
    };
    engine.beginFrame(s);
    RenderControl clean;
    clean.begin(pixels * 512);
    ASSERT_TRUE(traced(clean, 0, 200));
    const Image first = engine.estimate(200);
    ASSERT_TRUE(traced(clean, 200, 312));
    const Image whole = engine.estimate(512);
    ASSERT_EQ(whole.height(), 2 * 32);

    // The cancel comes from another thread a few rows in; where that thread ran too late (a loaded host) and the
    // batch completed, the frame is taken again.
    bool cancelled = false;
    for (int attempt = 0; attempt < 5 && !cancelled; ++attempt)
    {
        engine.beginFrame(s);
        RenderControl control;
        control.begin(pixels * 512);
        ASSERT_TRUE(traced(control, 0, 200));
        // A few rows into the second batch (32 rows of 312 samples each).
        std::jthread canceller([&](std::stop_token stop) {
            while (!stop.stop_requested() && control.done() < pixels * 200 + 4ull * 32ull * 312ull)
                std::this_thread::yield();
            control.requestCancel();
        });
        cancelled = !traced(control, 200, 312);
    }
    ASSERT_TRUE(cancelled) << "the cancel came after the batch in five attempts";
    EXPECT_EQ(engine.estimate(200).pixels(), first.pixels()) << "the cancelled batch left samples behind";
    RenderControl again;
    again.begin(pixels * 312);
    ASSERT_TRUE(traced(again, 200, 312));
    EXPECT_EQ(engine.estimate(512).pixels(), whole.pixels());
    engine.setSeedBlock(0);
}

TEST(SeedBlocks, FramesThatCannotBeCutIntoBlocksAreRefusedByName)
{
    const Scene scene = makeScene("cornell-box-lights");
    cpu::CpuEngine engine(EngineKind::Single);
    engine.setScene(scene);
    RenderSettings s = settingsFor(scene, 8, 8, 4);
    engine.setSeedBlock(4);
    engine.beginFrame(s); // two blocks of 4
    auto refusal = [&](const RenderSettings& settings) -> std::string {
        try
        {
            engine.beginFrame(settings);
        }
        catch (const UsageError& e)
        {
            return e.what();
        }
        return "accepted";
    };
    RenderSettings odd = s;
    odd.spp = 6;
    EXPECT_NE(refusal(odd).find("spp a multiple of the block"), std::string::npos) << refusal(odd);
    RenderSettings stratified = s;
    stratified.sampling = PixelSampling::Stratified;
    stratified.spp = 16;
    EXPECT_NE(refusal(stratified).find("random, accumulate or Sobol"), std::string::npos) << refusal(stratified);
    RenderSettings restir = s;
    restir.estimator = Estimator::RestirDi;
    EXPECT_NE(refusal(restir).find("restir-di"), std::string::npos) << refusal(restir);
    RenderSettings accumulate = s;
    accumulate.sampling = PixelSampling::Accumulate; // the random numbers, drawn a sample a pass
    EXPECT_EQ(refusal(accumulate), "accepted");
    RenderSettings tall = s; // 8 rows a block
    tall.spp = 8200;
    engine.setSeedBlock(1);
    EXPECT_NE(refusal(tall).find("65536 rows"), std::string::npos) << refusal(tall);
    engine.setSeedBlock(0);
    EXPECT_EQ(refusal(odd), "accepted");
}

TEST(SeedBlocks, ABlockHoldsTheSamplesTracedWithinIt)
{
    EXPECT_EQ(samplesInSeedBlock(5, 4, 0), 4u);
    EXPECT_EQ(samplesInSeedBlock(5, 4, 1), 1u);
    EXPECT_EQ(samplesInSeedBlock(5, 4, 2), 0u);
    EXPECT_EQ(samplesInSeedBlock(8, 4, 1), 4u);
    EXPECT_EQ(samplesInSeedBlock(7, 0, 0), 7u); // no blocks: one
    EXPECT_EQ(samplesInSeedBlock(7, 0, 1), 0u);
}
} // namespace
} // namespace rt::test
