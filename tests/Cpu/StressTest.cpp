// The numerical-stability stress suite on the CPU engine (issue 10; research notes §3.4): the scene moved
// far from the origin and scaled, tiny far spheres, a 1e6-radius ground, convex shapes under a sky (no
// secondary ray re-hits the shape it left), long accumulation, and no NaN/Inf sample anywhere. The scenes
// and checks are tests/Support/StressScenes.h, shared with tests/Gpu/GpuStressTest.cpp. Suites Stress*
// run by default (label stress); HeavyStress* are the long forms (labels stress, heavy).
#include <gtest/gtest.h>

#include <string>

#include "Engine/CpuEngine.h"
#include "Error.h"
#include "Scenes/Catalogue.h"
#include "Support/StressScenes.h"

namespace rt::test
{
namespace
{
struct NamedTransform
{
    const char* name;
    SceneTransform transform;
};

// Translations of the Cornell boxes (size ~1000) up to the measured limit kMaxOffsetToSize, and scales.
const NamedTransform kCornellTransforms[] = {
    {"Translate1e4", {vec3(1e4f, -1e4f, 1e4f), 1.0f}},
    {"Translate1e5", {vec3(1e5f, 0.0f, -1e5f), 1.0f}},
    {"Scale1e-3", {vec3(0.0f), 1e-3f}},
    {"Scale1e3", {vec3(0.0f), 1e3f}},
    {"Scale1e3Translate1e8", {vec3(0.0f, 1e8f, 0.0f), 1e3f}},
};

class StressMovedCornell : public ::testing::TestWithParam<NamedTransform>
{
};

TEST_P(StressMovedCornell, RendersTheSameImage)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    for (const char* id : {"rtrol-cornell-box", "cornell-box-lights"})
    {
        const MovedSceneAgreement a = compareMovedScene(engine, id, GetParam().transform, 64, 16);
        EXPECT_TRUE(a.disagreements.empty()) << id << ": " << a.disagreements.size() << " blocks, first "
                                             << a.disagreements.front();
        EXPECT_EQ(a.nonFiniteSamples, 0u) << id;
    }
}

INSTANTIATE_TEST_SUITE_P(Transforms, StressMovedCornell, ::testing::ValuesIn(kCornellTransforms),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(StressMovedCornellLimit, TranslationPastFloat32IsRefusedNamingTheLimit)
{
    SceneOptions options;
    options.transform.translation = vec3(1e6f, 0.0f, 0.0f);
    try
    {
        makeScene("rtrol-cornell-box", options);
        FAIL() << "a translation of 1e6 was accepted";
    }
    catch (const UsageError& e)
    {
        EXPECT_NE(std::string(e.what()).find("128 times its size"), std::string::npos) << e.what();
    }
    options.transform = {vec3(0.0f), 1e-6f};
    EXPECT_THROW(makeScene("rtrol-cornell-box", options), UsageError) << "a Cornell box 1e-3 units across";
}

struct ConvexCase
{
    ConvexShape shape;
    NamedTransform transform;
};

std::vector<ConvexCase> convexCases()
{
    // The shapes are ~3 units across: 100 units away is 30 times their size, inside the measured limit.
    const NamedTransform transforms[] = {{"AsBuilt", {}},
                                         {"Translate100", {vec3(100.0f, -60.0f, 80.0f), 1.0f}},
                                         {"Scale1e-3", {vec3(0.0f), 1e-3f}},
                                         {"Scale1e4Translate1e6", {vec3(1e6f, 0.0f, 5e5f), 1e4f}}};
    std::vector<ConvexCase> cases;
    for (const ConvexShape shape : {ConvexShape::Sphere, ConvexShape::Quad, ConvexShape::Triangle})
        for (const NamedTransform& t : transforms)
            cases.push_back({shape, t});
    return cases;
}

class StressConvexUnderSky : public ::testing::TestWithParam<ConvexCase>
{
};

TEST_P(StressConvexUnderSky, SecondaryRaysNeverReHitTheShapeTheyLeave)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    const ConvexUnderSky r = renderConvexUnderSky(engine, GetParam().shape, GetParam().transform.transform);
    EXPECT_GE(r.lowest, 0.5f - 1e-4f) << "a secondary ray re-hit the shape it left";
    EXPECT_LE(r.highest, 1.0f + 1e-4f);
    EXPECT_GT(r.shapePixels, 100) << "the shape must fill part of the 32x32 image";
    EXPECT_EQ(r.nonFiniteSamples, 0u);
}

INSTANTIATE_TEST_SUITE_P(Shapes, StressConvexUnderSky, ::testing::ValuesIn(convexCases()), [](const auto& info) {
    return toString(info.param.shape) + info.param.transform.name;
});

TEST(StressGroundSphere, HugeSphereIsLitAsThePlaneAtItsTop)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    const GroundPair g = renderGroundSphereAndPlane(engine, {});
    const auto bad = disagreeingBlocks(g.plane, g.sphere, kMaxZ);
    EXPECT_TRUE(bad.empty()) << bad.size() << " blocks, first " << bad.front();
    EXPECT_EQ(g.sphere.nonFiniteSamples + g.plane.nonFiniteSamples, 0u);
}

class StressTinySphere : public ::testing::TestWithParam<float>
{
};

TEST_P(StressTinySphere, IsHitWhereverRaysAimAtIt)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    const TinySphereCheck c = renderTinyFarSphere(engine, GetParam());
    EXPECT_GT(c.insidePixels, 50);
    EXPECT_GT(c.outsidePixels, 300);
    EXPECT_EQ(c.wrongInside, 0) << "pixels aimed inside the silhouette that missed";
    EXPECT_EQ(c.wrongOutside, 0) << "pixels aimed outside the silhouette that hit";
    EXPECT_EQ(c.nonFiniteSamples, 0u);
}

// 1e-3 radius at 1e3 units is 1e6 radii away: ulp(1e3) = 6e-5 is still 6 % of the radius.
INSTANTIATE_TEST_SUITE_P(Distances, StressTinySphere, ::testing::Values(10.0f, 100.0f, 1000.0f),
                         [](const auto& info) { return "Distance" + std::to_string(int(info.param)); });

// Tolerance 1e-5 relative: the exact values are sums of equal floats (zero variance), so a double sum is
// exact to 1e-7; a float one is 1.5e-4 off at 2^14 samples and 1 % at 2^20.
TEST(StressLongAccumulation, ProgressivePassesDoNotDrift)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    const AccumulationDrift d = renderLongAccumulation(engine, 1u << 16, PixelSampling::Accumulate);
    EXPECT_EQ(d.quadPixels, 4);
    EXPECT_LT(d.worstRelativeError, 1e-5);
    EXPECT_EQ(d.nonFiniteSamples, 0u);
}

TEST(HeavyStressLongAccumulation, MillionPassesStayWithinNoiseOfTheShortRun)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    const AccumulationDrift shortRun = renderLongAccumulation(engine, 1u << 14, PixelSampling::Accumulate);
    const AccumulationDrift longRun = renderLongAccumulation(engine, 1u << 20, PixelSampling::Accumulate);
    EXPECT_LT(shortRun.worstRelativeError, 1e-5);
    EXPECT_LT(longRun.worstRelativeError, 1e-5);
    EXPECT_EQ(shortRun.nonFiniteSamples + longRun.nonFiniteSamples, 0u);
}
} // namespace
} // namespace rt::test
