// What NEE's samplers say of each sample (LightSample::outcome, Shared/Lights/LightSample.h), which the engines
// count in the stats: a sample made by area sampling where the strategy asked for another sampler is marked
// kLightSampleFallback, one that rounding put off the light kLightSampleDeclined, and a sample the strategy's own
// sampler made is marked neither. The configurations are chosen by their geometry (a light's solid angle in
// double, a receiver in the light's plane), not by what the samplers compute.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "Render/LightSampleCounts.h"
#include "Render/RenderSettings.h"
#include "Render/RenderStats.h"
#include "Support/LightCases.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
constexpr int kSamples = 2000;
const vec3 kUp(0.0f, 0.0f, 1.0f);

/// Solid angle (sr) of the w x h rectangle centred on the z axis at height z, seen from the origin, in double:
/// 4 asin(a b / sqrt((a^2 + z^2)(b^2 + z^2))) with half-sides a, b.
double centredRectangleSolidAngle(double w, double h, double z)
{
    const double a = 0.5 * w, b = 0.5 * h;
    return 4.0 * std::asin(a * b / std::sqrt((a * a + z * z) * (b * b + z * z)));
}

/// A w x h rectangle light centred on the z axis at height z, facing down.
LightData centredRectangle(float w, float h, float z)
{
    return test::makeQuadLight({-0.5f * w, -0.5f * h, z}, {0.0f, h, 0.0f}, {w, 0.0f, 0.0f});
}

struct Tally
{
    int sampled = 0;
    int fallback = 0;
    int declined = 0;
    int other = 0; // bits beyond the two
};

/// kSamples samples of `light` from p (receiver normal n) by `strategy`, their outcomes counted.
Tally sampleOutcomes(const LightData& light, LightSampler strategy, const vec3& p, const vec3& n, std::uint32_t seed)
{
    Tally t;
    Rng rng(pcgHash(seed));
    for (int i = 0; i < kSamples; ++i)
    {
        LightSample ls;
        t.sampled += sampleLight(light, strategy, p, n, test::uniform2(rng), ls) ? 1 : 0;
        t.fallback += (ls.outcome & shader::kLightSampleFallback) != 0;
        t.declined += (ls.outcome & shader::kLightSampleDeclined) != 0;
        t.other += (ls.outcome & ~(shader::kLightSampleFallback | shader::kLightSampleDeclined)) != 0;
    }
    return t;
}

TEST(LightSampleOutcome, ARectangleTooSmallForItsSamplerIsSampledByAreaAndSaysSo)
{
    // 0.05 x 0.05 at 10: 2.5e-5 sr, below kMinSphericalRectangle (1e-2) and, projected, kMinProjectedPolygon (1e-4).
    const LightData tiny = centredRectangle(0.05f, 0.05f, 10.0f);
    ASSERT_LT(centredRectangleSolidAngle(0.05, 0.05, 10.0), 1e-4);
    for (const LightSampler s : {LightSampler::SolidAngle, LightSampler::Projected, LightSampler::ProjectedExact})
    {
        const Tally t = sampleOutcomes(tiny, s, vec3(0.0f), kUp, 1);
        EXPECT_EQ(t.sampled, kSamples) << toString(s);
        EXPECT_EQ(t.fallback, kSamples) << toString(s);
        EXPECT_EQ(t.declined, 0) << toString(s);
        EXPECT_EQ(t.other, 0) << toString(s);
    }
    const Tally area = sampleOutcomes(tiny, LightSampler::Area, vec3(0.0f), kUp, 1);
    EXPECT_EQ(area.sampled, kSamples);
    EXPECT_EQ(area.fallback, 0) << "area sampling asked for is no fallback";
}

TEST(LightSampleOutcome, ARectangleLargeEnoughIsSampledByItsOwnSampler)
{
    // 1 x 1 at 1: 0.80 sr, within every sampler's bounds.
    const LightData near = centredRectangle(1.0f, 1.0f, 1.0f);
    ASSERT_GT(centredRectangleSolidAngle(1.0, 1.0, 1.0), 0.5);
    for (const LightSampler s :
         {LightSampler::Area, LightSampler::SolidAngle, LightSampler::Projected, LightSampler::ProjectedExact})
    {
        const Tally t = sampleOutcomes(near, s, vec3(0.0f), kUp, 2);
        EXPECT_EQ(t.sampled, kSamples) << toString(s);
        EXPECT_EQ(t.fallback + t.declined + t.other, 0) << toString(s);
    }
}

TEST(LightSampleOutcome, AParallelogramFallsBackFromTheRectangleSamplers)
{
    const LightData skewed = test::makeQuadLight({-0.5f, -0.5f, 1.0f}, {1, 0, 0}, {0.5f, 1, 0});
    ASSERT_FALSE(shader::isRectangle(skewed));
    for (const LightSampler s : {LightSampler::SolidAngle, LightSampler::Projected})
        EXPECT_EQ(sampleOutcomes(skewed, s, vec3(0.0f), kUp, 3).fallback, kSamples) << toString(s);
    // Peters' projected-exact sampler takes any planar polygon: no fallback.
    EXPECT_EQ(sampleOutcomes(skewed, LightSampler::ProjectedExact, vec3(0.0f), kUp, 3).fallback, 0);
}

