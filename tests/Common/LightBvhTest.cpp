// The light BVH (Sampling/LightBvh.h builds it, Shared/LightBvh.h descends it): the tree bounds what it
// claims (boxes, power, parents, leaves), the pmf of every light sums to 1 and equals what selection
// reports, selection follows the pmf (chi-square), no light that can light a point is denied (the bound is
// conservative, checked against points sampled on each light), and lights of zero power are never picked.
// restir-di's candidates, whose selection numbers are stratified (Shared/Restir.h), follow the pmf together.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "Random/Pcg.h"
#include "Sampling/LightBvh.h"
#include "Scenes/Catalogue.h"
#include "Shared/LightSelection.h"
#include "Shared/Restir.h"
#include "Support/ChiSquare.h"
#include "Support/LightCases.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
/// A scene holding only `lights`, each with its own solid emission of luminance `power[i]` (0 allowed).
Scene sceneOfLights(const std::vector<LightData>& lights, const std::vector<float>& radiance)
{
    Scene scene;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        TextureData t{};
        t.type = TextureType::Solid;
        t.color0 = vec3(radiance[i]);
        scene.textures.push_back(t);
        MaterialData m{};
        m.type = MaterialType::DiffuseLight;
        m.albedoTexture = kNoIndex;
        m.emissionTexture = std::uint32_t(i);
        scene.materials.push_back(m);
        LightData l = lights[i];
        l.material = std::uint32_t(i);
        scene.lights.push_back(l);
    }
    return scene;
}

vec3 uniformIn(Rng& rng, float lo, float hi)
{
    const float x = rng.nextFloat();
    const float y = rng.nextFloat();
    const float z = rng.nextFloat();
    return vec3(lo) + (hi - lo) * vec3(x, y, z);
}

vec3 randomDirection(Rng& rng)
{
    const vec2 u = test::uniform2(rng);
    return shader::sampleUniformSphere(u);
}

/// Spheres, quads and triangles of random size, place, orientation and power (one in seven black).
Scene randomLights(std::uint32_t seed, int count)
{
    Rng rng(pcgHash(seed));
    std::vector<LightData> lights;
    std::vector<float> radiance;
    for (int i = 0; i < count; ++i)
    {
        const vec3 c = uniformIn(rng, -10.0f, 10.0f);
        const float size = 0.05f + 2.0f * rng.nextFloat();
        const int kind = i % 3;
        if (kind == 0)
            lights.push_back(test::makeSphereLight(c, 0.5f * size));
        else
        {
            const vec3 u = size * randomDirection(rng);
            const vec3 v = size * glm::normalize(glm::cross(u, randomDirection(rng)));
            lights.push_back(kind == 1 ? test::makeQuadLight(c, u, v) : test::makeTriangleLight(c, c + u, c + v));
        }
        radiance.push_back(i % 7 == 3 ? 0.0f : 0.1f + 10.0f * rng.nextFloat());
    }
    return sceneOfLights(lights, radiance);
}

float pmfOf(const LightBvh& bvh, std::uint32_t light, const vec3& p, const vec3& n, bool twoSided)
{
    return shader::lightBvhPmf(bvh.nodes.data(), bvh.leaves.data(), light, p, n, twoSided);
}

bool isLeaf(const LightBvhNode& node) { return (node.child & shader::kLightBvhLeaf) != 0u; }

/// True when the node's sphere holds every point of the light (its corners; a sphere's box corners).
bool holds(const LightBvhNode& node, const LightData& l)
{
    std::vector<vec3> corners;
    if (l.shape == LightShape::Sphere)
    {
        for (int k = 0; k < 8; ++k)
            corners.push_back(l.p0 + l.radius * vec3(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f));
    }
    else
    {
        corners = {l.p0, l.p0 + l.p1, l.p0 + l.p2};
        if (l.shape == LightShape::Quad)
            corners.push_back(l.p0 + l.p1 + l.p2);
    }
    for (const vec3& c : corners)
    {
        const dvec3 d = dvec3(c) - dvec3(node.centre);
        if (glm::dot(d, d) > double(node.radius2))
            return false;
    }
    return true;
}

