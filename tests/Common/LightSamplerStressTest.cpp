// Every NEE light sampler (area, solid-angle, projected; Shared/LightSampling.h) on lights that break naive
// formulas (issue 10, research notes §3.4): slivers, triangles and quads of almost no area, lights that fill
// nearly the whole hemisphere of the receiver, receivers in the light's plane, receivers without a normal.
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
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
struct NamedLight
{
    std::string name;
    LightData light;
};

std::vector<NamedLight> degenerateLights()
{
    const auto tri = [](const vec3& a, const vec3& b, const vec3& c) { return makeTriangleLight(a, b, c, 0); };
    const auto quad = [](const vec3& q, const vec3& u, const vec3& v) { return makeQuadLight(q, u, v, 0); };
    return {
        {"sliver triangle 1e-6 wide", tri({0, 0, 0}, {1, 0, 0}, {0.5f, 1e-6f, 0})},
        {"needle triangle, one edge 1e-7", tri({0, 0, 0}, {1, 0, 0}, {1, 1e-7f, 0})},
        {"triangle almost collinear (1 ulp)", tri({-1113.45f, -0.5f, -56.24f}, {-1113.45f, 0.0f, -56.24f},
                                                  {-1113.45f, 0.5f, std::nextafter(-56.24f, 0.0f)})},
        {"triangle of area 1e-12", tri({0, 0, 0}, {1e-6f, 0, 0}, {0, 1e-6f, 0})},
        {"sliver quad 1e-6 wide", quad({0, 0, 0}, {1, 0, 0}, {0, 1e-6f, 0})},
        {"quad of area 1e-12", quad({0.3f, 0.2f, 0}, {1e-6f, 0, 0}, {0, 1e-6f, 0})},
        {"skewed quad, edges 1e-6 rad apart", quad({0, 0, 0}, {1, 0, 0}, {1, 1e-6f, 0})},
        {"huge quad: near a hemisphere", quad({-1e3f, -1e3f, 0}, {2e3f, 0, 0}, {0, 2e3f, 0})},
        {"huge triangle: near a hemisphere", tri({-1e3f, -1e3f, 0}, {2e3f, -1e3f, 0}, {-1e3f, 2e3f, 0})},
    };
}

bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Receivers around the light: random points near it (heights from 1e-6 to 1), points in its plane, with
/// random normals, normals towards it, along its plane, and none (a medium).
struct Receiver
{
    vec3 p;
    vec3 n;
};

std::vector<Receiver> receivers(const LightData& light, Rng& rng)
{
    std::vector<Receiver> out;
    const vec3 centre = light.p0 + 0.3f * light.p1 + 0.3f * light.p2;
    const float size = std::max(glm::length(light.p1), glm::length(light.p2));
    for (int i = 0; i < 600; ++i)
    {
        const float height = (i % 3 == 0) ? 0.0f : size * std::pow(10.0f, -6.0f * rng.nextFloat());
        const float side = (i % 2 == 0) ? 1.0f : -1.0f;
        const vec3 lateral = size * 2.0f * (rng.nextFloat() - 0.5f) * glm::normalize(light.p1) +
                             size * 2.0f * (rng.nextFloat() - 0.5f) * glm::normalize(light.p2);
        const vec3 p = centre + lateral + side * height * light.normal;
        vec3 n;
        switch (i % 4)
        {
        case 0: n = sampleUniformSphere(test::uniform2(rng)); break;
        case 1: n = -side * light.normal; break; // facing the light
        case 2: n = glm::normalize(light.p1); break; // along the light's plane
        default: n = vec3(0.0f); break; // in a medium
        }
        out.push_back({p, n});
    }
    return out;
}

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
        for (const Receiver& r : receivers(light, rng))
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
