// Pixel sampling modes: stratified divides by the samples really taken (the thesis' CPU app took 9 of a
// nominal 10 and divided by 10: images 10 % too dark), accumulation equals independent sampling.
#include <gtest/gtest.h>

#include "RenderTestSupport.h"
#include "Scenes/Catalogue.h"

namespace rt::test
{
namespace
{
TEST(PixelSampling, StratifiedReportsAndDividesByTheSamplesTaken)
{
    const Scene scene = makeFurnace(0.5f, 0.5f); // every pixel converges to 1
    RenderSettings s = smallSettings(48, 10, 40, Estimator::BsdfOnly);
    s.sampling = PixelSampling::Stratified;
    s.unidirectionalLight = false; // the camera sees the inside of the sphere
    const RenderResult r = renderCpu(scene, s);
    EXPECT_EQ(r.stats.trueSpp, 9);
    EXPECT_EQ(r.stats.paths, 48ull * 48ull * 9ull);
    const MeanAndError m = pixelStatistics(r.image);
    EXPECT_NEAR(m.mean, 1.0, 3.0 * m.standardError + 1e-5); // dividing by 10 would give 0.9
}

TEST(PixelSampling, AccumulatedPassesEqualIndependentSamples)
{
    // Sample k of a pixel uses stream (seed, pixel, k) in both modes and is summed in the same order.
    const Scene scene = makeScene("rtrol-cornell-box");
    RenderSettings s = smallSettings(32, 6, 12, Estimator::Mixture);
    const Image random = renderCpu(scene, s).image;
    s.sampling = PixelSampling::Accumulate;
    EXPECT_TRUE(bitIdentical(random, renderCpu(scene, s).image));
}

TEST(PixelSampling, StratifiedReducesErrorOnAnEdge)
{
    // Anti-aliasing an edge is a 2-D integral with a discontinuity: jittered strata converge faster than
    // independent samples (research notes §5). Reference: the same view at 1024 spp.
    const Scene scene = makeScene("rtow-camera-test");
    RenderSettings s = smallSettings(40, 1024, 1, Estimator::BsdfOnly, 16.0f / 9.0f); // depth 1: camera rays only
    const Image reference = renderCpu(scene, s).image;
    s.spp = 16;
    double errRandom = 0.0, errStratified = 0.0;
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
    {
        s.seed = seed;
        s.sampling = PixelSampling::Random;
        const Image a = renderCpu(scene, s).image;
        s.sampling = PixelSampling::Stratified;
        const Image b = renderCpu(scene, s).image;
        for (std::size_t i = 0; i < reference.pixelCount(); ++i)
        {
            const vec3 da = a.data()[i] - reference.data()[i], db = b.data()[i] - reference.data()[i];
            errRandom += glm::dot(da, da);
            errStratified += glm::dot(db, db);
        }
    }
    EXPECT_LT(errStratified, 0.7 * errRandom);
}
} // namespace
} // namespace rt::test
