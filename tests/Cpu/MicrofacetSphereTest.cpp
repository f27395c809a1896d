// A rough copper sphere and a rough glass sphere under a uniform white sky against the float64 integral of
// their BSDFs (Support/MicrofacetSphere.h): the CPU engine's whole path, not the BSDF alone. Each estimator
// must give it: NEE has no light to sample, so its BSDF samples find the sky with MIS weight 1.
#include "Support/MicrofacetSphere.h"

#include "RenderTestSupport.h"

#include <gtest/gtest.h>

namespace rt::test
{
namespace
{
TEST(MicrofacetSkyFurnace, UnderAUniformSkyMatchesTheIntegralOfTheBsdf)
{
    for (const MicrofacetSphereCase& c : microfacetSphereCases())
    {
        SCOPED_TRACE(c.name);
        RenderSettings s = smallSettings(16, 512, microfacetSphereDepth(c), Estimator::BsdfOnly);
        s.russianRoulette = RussianRoulette::Off;
        expectMicrofacetSphere(renderCpu(microfacetSphereScene(c), s).image, c);
    }
}

TEST(MicrofacetSkyFurnace, EveryEstimatorSeesTheSkyTheSame)
{
    const MicrofacetSphereCase c = microfacetSphereCases().at(1); // copper, alpha 0.05, 60 degrees
    for (const Estimator e : {Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
    {
        SCOPED_TRACE(toString(e));
        expectMicrofacetSphere(renderCpu(microfacetSphereScene(c), smallSettings(16, 256, 8, e)).image, c);
    }
}

TEST(MicrofacetSkyFurnace, RoughGlassUnderAUniformSkyReturnsAtMostTheSky)
{
    // The whole path through the glass: the reflection plus what the interior lets out, never more than the
    // sky (microfacet single scattering loses energy, it makes none); and more than the reflection alone.
    for (const MicrofacetSphereCase& c : microfacetSphereCases())
    {
        if (c.conductor)
            continue;
        SCOPED_TRACE(c.name);
        const MeanAndError m = pixelStatistics(
            renderCpu(microfacetSphereScene(c), smallSettings(16, 256, 64, Estimator::BsdfOnly)).image);
        EXPECT_LE(m.mean, 1.0 + 4.0 * m.standardError);
        EXPECT_GT(m.mean, microfacetSphereReference(c).x + 0.5);
    }
}
} // namespace
} // namespace rt::test
