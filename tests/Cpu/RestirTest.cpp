// restir-di on the CPU engine (Integrator/RestirPasses.h, Shared/Shading/Restir.h): unbiased against nee-mis on
// the scenes it is for, its biased combination caught by the same test, deterministic, and its memory stated.
// The GPU's side: tests/Gpu/GpuRestirTest.cpp.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Engine/CpuEngine.h"
#include "Engine/CpuScene.h"
#include "Integrator/CpuShading.h"
#include "Render/RenderUniforms.h"
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

/// A restir-di setting that changes which points a pixel reuses, not what it estimates: cornell-box-lights with `s`
/// (the setting changed) passes the unbiasedness test against `ref` (32 renders' mean over the image, |Z| < 4), and at
/// 4 spp renders another image than with `withDefault` (the same settings, the default's value back). `what` names
/// the setting in the messages.
void expectAnotherImageNotAnotherExpectation(cpu::CpuEngine& engine, const Scene& scene, const OverSeeds& ref,
                                             const RenderSettings& s, RenderSettings withDefault,
                                             const std::string& what)
{
    const OverSeeds restir = renderSeeds(engine, s, 32, 100);
    const double z = zScore(restir.imageMean, restir.imageVariance, ref.imageMean, ref.imageVariance);
    EXPECT_LT(std::abs(z), 4.0) << what << ": restir-di " << restir.imageMean << ", nee-mis " << ref.imageMean;
    RenderSettings one = s;
    one.spp = 4;
    withDefault.spp = 4;
    EXPECT_FALSE(bitIdentical(renderCpu(scene, one).image, renderCpu(scene, withDefault).image)) << what;
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
        RenderSettings longHistory = s;
        longHistory.restirTemporalCap = 20;
        expectAnotherImageNotAnotherExpectation(engine, scene, ref, s, longHistory, "cap " + std::to_string(cap));
    }
}

// --restir-radius: the neighbours are drawn uniformly in the disk of that many pixels (restirNeighbour): every
// offset within the radius (after rounding to a pixel), their mean squared distance r^2 / 2 (a uniform disk's),
// within 4 standard errors and 0.5 px^2 (rounding to a pixel adds about 1/6 and leaving out the pixel itself about
// 1 / (2 pi), 0.33 in all; uniform in the radius instead of the area would give r^2 / 3); a draw off the image is
// refused.
TEST(CpuRestirRadius, NeighboursAreDrawnUniformlyInTheDiskOfTheRadius)
{
    const Scene scene = makeScene("cornell-box-lights");
    const cpu::CpuScene cs(scene);
    for (const int radius : {4, 30})
    {
        RenderSettings settings = restirSettings(scene);
        settings.restirRadius = radius;
        const shader::RenderUniforms uniforms = makeUniforms(scene, scene.camera, settings, 256, 256);
        ASSERT_EQ(uniforms.restirRadius, std::uint32_t(radius));
        shader::CpuShading<cpu::PathCode{}> shading(cs, uniforms);
        shader::Rng rng = shader::rngForSample(7u, 0u, 0u);
        const uvec2 centre(128u, 128u);
        double sum = 0.0, sum2 = 0.0;
        int kept = 0;
        constexpr int kDraws = 100000;
        for (int k = 0; k < kDraws; ++k)
        {
            uvec2 n;
            if (!shading.restirNeighbour(centre, shader::nextFloat2(rng), 256u, 256u, n))
                continue;
            const double dx = double(n.x) - 128.0, dy = double(n.y) - 128.0;
            const double d2 = dx * dx + dy * dy;
            ASSERT_LE(std::sqrt(d2), radius + std::sqrt(0.5)) << "radius " << radius;
            sum += d2;
            sum2 += d2 * d2;
            ++kept;
        }
        ASSERT_GT(kept, kDraws * 9 / 10);
        const double mean = sum / kept;
        const double standardError = std::sqrt((sum2 / kept - mean * mean) / kept);
        EXPECT_NEAR(mean, radius * radius / 2.0, 4.0 * standardError + 0.5)
            << "radius " << radius;
        uvec2 n;
        EXPECT_FALSE(shading.restirNeighbour(uvec2(0u, 0u), vec2(0.99f, 0.5f), 256u, 256u, n))
            << "a draw at -x, off the image";
    }
}

// The radius changes which neighbours a pixel reuses, not what it estimates: 4 px passes the unbiasedness test and
// renders another image than the default 30.
TEST(CpuRestirRadius, TheRadiusChangesTheImageNotItsExpectation)
{
    const Scene scene = makeScene("cornell-box-lights");
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    const OverSeeds ref = neeMisReference(engine, scene);
    RenderSettings s = restirSettings(scene);
    s.restirRadius = 4;
    RenderSettings wide = s;
    wide.restirRadius = 30;
    expectAnotherImageNotAnotherExpectation(engine, scene, ref, s, wide, "radius 4 px");
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
