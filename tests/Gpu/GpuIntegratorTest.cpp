// The GPU integrator a render runs (RayTracingGPU/Engine/GpuIntegrator.h): names, and auto's rule.
#include <gtest/gtest.h>

#include "Engine/GpuIntegrator.h"

namespace rt::gpu::test
{
namespace
{
using shader::Estimator;

/// A render of 600x600 pixels at 256 spp, the catalogue benchmark's.
constexpr std::uint64_t kBigRender = 600ull * 600 * 256;

shader::RenderUniforms render(Estimator estimator, std::uint32_t lights, std::uint32_t emitters)
{
    shader::RenderUniforms u{};
    u.estimator = estimator;
    u.lightCount = lights;
    u.emitterCount = emitters;
    return u;
}

TEST(IntegratorName, NamesRoundTrip)
{
    for (const GpuIntegrator i : {GpuIntegrator::Auto, GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
        EXPECT_EQ(parseName<GpuIntegrator>(toString(i)), i);
    EXPECT_FALSE(parseName<GpuIntegrator>("wave"));
    EXPECT_FALSE(parseName<GpuIntegrator>(""));
}

TEST(IntegratorChoice, AnExplicitChoiceStands)
{
    const auto u = render(Estimator::NeeMis, 12, 12);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Megakernel, false, u, 1u << 20, kBigRender), GpuIntegrator::Megakernel);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Wavefront, true, render(Estimator::BsdfOnly, 0, 0), 1, 1),
              GpuIntegrator::Wavefront);
}

// The rule, on the catalogue's cases measured on the H100 (docs/notebook/PERFORMANCE.md §8), at 600x600 and 256 spp.
TEST(IntegratorChoice, AutoTakesTheWavefrontWhereAVertexEvaluatesSeveralLightsOrTheSceneIsLarge)
{
    const auto autoFor = [](const shader::RenderUniforms& u, std::uint64_t primitives) {
        return resolveIntegrator(GpuIntegrator::Auto, false, u, primitives, kBigRender);
    };
    EXPECT_EQ(autoFor(render(Estimator::NeeMis, 12, 12), 20), GpuIntegrator::Wavefront); // cornell-box-lights
    EXPECT_EQ(autoFor(render(Estimator::Nee, 2, 2), 20), GpuIntegrator::Wavefront);
    EXPECT_EQ(autoFor(render(Estimator::Mixture, 12, 12), 20), GpuIntegrator::Wavefront);
    EXPECT_EQ(autoFor(render(Estimator::Mixture, 2, 1), 20), GpuIntegrator::Wavefront); // rtrol-cornell-glass
    EXPECT_EQ(autoFor(render(Estimator::NeeMis, 1, 1), 3), GpuIntegrator::Wavefront); // sphere-light-closeup
    EXPECT_EQ(autoFor(render(Estimator::Nee, 2, 1), 3), GpuIntegrator::Wavefront); // one emitter
    EXPECT_EQ(autoFor(render(Estimator::NeeMis, 1, 1), 1), GpuIntegrator::Megakernel); // furnace: the emitter alone
    EXPECT_EQ(autoFor(render(Estimator::Mixture, 1, 1), 17), GpuIntegrator::Megakernel); // rtrol-cornell-box
    EXPECT_EQ(autoFor(render(Estimator::BsdfOnly, 12, 12), 20), GpuIntegrator::Megakernel);
    EXPECT_EQ(autoFor(render(Estimator::Mixture, 0, 0), kWavefrontPrimitives - 1), GpuIntegrator::Megakernel);
    EXPECT_EQ(autoFor(render(Estimator::Mixture, 0, 0), kWavefrontPrimitives), GpuIntegrator::Wavefront);
    EXPECT_EQ(autoFor(render(Estimator::BsdfOnly, 0, 0), 485), GpuIntegrator::Wavefront); // rtow-final
}

// Media: the megakernel pays for their intersection shader as for many primitives (rtnw-cornell-smoke's mixture
// over one light: 1.55x in the wavefront on the H100), from the same number of paths.
TEST(IntegratorChoice, AutoTakesTheWavefrontForMedia)
{
    const shader::RenderUniforms smoke = render(Estimator::Mixture, 1, 1);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Auto, false, smoke, 10, kBigRender, false), GpuIntegrator::Megakernel);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Auto, false, smoke, 10, kBigRender, true), GpuIntegrator::Wavefront);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Auto, false, smoke, 10, kWavefrontMinPaths - 1, true),
              GpuIntegrator::Megakernel);
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Auto, true, smoke, 10, kBigRender, true), GpuIntegrator::Megakernel)
        << "a CPU device";
}

// Small renders (previews, the window's frames) run the megakernel: its launches cost less than the wavefront's
// per segment (docs/notebook/PERFORMANCE.md §8.5); NEE over several emitters gains from the wavefront soonest.
TEST(IntegratorChoice, AutoRunsTheMegakernelForSmallRenders)
{
    const auto autoFor = [](const shader::RenderUniforms& u, std::uint64_t primitives, std::uint64_t paths) {
        return resolveIntegrator(GpuIntegrator::Auto, false, u, primitives, paths);
    };
    const shader::RenderUniforms nee = render(Estimator::NeeMis, 12, 12); // cornell-box-lights
    EXPECT_EQ(autoFor(nee, 20, 600 * 600), GpuIntegrator::Megakernel); // one sample per pixel
    EXPECT_EQ(autoFor(nee, 20, kWavefrontMinPathsNee - 1), GpuIntegrator::Megakernel);
    EXPECT_EQ(autoFor(nee, 20, kWavefrontMinPathsNee), GpuIntegrator::Wavefront);
    EXPECT_EQ(autoFor(nee, 20, 600 * 600 * 4), GpuIntegrator::Wavefront);
    const shader::RenderUniforms mixture = render(Estimator::Mixture, 12, 12);
    EXPECT_EQ(autoFor(mixture, 20, 600 * 600 * 10), GpuIntegrator::Megakernel); // the thesis table's first row
    EXPECT_EQ(autoFor(mixture, 20, kWavefrontMinPaths - 1), GpuIntegrator::Megakernel);
    EXPECT_EQ(autoFor(mixture, 20, kWavefrontMinPaths), GpuIntegrator::Wavefront);
    EXPECT_EQ(autoFor(render(Estimator::BsdfOnly, 0, 0), 485, 600 * 338 * 32), GpuIntegrator::Megakernel); // rtow-final
    EXPECT_EQ(autoFor(render(Estimator::BsdfOnly, 0, 0), 485, 600 * 338 * 256), GpuIntegrator::Wavefront);
}

TEST(IntegratorChoice, AutoRunsTheMegakernelOnACpuDevice)
{
    EXPECT_EQ(resolveIntegrator(GpuIntegrator::Auto, true, render(Estimator::NeeMis, 12, 12), 1u << 20, kBigRender),
              GpuIntegrator::Megakernel);
}
} // namespace
} // namespace rt::gpu::test
