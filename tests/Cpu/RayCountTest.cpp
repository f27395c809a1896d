// Rays by kind (Render/RayCounts.h) where their number is known in closed form: inside the white furnace (a closed
// sphere) every path that Russian roulette does not end traces exactly `depth` segments, its camera ray and
// depth - 1 extension rays, and an estimator with NEE traces a shadow ray at each of its vertices but the last
// (the last vertex ends the path: the light it would sample lies beyond the depth).
#include <gtest/gtest.h>

#include "RenderTestSupport.h"
#include "Scenes/Catalogue.h"
#include "Shared/Estimator.h"

namespace rt::test
{
namespace
{
constexpr int kDepth = 5;

RenderResult renderFurnace(Estimator estimator, RussianRoulette roulette, EngineKind engine)
{
    const Scene scene = makeFurnace(0.5f, 0.5f);
    RenderSettings s = smallSettings(16, 3, kDepth, estimator);
    s.russianRoulette = roulette;
    s.unidirectionalLight = scene.defaults.unidirectionalLight;
    return renderCpu(scene, s, engine);
}

TEST(RayCounts, InTheFurnaceEveryPathTracesItsDepthAndNeeAShadowRayPerVertexButTheLast)
{
    for (const EngineKind engine : {EngineKind::Single, EngineKind::Multi})
        for (const Estimator e : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
        {
            const RenderResult r = renderFurnace(e, RussianRoulette::Off, engine);
            const RenderStats& st = r.stats;
            ASSERT_TRUE(st.raysCounted);
            EXPECT_EQ(st.paths, 16u * 16u * 3u);
            EXPECT_EQ(st.rays.camera, st.paths) << toString(e);
            EXPECT_EQ(st.rays.extension, (kDepth - 1) * st.paths) << toString(e);
            EXPECT_EQ(st.rays.shadow, shader::usesNee(e) ? (kDepth - 1) * st.paths : 0u) << toString(e);
            // Each of those vertices drew one light sample (the furnace's sphere: its own samplers, no fallback).
            EXPECT_EQ(st.lightSamples.drawn, st.rays.shadow) << toString(e);
            EXPECT_EQ(st.lightSamples.fallback + st.lightSamples.declined, 0u) << toString(e);
            EXPECT_DOUBLE_EQ(st.mraysPerSecond(st.rays.total()), double(st.rays.total()) / st.renderSeconds * 1e-6);
        }
}

TEST(RayCounts, RussianRouletteEndsPathsAsItsRuleSays)
{
    // Albedo 0.5, so the throughput is 0.5^k after scattering at vertex k - 1. The roulette is first drawn at
    // vertex 1 (beta 0.25), deciding the third segment. pbrt-v4's rule (survival m, the throughput's largest
    // component) survives with 0.25 and scales beta back to 1, then survives each later vertex with 0.5: the
    // extension rays of segments 1-4 are expected 1 + 1/4 + 1/8 + 1/16 = 1.4375 per path. Cycles' rule (survival
    // sqrt(m)) survives vertex 1 with 0.5 and leaves beta at sqrt(0.25) = 0.5, so every later vertex sees m = 0.25
    // again: 1 + 1/2 + 1/4 + 1/8 = 1.875 per path. A path's count has a standard deviation of 0.86 (pbrt-v4) or
    // 1.05 (Cycles), so over 768 paths the mean's is below 0.04: the bounds, 0.15, are 4 of those, and the two
    // expectations 11 apart.
    for (const auto& [rule, expected] : {std::pair{RussianRoulette::Throughput, 1.4375}, std::pair{RussianRoulette::Sqrt, 1.875}})
    {
        const RenderStats st = renderFurnace(Estimator::NeeMis, rule, EngineKind::Multi).stats;
        EXPECT_EQ(st.rays.camera, st.paths);
        EXPECT_NEAR(double(st.rays.extension) / double(st.paths), expected, 0.15) << toString(rule);
        // NEE runs at a vertex before the roulette (drawn after scattering): a shadow ray at every vertex a path
        // goes on from, and one more at the vertex where the roulette ends it, at most once per path.
        EXPECT_GT(st.rays.shadow, st.rays.extension);
        EXPECT_LE(st.rays.shadow, st.rays.extension + st.paths);
    }
}

TEST(LightSampleCounts, TheSamplerChangesNoPathAndItsFallbacksAreCounted)
{
    // NEE's numbers are drawn whatever its sample becomes and the path's direction does not depend on it, so every
    // light sampler draws at the same vertices. Area sampling asked for is no fallback; the solid-angle and the
    // projected samplers share the spherical rectangle's bounds, so they fall back at the same vertices: on
    // cornell-box-lights the points that see a light below 1e-2 sr (its nine 355 x 10 strips on the back wall:
    // 0.005-0.03 sr from the floor's centre, mostly below 1e-2 from the front of the room).
    const Scene scene = makeScene("cornell-box-lights");
    RenderSettings s = smallSettings(24, 2, 50, Estimator::NeeMis);
    s.unidirectionalLight = scene.defaults.unidirectionalLight;
    LightSampleCounts counts[4];
    const LightSampler samplers[4] = {LightSampler::Area, LightSampler::SolidAngle, LightSampler::Projected,
                                      LightSampler::ProjectedExact};
    for (int i = 0; i < 4; ++i)
    {
        s.lightSampler = samplers[i];
        const RenderStats st = renderCpu(scene, s, EngineKind::Multi).stats;
        counts[i] = st.lightSamples;
        EXPECT_GE(counts[i].drawn, st.rays.shadow) << toString(samplers[i]);
        EXPECT_EQ(counts[i].drawn, counts[0].drawn) << toString(samplers[i]);
        EXPECT_EQ(counts[i].declined, 0u) << toString(samplers[i]) << ": no receiver lies in a light's plane";
    }
    EXPECT_GT(counts[0].drawn, 2000u);
    EXPECT_EQ(counts[0].fallback, 0u);
    EXPECT_GT(counts[1].fallback, counts[1].drawn / 20) << "too few to say the bounds are applied";
    EXPECT_LT(counts[1].fallback, counts[1].drawn / 2);
    EXPECT_EQ(counts[2].fallback, counts[1].fallback);
    // Peters' sampler falls back below 1e-4 sr of projected solid angle: fewer vertices.
    EXPECT_GT(counts[3].fallback, 0u);
    EXPECT_LT(counts[3].fallback, counts[1].fallback);
}

TEST(RayCounts, RestirTracesEachCameraPathTwice)
{
    // The candidates pass traces the camera ray to the vertex it resamples at, the shading pass the whole path
    // again from the camera: two camera rays per path, the extension rays once.
    const RenderStats st = renderFurnace(Estimator::RestirDi, RussianRoulette::Off, EngineKind::Multi).stats;
    EXPECT_EQ(st.rays.camera, 2 * st.paths);
    EXPECT_EQ(st.rays.extension, (kDepth - 1) * st.paths);
    EXPECT_GT(st.rays.shadow, (kDepth - 2) * st.paths) << "NEE past the resampled vertex, and the reservoirs' rays";
}

TEST(LightSampleCounts, RestirCountsEachCandidateAndNeeBeyondTheResampledVertex)
{
    // In the furnace every vertex selects its light: each pixel's resampled vertex draws the render's M candidates,
    // and NEE one sample at each vertex past it but the last, depth - 2 of them.
    const RenderStats st = renderFurnace(Estimator::RestirDi, RussianRoulette::Off, EngineKind::Multi).stats;
    // renderFurnace's M.
    const std::uint64_t candidates = smallSettings(16, 3, kDepth, Estimator::RestirDi).restirCandidates;
    EXPECT_EQ(st.lightSamples.drawn, (candidates + kDepth - 2) * st.paths);
    EXPECT_EQ(st.lightSamples.fallback + st.lightSamples.declined, 0u);
}
} // namespace
} // namespace rt::test
