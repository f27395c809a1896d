// Seed blocks on the GPU engine (RenderEngine::setSeedBlock; Support/SeedBlocks.h): each block of a frame the
// render of its seed alone, bit for bit, on the megakernel (whose launches stop at a block's end: the media's hash
// takes the launch's first sample) and on the wavefront (whose waves cross blocks, in waves of 97 paths: a pixel's
// samples split between waves, each summed into its block's image).
#include <gtest/gtest.h>

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
