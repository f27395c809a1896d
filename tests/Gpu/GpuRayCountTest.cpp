// --count-rays on the GPU (GpuEngineOptions::countRays, Shaders/Rays.glsl's countRay): the closed form of the
// furnace (every path of a closed sphere traces `depth` segments, NEE a shadow ray at each vertex but the last:
// tests/Cpu/RayCountTest.cpp) on both integrators, the CPU engine's counts (rays, and NEE's light samples by
// outcome) on the benchmark scene, and an image that counting leaves as it was, bit for bit. Without the option
// the engine reports no rays.
#include <gtest/gtest.h>

#include <cstring>
#include <tuple>

#include "GpuTestEnvironment.h"
#include "Render/EngineRegistry.h"
#include "Shared/Estimator.h"
#include "Support/SmallSettings.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::test
{
namespace
{
constexpr int kDepth = 5;

class GpuRayCounts : public ::testing::Test
{
protected:
    void SetUp() override
    {
        RT_REQUIRE_GPU();
        m_messagesBefore = sharedEngine()->validationMessages();
        sharedEngine()->setCountRays(true);
    }
    void TearDown() override
    {
        if (!sharedEngine())
            return;
        sharedEngine()->setCountRays(false);
        sharedEngine()->setIntegrator(suiteIntegrator());
        EXPECT_EQ(sharedEngine()->validationMessages(), m_messagesBefore) << "Vulkan validation messages";
    }

private:
    std::uint64_t m_messagesBefore = 0;
};

/// settingsFor's (the scene's aspect and emitter sidedness) with `estimator` and `roulette`.
RenderSettings settingsOf(const Scene& scene, int width, int spp, int depth, Estimator estimator,
                          RussianRoulette roulette)
{
    RenderSettings s = ::rt::test::settingsFor(scene, width, spp, depth);
    s.estimator = estimator;
    s.russianRoulette = roulette;
    return s;
}

TEST_F(GpuRayCounts, InTheFurnaceEveryPathTracesItsDepthOnBothIntegrators)
{
    const Scene furnace = makeFurnace(0.5f, 0.5f);
    for (const GpuIntegrator integrator : {GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
        for (const Estimator e : {Estimator::BsdfOnly, Estimator::NeeMis})
        {
            sharedEngine()->setIntegrator(integrator);
            const RenderSettings s = settingsOf(furnace, 16, 3, kDepth, e, RussianRoulette::Off);
            const RenderStats st = renderOnGpu(furnace, s).stats;
            const std::string what = std::string(toString(integrator)) + ", " + toString(e);
            ASSERT_TRUE(st.raysCounted) << what;
            EXPECT_EQ(st.rays.camera, st.paths) << what;
            EXPECT_EQ(st.rays.extension, (kDepth - 1) * st.paths) << what;
            EXPECT_EQ(st.rays.shadow, shader::usesNee(e) ? (kDepth - 1) * st.paths : 0u) << what;
            EXPECT_EQ(st.lightSamples.drawn, st.rays.shadow) << what << ": a light sample at each NEE vertex";
            EXPECT_EQ(st.lightSamples.fallback + st.lightSamples.declined, 0u) << what;
        }
}

TEST_F(GpuRayCounts, RestirTracesEachCameraPathTwice)
{
    // As on the CPU (tests/Cpu/RayCountTest.cpp): the candidates pass traces the camera ray to the vertex it
    // resamples at, the shading pass the whole path again; each of the three passes adds its own counts.
    const Scene furnace = makeFurnace(0.5f, 0.5f);
    const RenderSettings s = settingsOf(furnace, 16, 2, kDepth, Estimator::RestirDi, RussianRoulette::Off);
    const RenderStats st = renderOnGpu(furnace, s).stats;
    ASSERT_TRUE(st.raysCounted);
    EXPECT_EQ(st.rays.camera, 2 * st.paths);
    EXPECT_EQ(st.rays.extension, (kDepth - 1) * st.paths);
    EXPECT_GT(st.rays.shadow, (kDepth - 2) * st.paths) << "NEE past the resampled vertex, and the reservoirs' rays";
    // Light samples as on the CPU: each pixel's M candidates, and NEE at the depth - 2 vertices past the resampled one.
    EXPECT_EQ(st.lightSamples.drawn, std::uint64_t(s.restirCandidates + kDepth - 2) * st.paths);
    EXPECT_EQ(st.lightSamples.fallback + st.lightSamples.declined, 0u);
}

TEST_F(GpuRayCounts, AgreeWithTheCpuEngineAndLeaveTheImageAsItWas)
{
    // The engines trace the same paths from the same random numbers; a float rounding differently may send one
    // path another way, so the kinds agree to 1 %, the camera rays exactly.
    const Scene scene = makeScene("cornell-box-lights");
    const RenderSettings s = settingsOf(scene, 24, 2, 50, Estimator::NeeMis, RussianRoulette::Throughput);
    sharedEngine()->setIntegrator(GpuIntegrator::Megakernel);
    const RenderResult counted = renderOnGpu(scene, s);
    sharedEngine()->setCountRays(false);
    const RenderResult plain = renderOnGpu(scene, s);
    EXPECT_FALSE(plain.stats.raysCounted);
    EXPECT_EQ(plain.stats.rays, RayCounts{});
    ASSERT_EQ(counted.image.pixelCount(), plain.image.pixelCount());
    EXPECT_EQ(std::memcmp(counted.image.data(), plain.image.data(), plain.image.pixelCount() * sizeof(vec3)), 0)
        << "counting changed the image";

    const auto cpu = engines::make(EngineKind::Multi);
    cpu->setScene(scene);
    RenderControl control;
    const RenderStats reference = renderWithSettings(*cpu, s, control).stats;
    const RenderStats& gpu = counted.stats;
    ASSERT_TRUE(gpu.raysCounted);
    EXPECT_EQ(gpu.rays.camera, reference.rays.camera);
    EXPECT_EQ(gpu.rays.camera, gpu.paths);
    for (const auto& [name, g, c] : {std::tuple{"extension", gpu.rays.extension, reference.rays.extension},
                                     std::tuple{"shadow", gpu.rays.shadow, reference.rays.shadow}})
    {
        EXPECT_GT(c, gpu.paths / 2) << name << ": too few to compare";
        EXPECT_NEAR(double(g), double(c), 0.01 * double(c)) << name;
    }
    // NEE's light samples likewise: the projected sampler falls back to area sampling where a light is below
    // 1e-2 sr (tests/Cpu/RayCountTest.cpp), on the GPU's float trigonometry as on the CPU's. The fallbacks (a few
    // hundred) to 3 %, a path sent another way moving one vertex or two.
    EXPECT_NEAR(double(gpu.lightSamples.drawn), double(reference.lightSamples.drawn),
                0.01 * double(reference.lightSamples.drawn));
    EXPECT_GT(reference.lightSamples.fallback, reference.lightSamples.drawn / 20) << "too few to compare";
    EXPECT_NEAR(double(gpu.lightSamples.fallback), double(reference.lightSamples.fallback),
                0.03 * double(reference.lightSamples.fallback));
    EXPECT_EQ(gpu.lightSamples.declined, reference.lightSamples.declined);
    EXPECT_EQ(plain.stats.lightSamples, LightSampleCounts{}) << "counted without --count-rays";
}

TEST_F(GpuRayCounts, TheWavefrontCountsTheMegakernelsLightSamples)
{
    // The same paths on both integrators; the wavefront adds its vertices' outcomes once per subgroup.
    const Scene scene = makeScene("cornell-box-lights");
    RenderSettings s = settingsOf(scene, 24, 2, 50, Estimator::NeeMis, RussianRoulette::Throughput);
    s.lightSampler = LightSampler::SolidAngle;
    sharedEngine()->setIntegrator(GpuIntegrator::Megakernel);
    const LightSampleCounts mega = renderOnGpu(scene, s).stats.lightSamples;
    sharedEngine()->setIntegrator(GpuIntegrator::Wavefront);
    const LightSampleCounts wave = renderOnGpu(scene, s).stats.lightSamples;
    EXPECT_GT(mega.fallback, mega.drawn / 20) << "too few to compare";
    EXPECT_NEAR(double(wave.drawn), double(mega.drawn), 0.01 * double(mega.drawn));
    EXPECT_NEAR(double(wave.fallback), double(mega.fallback), 0.03 * double(mega.fallback));
}
} // namespace
} // namespace rt::gpu::test
