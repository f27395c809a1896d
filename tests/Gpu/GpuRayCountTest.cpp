// --count-rays on the GPU (GpuEngineOptions::countRays, Shaders/Rays.glsl's countRay): the closed form of the
// furnace (every path of a closed sphere traces `depth` segments, NEE a shadow ray at each vertex but the last:
// tests/Cpu/RayCountTest.cpp) on both integrators, the CPU engine's counts on the benchmark scene, and an image
// that counting leaves as it was, bit for bit. Without the option the engine reports no rays.
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
}
} // namespace
} // namespace rt::gpu::test
