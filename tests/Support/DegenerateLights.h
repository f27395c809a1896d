// The stress suite's degenerate lights and the receivers around them (issue 10, research notes §3.4):
// slivers, triangles and quads of almost no area, lights that fill nearly the whole hemisphere of the
// receiver, receivers in the light's plane and without a normal. Made by Sampling/LightSampling.h's
// constructors, the ones SceneBuilder::finish uses. The CPU samplers take them in
// tests/Common/LightSamplerStressTest.cpp, the GPU's in tests/Gpu/GpuStressTest.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Random/Pcg.h"
#include "Sampling/LightSampling.h"
#include "Sampling/Warps.h"
#include "Support/StatisticsHelpers.h"

namespace rt::test
{
struct NamedLight
{
    std::string name;
    LightData light;
};

inline std::vector<NamedLight> degenerateLights()
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

inline bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Receivers around the light: random points near it (heights from 1e-6 to 1), points in its plane, with
/// random normals, normals towards it, along its plane, and none (a medium).
struct Receiver
{
    vec3 p;
    vec3 n;
};

inline std::vector<Receiver> receiversAround(const LightData& light, Rng& rng)
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
        case 0: n = sampleUniformSphere(uniform2(rng)); break;
        case 1: n = -side * light.normal; break; // facing the light
        case 2: n = glm::normalize(light.p1); break; // along the light's plane
        default: n = vec3(0.0f); break; // in a medium
        }
        out.push_back({p, n});
    }
    return out;
}

} // namespace rt::test
