// Every NEE light sampler (area, solid-angle, projected; Shared/LightSampling.h) on lights that break naive
// formulas (issue 10, research notes §3.4; the lights and receivers: Support/DegenerateLights.h).
// Whatever the sampler returns must be finite, and a returned sample must carry pdf > 0; lightPdf must be
// finite and >= 0 at every direction. The lights are made by Sampling/LightSampling.h's constructors, the
// ones SceneBuilder::finish uses, which also drops lights of exactly zero area (checked below).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "Random/Pcg.h"
#include "Sampling/LightSampling.h"
#include "Sampling/Warps.h"
#include "Scene/SceneBuilder.h"
#include "Support/DegenerateLights.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using test::degenerateLights;
using test::finite;
using test::NamedLight;
using test::Receiver;
using test::receiversAround;

class StressLightSamplers : public ::testing::TestWithParam<LightSampler>
{
};

TEST_P(StressLightSamplers, DegenerateLightsGiveFiniteSamplesWithPositivePdf)
{
    const LightSampler strategy = GetParam();
    Rng rng(2024);
    for (const NamedLight& named : degenerateLights())
    {
        const LightData& light = named.light;
        ASSERT_TRUE(light.area > 0.0f && finite(light.normal) && finite(light.dualU) && finite(light.dualV))
            << named.name << ": the constructor made a non-finite record";
        int returned = 0, nonFinite = 0, zeroPdf = 0, badPdf = 0;
        for (const Receiver& r : receiversAround(light, rng))
            for (int k = 0; k < 16; ++k)
            {
                LightSample s;
                if (sampleLight(light, strategy, r.p, r.n, test::uniform2(rng), s))
                {
                    ++returned;
                    if (!finite(s.wi) || !finite(s.point) || !finite(s.normal) || !std::isfinite(s.pdf) ||
                        !std::isfinite(s.distance) || !std::isfinite(s.uv.x) || !std::isfinite(s.uv.y))
                        ++nonFinite;
                    else if (!(s.pdf > 0.0f))
                        ++zeroPdf;
                }
                const vec3 wi = sampleUniformSphere(test::uniform2(rng));
                const float pdf = lightPdf(light, strategy, r.p, r.n, wi);
                if (!std::isfinite(pdf) || pdf < 0.0f)
                    ++badPdf;
            }
        EXPECT_EQ(nonFinite, 0) << named.name << ": non-finite samples of " << returned;
        EXPECT_EQ(zeroPdf, 0) << named.name << ": returned samples with pdf <= 0, of " << returned;
        EXPECT_EQ(badPdf, 0) << named.name << ": lightPdf non-finite or negative";
        EXPECT_GT(returned, 0) << named.name << ": no sample at all";
    }
}

INSTANTIATE_TEST_SUITE_P(Samplers, StressLightSamplers,
                         ::testing::Values(LightSampler::Area, LightSampler::SolidAngle, LightSampler::Projected),
                         [](const auto& param) {
                             return std::string(param.param == LightSampler::Area         ? "Area"
                                                : param.param == LightSampler::SolidAngle ? "SolidAngle"
                                                                                         : "Projected");
                         });

TEST(StressLightList, ZeroAreaEmittersAreNotLights)
{
    // Collinear vertices and parallel quad edges have no area: no light record (its normal would be 0/0).
    SceneBuilder b("zero-area-emitters");
    const std::uint32_t glow = b.diffuseLight(vec3(1.0f));
    MeshData m;
    m.name = "collinear";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 1, 3};
    b.mesh(b.world(), b.addMesh(std::move(m)), glow);
    const Scene s = b.finish();
    ASSERT_EQ(s.lights.size(), 1u) << "only the second triangle has area";
    EXPECT_EQ(s.lightSources[0].primitive, 1u);
}
} // namespace
} // namespace rt
