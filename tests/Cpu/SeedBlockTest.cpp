// Seed blocks on the CPU engine (RenderEngine::setSeedBlock; Support/SeedBlocks.h): a frame of several seeds, each
// block the render of its seed alone, bit for bit; and the frames that cannot be cut into blocks refused by name.
#include <gtest/gtest.h>

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
    EXPECT_NE(refusal(stratified).find("random or Sobol"), std::string::npos) << refusal(stratified);
    RenderSettings restir = s;
    restir.estimator = Estimator::RestirDi;
    EXPECT_NE(refusal(restir).find("restir-di"), std::string::npos) << refusal(restir);
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