TEST(LightBvh, TreeBoundsItsLightsAndEveryLeafIsFound)
{
    const Scene scene = randomLights(7, 300);
    const LightBvh bvh = buildLightBvh(scene);
    ASSERT_EQ(bvh.leaves.size(), scene.lights.size());
    int leaves = 0;
    for (std::uint32_t i = 0; i < bvh.nodes.size(); ++i)
    {
        const LightBvhNode& node = bvh.nodes[i];
        if (isLeaf(node))
        {
            ++leaves;
            const std::uint32_t light = node.child & ~shader::kLightBvhLeaf;
            ASSERT_LT(light, scene.lights.size());
            EXPECT_EQ(bvh.leaves[light], i);
            EXPECT_GT(node.power, 0.0f);
            continue;
        }
        const LightBvhNode& a = bvh.nodes[i + 1];
        const LightBvhNode& b = bvh.nodes[node.child];
        EXPECT_EQ(a.parent, i);
        EXPECT_EQ(b.parent, i);
        EXPECT_NEAR(node.power, a.power + b.power, 1e-5f * node.power);
    }
    // Every node's sphere holds the emitters below it, its cone of normals their normals (a sphere's: every
    // direction).
    for (std::uint32_t light = 0; light < scene.lights.size(); ++light)
    {
        if (bvh.leaves[light] == kNoIndex)
            continue;
        const LightBvhNode& leaf = bvh.nodes[bvh.leaves[light]];
        EXPECT_TRUE(holds(leaf, scene.lights[light])) << "light " << light;
        for (std::uint32_t k = leaf.parent; k != kNoIndex; k = bvh.nodes[k].parent)
        {
            const LightBvhNode& node = bvh.nodes[k];
            EXPECT_TRUE(holds(node, scene.lights[light])) << "light " << light << " under node " << k;
            const float thetaNode = std::acos(node.cosThetaO);
            const float between = std::acos(std::clamp(glm::dot(node.axis, leaf.axis), -1.0f, 1.0f));
            EXPECT_LE(std::min(between + std::acos(leaf.cosThetaO), 3.14159265f), thetaNode + 1e-4f)
                << "light " << light << " under node " << k;
        }
    }
    int powered = 0;
    for (std::uint32_t i = 0; i < scene.lights.size(); ++i)
    {
        const bool black = i % 7 == 3;
        EXPECT_EQ(bvh.leaves[i] == kNoIndex, black) << "light " << i;
        powered += black ? 0 : 1;
    }
    EXPECT_EQ(leaves, powered);
    EXPECT_EQ(bvh.nodes.size(), std::size_t(2 * powered - 1));
}

// The pmfs sum to 1 less what selection loses at nodes whose children both prove that they cannot
// contribute (their parent's looser bound did not): there it selects nothing, as pbrt-v4 does.
TEST(LightBvh, PmfSumsToAtMostOneAndIsWhatSelectionReports)
{
    const Scene scene = randomLights(11, 200);
    const LightBvh bvh = buildLightBvh(scene);
    Rng rng(pcgHash(5));
    for (int k = 0; k < 200; ++k)
    {
        const vec3 p = uniformIn(rng, -14.0f, 14.0f);
        const vec3 n = k % 4 == 0 ? vec3(0.0f) : randomDirection(rng);
        const bool twoSided = k % 3 == 0;
        double sum = 0.0;
        for (std::uint32_t i = 0; i < scene.lights.size(); ++i)
        {
            const float pmf = pmfOf(bvh, i, p, n, twoSided);
            EXPECT_GE(pmf, 0.0f);
            sum += pmf;
        }
        EXPECT_LE(sum, 1.0 + 1e-4) << "point " << k;
        float pmf = 0.0f;
        const float u = rng.nextFloat();
        const std::uint32_t light = shader::selectLightBvh(bvh.nodes.data(), p, n, twoSided, u, pmf);
        if (light == kNoIndex)
        {
            EXPECT_EQ(pmf, 0.0f);
            EXPECT_LT(sum, 1.0) << "point " << k;
            continue;
        }
        EXPECT_NEAR(pmf, pmfOf(bvh, light, p, n, twoSided), 1e-5f * pmf) << "point " << k;
        EXPECT_GT(pmf, 0.0f);
    }
}

/// The selection chi-square tests' three shading points of randomLights(3, 40) (a medium point, two surfaces), and
/// their significance level (Šidák over the three).
const vec3 kSelectionPoints[] = {vec3(0.0f), vec3(9.0f, -3.0f, 1.0f), vec3(-30.0f, 2.0f, 5.0f)};
const vec3 kSelectionNormals[] = {vec3(0.0f), glm::normalize(vec3(-1.0f, 0.2f, 0.1f)), vec3(1.0f, 0.0f, 0.0f)};
const double kSelectionAlpha = 1.0 - std::pow(1.0 - test::kChiSquareAlpha, 1.0 / 3.0);

