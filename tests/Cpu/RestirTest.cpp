// restir-di on the CPU engine (Integrator/RestirPasses.h, Shared/Shading/Restir.h): unbiased against nee-mis on
// the scenes it is for, its biased combination caught by the same test, deterministic, and its memory stated.
// The GPU's side: tests/Gpu/GpuRestirTest.cpp.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Engine/CpuEngine.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"
#include "Support/RestirChecks.h"
#include "RenderTestSupport.h"

namespace rt::test
{
namespace
{
/// Support/RestirChecks.h's unbiasedness test on the CPU engine.
void expectUnbiased(const std::string& id)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    expectRestirUnbiased(engine, id);
}

class CpuRestir : public ::testing::TestWithParam<std::string>
{
};

// The test (Support/RestirChecks.h): the mean of 32 independent restir-di renders at low spp agrees
// with a nee-mis reference, block by block and over the image (|Z| < 4 with 31 degrees of freedom: the 10 tests would fail by chance
// about once in 250 runs).
TEST_P(CpuRestir, UnbiasedAgainstNeeMis)
{
    expectUnbiased(GetParam());
}

std::string sceneName(const ::testing::TestParamInfo<std::string>& param)
{
    std::string name = param.param;
    std::erase(name, '-');
    return name;
}

INSTANTIATE_TEST_SUITE_P(LightScenes, CpuRestir, ::testing::Values("cornell-box-lights"), sceneName);

// The same test on the many-light scenes: 22 and 32 s on the CI kind, so in the heavy suite (label heavy).
class HeavyCpuRestir : public CpuRestir
{
};

TEST_P(HeavyCpuRestir, UnbiasedAgainstNeeMis)
{
    expectUnbiased(GetParam());
}

INSTANTIATE_TEST_SUITE_P(HeavyLightScenes, HeavyCpuRestir, ::testing::Values("many-lights", "lamp-room"), sceneName);

// The same test catches the biased combination (Alg. 4: 1 / the inputs' summed M, whatever their domains), which
// darkens where neighbours see lights this pixel does not: were the unbiased path's Z ever computed as the
// biased one's, UnbiasedAgainstNeeMis would fail as this does.
TEST(CpuRestirBiased, TheSameTestFindsTheBiasedCombinationDarker)
{
    const Scene scene = makeScene("cornell-box-lights");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    const OverSeeds ref = neeMisReference(engine, scene);
    RenderSettings s = restirSettings(scene);
    s.restirBiased = true;
    const OverSeeds biased = renderSeeds(engine, s, 32, 100);
    EXPECT_LT(zScore(biased.imageMean, biased.imageVariance, ref.imageMean, ref.imageVariance), -4.0)
        << "biased " << biased.imageMean << ", nee-mis " << ref.imageMean;
}

// --restir-temporal-cap changes how long a pixel keeps its point, not what it estimates: cap 1 and no temporal
// reuse (0) pass the same test, and render other images than the default 20.
TEST(CpuRestirHistory, TheTemporalCapChangesTheImageNotItsExpectation)
{
    const Scene scene = makeScene("cornell-box-lights");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    const OverSeeds ref = neeMisReference(engine, scene);
    for (int cap : {0, 1})
    {
        RenderSettings s = restirSettings(scene);
        s.restirTemporalCap = cap;
        const OverSeeds restir = renderSeeds(engine, s, 32, 100);
        const double z = zScore(restir.imageMean, restir.imageVariance, ref.imageMean, ref.imageVariance);
        EXPECT_LT(std::abs(z), 4.0) << "cap " << cap << ": restir-di " << restir.imageMean << ", nee-mis " << ref.imageMean;
        RenderSettings one = s;
        one.spp = 4;
        RenderSettings longHistory = one;
        longHistory.restirTemporalCap = 20;
        EXPECT_FALSE(bitIdentical(renderCpu(scene, one).image, renderCpu(scene, longHistory).image)) << "cap " << cap;
    }
}

TEST(CpuRestirDeterminism, SingleAndMultiCoreRenderTheSameImageAndTheSeedDecides)
{
    const Scene scene = makeScene("cornell-box-lights");
    const RenderSettings s = restirSettings(scene);
    const RenderResult multi = renderCpu(scene, s, EngineKind::Multi);
    EXPECT_TRUE(bitIdentical(multi.image, renderCpu(scene, s, EngineKind::Single).image));
    EXPECT_TRUE(bitIdentical(multi.image, renderCpu(scene, s, EngineKind::Multi).image));
    RenderSettings other = s;
    other.seed += 1;
    EXPECT_FALSE(bitIdentical(multi.image, renderCpu(scene, other, EngineKind::Multi).image));
}

TEST(CpuRestirStats, ReservoirsTakeAtMost64BytesPerPixelAndTheCombinationIsNamed)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    expectRestirStats(engine);
}
} // namespace
} // namespace rt::test
