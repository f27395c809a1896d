// The numerical-stability stress suite on the GPU engine: the checks of tests/Cpu/StressTest.cpp
// (tests/Support/StressScenes.h), at sizes lavapipe renders in seconds. Suites GpuStress* run by default
// (labels gpu, stress); Heavy/GpuStress* are the long forms (labels gpu, stress, heavy).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "GpuTestEnvironment.h"
#include "ParityKernel.h"
#include "Support/DegenerateLights.h"
#include "Support/StressScenes.h"

namespace rt::gpu::test
{
namespace
{
using namespace ::rt::test;

class GpuStressTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        RT_REQUIRE_GPU();
        m_messagesBefore = sharedEngine()->validationMessages();
    }
    void TearDown() override
    {
        if (sharedEngine())
        {
            EXPECT_EQ(sharedEngine()->validationMessages(), m_messagesBefore) << "Vulkan validation messages";
        }
    }

private:
    std::uint64_t m_messagesBefore = 0;
};

using GpuStressMovedCornell = GpuStressTest;

// The CPU suite's transforms (inside the measured limits), on the book 3 box only (its quads and rotated boxes: the triangle BLASes and
// their TLAS instance transforms), 64 pixels at 8 spp.
TEST_F(GpuStressMovedCornell, RendersTheSameImageMovedAndScaled)
{
    const SceneTransform transforms[] = {{vec3(1e4f, -1e4f, 1e4f), 1.0f},
                                         {vec3(1e6f, -1e6f, 1e6f), 1.0f}, // render space: issue 41
                                         {vec3(0.0f), 1e-3f},
                                         {vec3(0.0f), 1e3f},
                                         {vec3(0.0f, 1e7f, 0.0f), 1e3f}};
    for (const SceneTransform& t : transforms)
    {
        const MovedSceneAgreement a = compareMovedScene(*sharedEngine(), "rtrol-cornell-box", t, 64, 8);
        EXPECT_TRUE(a.disagreements.empty()) << "translation " << t.translation.x << ", scale " << t.scale << ": "
                                             << a.disagreements.size() << " blocks, first " << a.disagreements.front();
        EXPECT_EQ(a.nonFiniteSamples, 0u);
    }
}

using GpuStressConvexUnderSky = GpuStressTest;

TEST_F(GpuStressConvexUnderSky, SecondaryRaysNeverReHitTheShapeTheyLeave)
{
    const SceneTransform transforms[] = {{}, {vec3(50.0f, -30.0f, 40.0f), 1.0f}, {vec3(0.0f), 1e-3f},
                                         {vec3(3e5f, 0.0f, 1e5f), 1e4f}};
    for (const ConvexShape shape : {ConvexShape::Sphere, ConvexShape::Quad, ConvexShape::Triangle})
        for (const SceneTransform& t : transforms)
        {
            const ConvexUnderSky r = renderConvexUnderSky(*sharedEngine(), shape, t);
            const std::string what = toString(shape) + " translated " + std::to_string(t.translation.x) +
                                     ", scaled " + std::to_string(t.scale);
            EXPECT_GE(r.lowest, 0.5f - 1e-4f) << what << ": a secondary ray re-hit the shape it left";
            EXPECT_LE(r.highest, 1.0f + 1e-4f) << what;
            EXPECT_GT(r.shapePixels, 100) << what;
            EXPECT_EQ(r.nonFiniteSamples, 0u) << what;
        }
}

using GpuStressGround = GpuStressTest;

TEST_F(GpuStressGround, HugeSphereIsLitAsThePlaneAtItsTop)
{
    const GroundPair g = renderGroundSphereAndPlane(*sharedEngine());
    const auto bad = disagreeingBlocks(g.plane, g.sphere, kMaxZ);
    EXPECT_TRUE(bad.empty()) << bad.size() << " blocks, first " << bad.front();
    EXPECT_EQ(g.sphere.nonFiniteSamples + g.plane.nonFiniteSamples, 0u);
}