/// Expected counts of `selections` descents at selection point `c` per light of `bvh`'s `lights`, by their pmfs,
/// and last the count of descents that select nothing (what the pmfs leave of 1).
std::vector<double> expectedSelections(const LightBvh& bvh, int lights, int c, double selections)
{
    std::vector<double> expected;
    double none = 1.0;
    for (int i = 0; i < lights; ++i)
    {
        const double pmf = pmfOf(bvh, std::uint32_t(i), kSelectionPoints[c], kSelectionNormals[c], false);
        expected.push_back(pmf * selections);
        none -= pmf;
    }
    expected.push_back(std::max(none, 0.0) * selections);
    return expected;
}

TEST(LightBvh, SelectionFollowsThePmf)
{
    const Scene scene = randomLights(3, 40);
    const LightBvh bvh = buildLightBvh(scene);
    const int n = int(scene.lights.size());
    constexpr long kSamples = 400'000;
    for (int c = 0; c < 3; ++c)
    {
        // Cell n: nothing selected.
        const auto h = test::histogram(n + 1, kSamples, 100 + c, [&](Rng& rng) {
            float pmf = 0.0f;
            const auto light = shader::selectLightBvh(bvh.nodes.data(), kSelectionPoints[c], kSelectionNormals[c],
                                                      false, rng.nextFloat(), pmf);
            return light == kNoIndex ? n : int(light);
        });
        const std::vector<double> expected = expectedSelections(bvh, n, c, double(kSamples));
        for (int i = 0; i < n; ++i)
        {
            if (expected[i] == 0.0)
            {
                EXPECT_EQ(h.counts[i], 0.0) << "light " << i << " has pmf 0 and was picked";
            }
        }
        const auto r = test::chiSquareTest(h.counts, expected, kSelectionAlpha);
        EXPECT_TRUE(r.passed) << "configuration " << c << ": " << r.message;
    }
}

// Candidate k's number is uniform on its stratum [k / M, (k + 1) / M) only; the strata's pmfs average to the
// selection's. The candidates of many pixels, pooled, follow the pmf (the strata make the pooled counts less spread
// than independent draws': the test is conservative, not blind to strata that do not average to the pmf).
TEST(LightBvh, StratifiedCandidatesOfManyPixelsFollowThePmf)
{
    const Scene scene = randomLights(3, 40);
    const LightBvh bvh = buildLightBvh(scene);
    const int n = int(scene.lights.size());
    constexpr std::uint32_t kCandidates = 8;
    constexpr long kPixels = 50'000;
    for (int c = 0; c < 3; ++c)
    {
        Rng rng(pcgHash(200 + std::uint32_t(c)));
        std::vector<double> counts(std::size_t(n) + 1, 0.0); // cell n: nothing selected
        for (long pixel = 0; pixel < kPixels; ++pixel)
        {
            const float xi = rng.nextFloat();
            for (std::uint32_t k = 0; k < kCandidates; ++k)
            {
                float pmf = 0.0f;
                const std::uint32_t light =
                    shader::selectLightBvh(bvh.nodes.data(), kSelectionPoints[c], kSelectionNormals[c], false,
                                           shader::stratifiedCandidateNumber(k, kCandidates, xi), pmf);
                counts[light == kNoIndex ? std::size_t(n) : std::size_t(light)] += 1.0;
            }
        }
        const auto r =
            test::chiSquareTest(counts, expectedSelections(bvh, n, c, double(kPixels * kCandidates)), kSelectionAlpha);
        EXPECT_TRUE(r.passed) << "configuration " << c << ": " << r.message;
    }
}

/// A point of light `l` from u, and its unit front normal.
vec3 pointOn(const LightData& l, const vec2& u, vec3& normal)
{
    if (l.shape == LightShape::Sphere)
    {
        normal = shader::sampleUniformSphere(u);
        return l.p0 + l.radius * normal;
    }
    normal = l.normal;
    if (l.shape == LightShape::Quad)
        return l.p0 + u.x * l.p1 + u.y * l.p2;
    const vec2 b = shader::sampleUniformTriangle(u);
    return l.p0 + b.x * l.p1 + b.y * l.p2;
}

TEST(LightBvh, NeverDeniesALightThatCanReachThePoint)
{
    const Scene scene = randomLights(23, 120);
    const LightBvh bvh = buildLightBvh(scene);
    Rng rng(pcgHash(9));
    int reachable = 0;
    for (int k = 0; k < 150; ++k)
    {
        const vec3 p = uniformIn(rng, -12.0f, 12.0f);
        const vec3 n = k % 5 == 0 ? vec3(0.0f) : randomDirection(rng);
        const bool twoSided = k % 2 == 0;
        for (std::uint32_t i = 0; i < scene.lights.size(); ++i)
        {
            if (bvh.leaves[i] == kNoIndex)
                continue;
            const LightData& l = scene.lights[i];
            bool reaches = false;
            for (int s = 0; s < 64 && !reaches; ++s)
            {
                vec3 normal;
                const vec3 y = pointOn(l, test::uniform2(rng), normal);
                const vec3 toLight = y - p;
                const bool aboveHorizon = glm::dot(n, n) == 0.0f || glm::dot(n, toLight) > 0.0f;
                const float emission = glm::dot(normal, -toLight);
                const bool facing = twoSided ? emission != 0.0f : emission > 0.0f;
                reaches = aboveHorizon && facing;
            }
            if (!reaches)
            {
                continue;
            }
            ++reachable;
            EXPECT_GT(pmfOf(bvh, i, p, n, twoSided), 0.0f) << "light " << i << " at point " << k;
        }
    }
    EXPECT_GT(reachable, 1000); // the test saw enough lights that matter
}

