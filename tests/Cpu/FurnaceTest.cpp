// The white furnace (research notes §4.5): inside a closed sphere of albedo a that emits Le everywhere,
// radiance is Le / (1 - a) in every direction, whatever the geometry. A wrong pdf, a missing cosine or a
// missing mixture weight moves the mean (the thesis' GPU app gained 4/3 per diffuse bounce).
#include <gtest/gtest.h>

#include <cmath>

#include "RenderTestSupport.h"
#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"

namespace rt::test
{
namespace
{
struct FurnaceCase
{
    float albedo;
    float emission;
    Estimator estimator;
    PixelSampling sampling;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase>
{
};

TEST_P(Furnace, EveryPixelConvergesToLeOverOneMinusAlbedo)
{
    const FurnaceCase c = GetParam();
    const Scene scene = makeFurnace(c.albedo, c.emission);
    // Depth so large that the truncated tail a^depth is far below the tolerance.
    const int depth = static_cast<int>(std::ceil(std::log(1e-7) / std::log(c.albedo)));
    RenderSettings s = smallSettings(48, 64, depth, c.estimator);
    s.sampling = c.sampling;
    s.unidirectionalLight = scene.defaults.unidirectionalLight; // the camera sees the inside: two-sided
    const RenderResult r = renderCpu(scene, s);
    ASSERT_EQ(r.stats.nanSamples + r.stats.infSamples, 0u);

    const double expected = c.emission / (1.0 - c.albedo);
    const MeanAndError stats = pixelStatistics(r.image);
    // Both estimators can have zero variance here: cosine sampling weights every bounce by exactly the
    // albedo, and light sampling of the enclosing sphere from a point on it has the cosine density too. The
    // float sums still round, so every tolerance gets 1e-5 of the value on top of the statistical one.
    const double rounding = 1e-5 * expected;
    // The mean of all pixels: within 3 standard errors of the closed form.
    EXPECT_NEAR(stats.mean, expected, 3.0 * stats.standardError + rounding)
        << "mean " << stats.mean << ", standard error " << stats.standardError;
    // Every pixel: within 3 of its own standard errors (the pixel spread), which a correct estimator
    // misses for 0.27% of pixels; allow 1% before calling it wrong.
    int outside = 0;
    for (const vec3& p : r.image.pixels())
        if (std::fabs((double(p.x) + p.y + p.z) / 3.0 - expected) > 3.0 * stats.pixelStdDev + rounding)
            ++outside;
    EXPECT_LT(outside, static_cast<int>(0.01 * r.image.pixelCount())) << outside << " pixels beyond 3 sigma";
}

INSTANTIATE_TEST_SUITE_P(
    Estimators, Furnace,
    ::testing::Values(FurnaceCase{0.5f, 0.5f, Estimator::BsdfOnly, PixelSampling::Random},
                      FurnaceCase{0.5f, 0.5f, Estimator::Mixture, PixelSampling::Random},
                      FurnaceCase{0.8f, 0.1f, Estimator::BsdfOnly, PixelSampling::Random},
                      FurnaceCase{0.8f, 0.1f, Estimator::Mixture, PixelSampling::Stratified},
                      FurnaceCase{0.3f, 1.4f, Estimator::Mixture, PixelSampling::Accumulate},
                      FurnaceCase{0.5f, 0.5f, Estimator::Nee, PixelSampling::Random},
                      FurnaceCase{0.8f, 0.1f, Estimator::NeeMis, PixelSampling::Random},
                      FurnaceCase{0.3f, 1.4f, Estimator::NeeMis, PixelSampling::Stratified}));
} // namespace
} // namespace rt::test

namespace rt::test
{
namespace
{
/// A closed box whose six walls all emit Le and reflect with albedo a: radiance is Le / (1 - a) inside any
/// closed enclosure (research notes §4.5). Unlike the sphere, light sampling here has variance, so the
/// mixture's weights (six quad lights against the cosine lobe) are really exercised.
TEST(Furnace, ClosedBoxWithSixEmittingWallsUnderEveryEstimator)
{
    const float albedo = 0.6f, emission = 0.8f;
    SceneBuilder b("box-furnace");
    const std::uint32_t g = b.group("walls");
    b.box(g, vec3(-1.0f, -0.7f, -1.3f), vec3(1.2f, 0.9f, 1.1f), b.emissiveLambertian(vec3(albedo), vec3(emission)));
    b.instance(g, Transform::rotateY(20.0f));
    Scene& s = b.scene();
    s.camera.lookFrom = vec3(0.1f, 0.0f, 0.2f);
    s.camera.lookAt = vec3(-0.5f, -0.2f, -1.0f);
    s.camera.vfovDegrees = 100.0f;
    const Scene scene = b.finish();
    ASSERT_EQ(scene.lights.size(), 6u);
    const double expected = emission / (1.0 - albedo);
    for (const Estimator estimator : {Estimator::BsdfOnly, Estimator::Mixture})
    {
        RenderSettings settings = smallSettings(40, 64, 40, estimator);
        settings.unidirectionalLight = false; // the walls face outwards; the camera sees their backs
        const RenderResult r = renderCpu(scene, settings);
        const MeanAndError m = pixelStatistics(r.image);
        EXPECT_NEAR(m.mean, expected, 3.0 * m.standardError + 1e-5 * expected) << toString(estimator);
        if (estimator == Estimator::Mixture)
        {
            EXPECT_GT(m.pixelStdDev, 1e-4) << "light sampling of a box should not be zero-variance";
        }
    }
}
} // namespace
} // namespace rt::test