TEST(LightSampleOutcome, TrianglesOutsideArvosBoundsFallBack)
{
    // Half of a 0.05 x 0.05 square at 10 (1.25e-5 sr, below kMinSphericalTriangle, 3e-4) against half of a unit
    // square at 1 (0.40 sr).
    const LightData tiny = test::makeTriangleLight({-0.025f, -0.025f, 10}, {0.025f, -0.025f, 10}, {-0.025f, 0.025f, 10});
    const LightData near = test::makeTriangleLight({-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1});
    for (const LightSampler s : {LightSampler::SolidAngle, LightSampler::Projected, LightSampler::ProjectedExact})
    {
        EXPECT_EQ(sampleOutcomes(tiny, s, vec3(0.0f), kUp, 4).fallback, kSamples) << toString(s);
        const Tally t = sampleOutcomes(near, s, vec3(0.0f), kUp, 5);
        EXPECT_EQ(t.sampled, kSamples) << toString(s);
        EXPECT_EQ(t.fallback + t.declined, 0) << toString(s);
    }
}

TEST(LightSampleOutcome, AReceiverInTheLightsPlaneDeclinesEverySample)
{
    // The unit square in z = 0 seen from (2, 0.5, 0): every sampled point's direction lies in the plane, where
    // the light has no solid angle, so its pdf is 0. Area sampling declines each; the spherical samplers first
    // fall back to it (no solid angle), then decline likewise. No sample is dropped unmarked.
    const LightData square = test::makeQuadLight({0, 0, 0}, {0, 1, 0}, {1, 0, 0});
    const vec3 p(2.0f, 0.5f, 0.0f);
    const Tally area = sampleOutcomes(square, LightSampler::Area, p, vec3(0.0f), 6);
    EXPECT_EQ(area.sampled, 0);
    EXPECT_EQ(area.declined, kSamples);
    EXPECT_EQ(area.fallback, 0);
    const Tally solidAngle = sampleOutcomes(square, LightSampler::SolidAngle, p, vec3(0.0f), 6);
    EXPECT_EQ(solidAngle.sampled, 0);
    EXPECT_EQ(solidAngle.declined, kSamples);
    EXPECT_EQ(solidAngle.fallback, kSamples);
    // Book 3's sampler (the mixture's) marks its declined samples the same way.
    Rng rng(pcgHash(7));
    LightSample ls;
    EXPECT_FALSE(sampleLight(square, p, test::uniform2(rng), ls));
    EXPECT_EQ(ls.outcome, shader::kLightSampleDeclined);
}

TEST(LightSampleOutcome, SpheresNeverFallBackAndTheirFarSideIsNoDeclinedSample)
{
    const LightData sphere = test::makeSphereLight({0, 0, 3}, 1.0f);
    for (const LightSampler s : {LightSampler::SolidAngle, LightSampler::Projected, LightSampler::ProjectedExact})
    {
        const Tally t = sampleOutcomes(sphere, s, vec3(0.0f), kUp, 8);
        EXPECT_EQ(t.sampled, kSamples) << toString(s);
        EXPECT_EQ(t.fallback + t.declined + t.other, 0) << toString(s);
    }
    // Area sampling from outside draws the whole surface: from 3 radii away two thirds of its points face away
    // (no contribution by design), which is neither a fallback nor a declined sample.
    const Tally area = sampleOutcomes(sphere, LightSampler::Area, vec3(0.0f), kUp, 9);
    // (1 - r / d) / 2 = 1/3 kept: 667 of 2000, one standard deviation 21.
    EXPECT_NEAR(area.sampled, kSamples / 3, kSamples / 30);
    EXPECT_EQ(area.fallback + area.declined + area.other, 0);
}
TEST(LightSampleCounts, EachOutcomeIsCountedAndTheStatsCarryThem)
{
    LightSampleCounts c;
    countLightSample(c, 0u); // a vertex that drew none
    countLightSample(c, shader::kLightSampleDrawn);
    countLightSample(c, shader::kLightSampleDrawn | shader::kLightSampleFallback);
    countLightSample(c, shader::kLightSampleDrawn | shader::kLightSampleFallback | shader::kLightSampleDeclined);
    countLightSample(c, shader::kLightSampleDrawn | shader::kLightSampleDeclined);
    EXPECT_EQ(c, (LightSampleCounts{4, 2, 2}));
    EXPECT_EQ(lightSampleCountsFromJson(toJson(c)), c);

    RenderStats st;
    st.lightSamples = c;
    EXPECT_FALSE(st.toJson().contains("light_samples")) << "not counted: not reported";
    st.raysCounted = true;
    const nlohmann::json j = st.toJson();
    EXPECT_EQ(j.at("light_samples").at("drawn"), 4u);
    EXPECT_EQ(j.at("light_samples").at("fallback"), 2u);
    EXPECT_EQ(j.at("light_samples").at("declined"), 2u);
}
} // namespace
} // namespace rt