TEST(LightBvh, AsksNothingOfAPointNoLightCanReach)
{
    // Two quads facing +z at z = 0 and a receiver below them looking down: nothing reaches it.
    const LightData a = test::makeQuadLight(vec3(-1.0f, -1.0f, 0.0f), vec3(2.0f, 0.0f, 0.0f), vec3(0.0f, 2.0f, 0.0f));
    const LightData b = test::makeQuadLight(vec3(2.0f, -1.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f));
    const Scene scene = sceneOfLights({a, b}, {1.0f, 4.0f});
    const LightBvh bvh = buildLightBvh(scene);
    const vec3 below(0.0f, 0.0f, -3.0f); // outside their bounding spheres (radius 1.41 and 0.71)
    const vec3 above(0.0f, 0.0f, 3.0f);
    const vec3 up(0.0f, 0.0f, 1.0f);
    float pmf = 1.0f;
    EXPECT_EQ(shader::selectLightBvh(bvh.nodes.data(), below, up, false, 0.5f, pmf), kNoIndex);
    EXPECT_EQ(pmf, 0.0f);
    EXPECT_EQ(pmfOf(bvh, 0, below, up, false), 0.0f);
    // Above them, looking up: the horizon hides them. Looking down: both found, the nearer favoured.
    EXPECT_EQ(pmfOf(bvh, 0, above, up, false), 0.0f);
    EXPECT_EQ(pmfOf(bvh, 1, above, up, false), 0.0f);
    const float first = pmfOf(bvh, 0, above, -up, false);
    EXPECT_GT(first, 0.0f);
    EXPECT_NEAR(first + pmfOf(bvh, 1, above, -up, false), 1.0f, 1e-6f);
    // Two-sided, the point below sees them.
    EXPECT_GT(pmfOf(bvh, 0, below, up, true), 0.0f);
}

TEST(LightBvh, SceneWithoutPoweredEmittersSelectsNothing)
{
    const Scene scene = sceneOfLights({test::makeSphereLight(vec3(0.0f), 1.0f)}, {0.0f});
    const LightBvh bvh = buildLightBvh(scene);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.leaves[0], kNoIndex);
    float pmf = 1.0f;
    EXPECT_EQ(shader::selectLightBvh(bvh.nodes.data(), vec3(5.0f), vec3(0.0f), false, 0.3f, pmf), kNoIndex);
    EXPECT_EQ(pmf, 0.0f);
    EXPECT_EQ(pmfOf(bvh, 0, vec3(5.0f), vec3(0.0f), false), 0.0f);
}

TEST(LightBvh, FavoursTheLightsNearAPointInManyLights)
{
    // many-lights: 1000 small emitters in the upper part of the Cornell room. From a point among them, the
    // BVH should give the nearest far more than their share of the count.
    const Scene scene = placedScene("many-lights"); // the point below is in the scene's own coordinates
    const LightBvh bvh = buildLightBvh(scene);
    const std::uint32_t emitters = scene.emitterCount();
    ASSERT_GE(emitters, 1000u);
    const vec3 p(278.0f, 380.0f, 278.0f);
    const vec3 n(0.0f); // in a medium: no horizon
    double sum = 0.0;
    double nearShare = 0.0;
    int nearCount = 0;
    for (std::uint32_t i = 0; i < emitters; ++i)
    {
        const float pmf = pmfOf(bvh, i, p, n, false);
        sum += pmf;
        const LightData& l = scene.lights[i];
        if (glm::length(l.p0 - p) < 80.0f)
        {
            nearShare += pmf;
            ++nearCount;
        }
    }
    EXPECT_LE(sum, 1.0 + 1e-4);
    EXPECT_GT(sum, 0.9); // little is lost to nodes whose children both face away
    ASSERT_GT(nearCount, 0);
    // Their share of the selection against their share of the count.
    EXPECT_GT(nearShare, 2.0 * double(nearCount) / double(emitters)) << nearCount << " lights near";
}
} // namespace
} // namespace rt