using GpuStressTinySphere = GpuStressTest;

TEST_F(GpuStressTinySphere, IsHitWhereverRaysAimAtIt)
{
    for (const float distance : {10.0f, 100.0f, 1000.0f})
    {
        const TinySphereCheck c = renderTinyFarSphere(*sharedEngine(), distance);
        EXPECT_GT(c.insidePixels, 50);
        EXPECT_EQ(c.wrongInside, 0) << "distance " << distance << ": pixels aimed inside the silhouette that missed";
        EXPECT_EQ(c.wrongOutside, 0) << "distance " << distance << ": pixels aimed outside that hit";
        EXPECT_EQ(c.nonFiniteSamples, 0u);
    }
}

using GpuStressLightSamplers = GpuStressTest;

// The Common suite's degenerate lights (Support/DegenerateLights.h) through the GPU's compilation of
// Shared/LightSampling.h (Shaders/Tests/Parity.comp, mode kLightSampling), every NEE sampler: each returned
// sample finite with pdf > 0, and lightPdf of its direction finite and >= 0 (float32 on the GPU).
TEST_F(GpuStressLightSamplers, DegenerateLightsGiveFiniteSamplesWithPositivePdf)
{
    Rng rng(2024);
    for (const NamedLight& named : degenerateLights())
        for (const std::uint32_t strategy : {0u, 1u, 2u}) // LightSampler Area, SolidAngle, Projected
        {
            std::vector<std::uint32_t> in;
            for (const Receiver& r : receiversAround(named.light, rng))
                for (int k = 0; k < 16; ++k)
                {
                    const vec2 u = uniform2(rng);
                    in.insert(in.end(), {0u, bits(r.p.x), bits(r.p.y), bits(r.p.z), bits(u.x), bits(u.y), strategy,
                                         bits(r.n.x), bits(r.n.y), bits(r.n.z)});
                }
            const std::vector<std::uint32_t> out = runParity(kLightSampling, in, {named.light});
            const std::uint32_t words = kParityLayouts[kLightSampling].outputWords;
            int returned = 0, bad = 0;
            for (std::size_t i = 0; i + words <= out.size(); i += words)
            {
                if (out[i] == 0u)
                    continue;
                ++returned;
                const float pdf = asFloat(out[i + 4]), pdfAgain = asFloat(out[i + 5]);
                if (!finite(vec3At(out, i + 1)) || !std::isfinite(pdf) || !(pdf > 0.0f) || !std::isfinite(pdfAgain) ||
                    pdfAgain < 0.0f)
                    ++bad;
            }
            EXPECT_EQ(bad, 0) << named.name << ", sampler " << strategy << ": bad samples of " << returned;
            EXPECT_GT(returned, 0) << named.name << ", sampler " << strategy;
        }
}

// Random sampling, not 1-spp passes: a dispatch per pass would take hours on lavapipe; the shader adds the
// samples one after the other into the accumulation image either way.
class GpuStressLongAccumulation : public GpuStressTest, public ::testing::WithParamInterface<std::uint32_t>
{
};

TEST_P(GpuStressLongAccumulation, SumsDoNotDrift)
{
    const AccumulationDrift d = renderLongAccumulation(*sharedEngine(), GetParam(), PixelSampling::Random);
    EXPECT_EQ(d.quadPixels, 4);
    EXPECT_LT(d.worstRelativeError, 1e-5) << GetParam() << " spp";
    EXPECT_EQ(d.nonFiniteSamples, 0u);
}

INSTANTIATE_TEST_SUITE_P(Short, GpuStressLongAccumulation, ::testing::Values(1u << 14),
                         [](const auto& param) { return "Spp" + std::to_string(param.param); });
INSTANTIATE_TEST_SUITE_P(Heavy, GpuStressLongAccumulation, ::testing::Values(1u << 20),
                         [](const auto& param) { return "Spp" + std::to_string(param.param); });
} // namespace
} // namespace rt::gpu::test
