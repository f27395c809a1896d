// Seed blocks on the GPU engine (RenderEngine::setSeedBlock; Support/SeedBlocks.h): each block of a frame the
// render of its seed alone, bit for bit, on the megakernel (whose launches stop at a block's end: the media's hash
// takes the launch's first sample) and on the wavefront (whose waves cross blocks, in waves of 97 paths: a pixel's
// samples split between waves, each summed into its block's image).
#include <gtest/gtest.h>

#include <stop_token>
#include <thread>

#include "GpuTestEnvironment.h"
#include "Scenes/Catalogue.h"
#include "Support/SeedBlocks.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
TEST(GpuSeedBlocks, EachBlockIsTheRenderOfItsSeedAloneOnBothIntegrators)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    struct Case
    {
        const char* scene;
        Estimator estimator;
        PixelSampling sampling;
    };
    for (const GpuIntegrator integrator : {GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
    {
        engine.setIntegrator(integrator, integrator == GpuIntegrator::Wavefront ? 97u : 0u);
        for (const Case& c : {Case{"cornell-box-lights", Estimator::NeeMis, PixelSampling::Random},
                              Case{"rtnw-cornell-smoke", Estimator::NeeMis, PixelSampling::Sobol},
                              Case{"rtnw-motion-blur", Estimator::Mixture, PixelSampling::Random}})
        {
            const Scene scene = makeScene(c.scene);
            engine.setScene(scene);
            RenderSettings s = ::rt::test::settingsFor(scene, 12, 3, 6);
            s.estimator = c.estimator;
            s.sampling = c.sampling;
            s.seed = 5;
            ::rt::test::expectSeedBlocksAreTheirSeedsRenders(engine, s, std::string(c.scene) + " on the " +
                                                                            toString(integrator));
        }
    }
    engine.setIntegrator(suiteIntegrator());
}
// A batch cancelled between its bands, crossing from the first block into the second, is put back whole: the
// snapshot and the restore cover every block's image (a block left with the cancelled samples would show them, as
// would a compensation image not put back once the batch is taken again).
TEST(GpuSeedBlocks, ACancelledBatchPutsEveryBlockBack)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    // The shared engine's settings back as the suite had them, whatever ends the test.
    struct Restore
    {
        GpuEngine& engine;
        ~Restore()
        {
            engine.setBandRows(0);
            engine.setSeedBlock(0);
            engine.setIntegrator(suiteIntegrator());
        }
    } restore{engine};
    engine.setIntegrator(GpuIntegrator::Megakernel);
    const Scene scene = makeScene("cornell-box-lights");
    engine.setScene(scene);
    RenderSettings s = ::rt::test::settingsFor(scene, 16, 1000, 6); // two blocks of 500
    s.aspect = 1.0f;
    const std::uint64_t pixels = 16ull * 16ull;
    engine.setSeedBlock(500);
    engine.beginFrame(s);
    RenderControl control;
    control.begin(pixels * 1000);
    ASSERT_TRUE(engine.traceSamples(0, 1, control).complete);
    const Image first = engine.estimate(1);
    ASSERT_TRUE(engine.traceSamples(1, 999, control).complete);
    const Image whole = engine.estimate(1000);

    engine.setBandRows(2); // eight bands a batch, the cancel polled between them
    // The cancel comes from another thread a few bands in; where that thread ran too late (a loaded host) and the
    // batch completed, the frame is taken again.
    bool cancelled = false;
    for (int attempt = 0; attempt < 5 && !cancelled; ++attempt)
    {
        engine.beginFrame(s);
        RenderControl batch;
        batch.begin(pixels * 1000);
        ASSERT_TRUE(engine.traceSamples(0, 1, batch).complete);
        std::jthread canceller([&](std::stop_token stop) { // two bands into the second batch
            while (!stop.stop_requested() && batch.done() < pixels + 2ull * 16ull * 2ull * 999ull)
                std::this_thread::yield();
            batch.requestCancel();
        });
        cancelled = !engine.traceSamples(1, 999, batch).complete;
    }
    ASSERT_TRUE(cancelled) << "the cancel came after the batch in five attempts";
    EXPECT_EQ(engine.estimate(1).pixels(), first.pixels()) << "a block kept the cancelled batch's samples";
    RenderControl again;
    again.begin(pixels * 999);
    ASSERT_TRUE(engine.traceSamples(1, 999, again).complete);
    EXPECT_EQ(engine.estimate(1000).pixels(), whole.pixels());
}

// The refusals are the engines' shared rule (RenderEngine::seedBlocksOf); the GPU takes it before it allocates.
TEST(GpuSeedBlocks, AStratifiedFrameIsRefusedByName)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    const Scene scene = makeScene("cornell-box-lights");
    engine.setScene(scene);
    RenderSettings s = ::rt::test::settingsFor(scene, 8, 16, 4);
    s.sampling = PixelSampling::Stratified;
    engine.setSeedBlock(8);
    std::string message;
    try
    {
        engine.beginFrame(s);
    }
    catch (const UsageError& e)
    {
        message = e.what();
    }
    engine.setSeedBlock(0);
    EXPECT_NE(message.find("random, accumulate or Sobol"), std::string::npos) << message;
}
} // namespace
} // namespace rt::gpu::test
