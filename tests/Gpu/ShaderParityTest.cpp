// The GLSL twins of Common's building blocks give the C++ answers: the random streams and the ray offset bit
// for bit (integer arithmetic, no fused multiply-add), the warps, light samplers, Perlin noise and sphere
// roots to a tolerance that allows the GPU's transcendental functions (Vulkan guarantees sin/cos only to
// an absolute 2^-11; real devices do far better).
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestEnvironment.h"
#include "Image/ImageIO.h"
#include "Math/RayOffset.h"
#include "ParityKernel.h"
#include "Random/Pcg.h"
#include "Sampling/LightBvh.h"
#include "Sampling/LightSampling.h"
#include "Sampling/Warps.h"
#include "Scene/Perlin.h"
#include "Scenes/Catalogue.h"
#include "Shared/LightBvh.h"

namespace rt::gpu::test
{
namespace
{
/// Deterministic test inputs in [lo, hi).
std::vector<float> uniforms(std::size_t n, float lo, float hi, std::uint32_t seed)
{
    SceneRandom rnd(seed);
    std::vector<float> v(n);
    for (float& x : v)
        x = rnd.uniform(lo, hi);
    return v;
}

void expectNear(const vec3& gpu, const vec3& cpu, float tolerance, const char* what, std::size_t c)
{
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(gpu[k], cpu[k], tolerance) << what << ", case " << c << ", component " << k;
}

TEST(GpuShaderParity, SobolStreamsAreBitIdentical)
{
    RT_REQUIRE_GPU();
    std::vector<std::uint32_t> in;
    for (std::uint32_t seed : {0u, 0xDEADBEEFu})
        for (std::uint32_t pixel : {0u, 12345u, 0xFFFFFFFFu})
            for (std::uint32_t sample : {0u, 1u, 7u, 100000u, 0xFFFFFFFFu})
                in.insert(in.end(), {seed, pixel, sample});
    const std::vector<std::uint32_t> out = runParity(kSobol, in);
    for (std::size_t c = 0; c < in.size() / 3; ++c)
    {
        Rng rng = Rng::forSobolSample(in[3 * c], in[3 * c + 1], in[3 * c + 2]);
        for (std::size_t k = 0; k < 8; k += 2)
        {
            const vec2 u = rng.next2D();
            EXPECT_EQ(out[8 * c + k], bits(u.x)) << "case " << c << ", draw " << k / 2;
            EXPECT_EQ(out[8 * c + k + 1], bits(u.y)) << "case " << c << ", draw " << k / 2;
        }
    }
}

TEST(GpuShaderParity, RandomStreamsAreBitIdentical)
{
    RT_REQUIRE_GPU();
    std::vector<std::uint32_t> in;
    for (std::uint32_t seed : {0u, 1u, 0xDEADBEEFu})
        for (std::uint32_t pixel : {0u, 1u, 12345u, 0xFFFFFFFFu})
            for (std::uint32_t sample : {0u, 7u, 100000u})
                in.insert(in.end(), {seed, pixel, sample});
    const std::vector<std::uint32_t> out = runParity(kRandom, in);
    for (std::size_t c = 0; c < in.size() / 3; ++c)
    {
        Rng rng = Rng::forSample(in[3 * c], in[3 * c + 1], in[3 * c + 2]);
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(out[8 * c + k], rng.nextUint()) << "case " << c << ", nextUint " << k;
        for (int k = 4; k < 8; ++k)
            EXPECT_EQ(out[8 * c + k], bits(rng.nextFloat())) << "case " << c << ", nextFloat " << k;
    }
}

TEST(GpuShaderParity, RayOffsetIsBitIdentical)
{
    RT_REQUIRE_GPU();
    std::vector<std::uint32_t> in;
    const std::vector<float> scales = {1e-6f, 1e-3f, 0.02f, 1.0f, 555.0f, 1e4f, 1e6f};
    const std::vector<float> r = uniforms(6 * 64, -1.0f, 1.0f, 7u);
    for (std::size_t c = 0; c < 64; ++c)
    {
        const float scale = scales[c % scales.size()];
        const vec3 p = scale * vec3(r[6 * c], r[6 * c + 1], r[6 * c + 2]);
        const vec3 n = glm::normalize(vec3(r[6 * c + 3], r[6 * c + 4], r[6 * c + 5]) + vec3(1e-3f));
        const float offsetScale = scales[(c / scales.size()) % scales.size()]; // below 1 counts as 1
        in.insert(in.end(), {bits(p.x), bits(p.y), bits(p.z), bits(n.x), bits(n.y), bits(n.z), bits(offsetScale)});
    }
    const std::vector<std::uint32_t> out = runParity(kRayOffset, in);
    for (std::size_t c = 0; c < 64; ++c)
    {
        const vec3 expected = offsetRayOrigin(vec3At(in, 7 * c), vec3At(in, 7 * c + 3), asFloat(in[7 * c + 6]));
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(out[3 * c + k], bits(expected[k])) << "case " << c << ", component " << k;
    }
}

TEST(GpuShaderParity, WarpsMatchCommon)
{
    RT_REQUIRE_GPU();
    const std::vector<float> r = uniforms(3 * 256, 0.0f, 1.0f, 11u);
    std::vector<std::uint32_t> in;
    for (std::size_t c = 0; c < 256; ++c)
        in.insert(in.end(), {bits(r[3 * c]), bits(r[3 * c + 1]), bits(1e-4f + r[3 * c + 2])});
    const std::vector<std::uint32_t> out = runParity(kWarps, in);
    constexpr float kTolerance = 2e-5f;
    for (std::size_t c = 0; c < 256; ++c)
    {
        const vec2 u(asFloat(in[3 * c]), asFloat(in[3 * c + 1]));
        const std::uint32_t* o = &out[13 * c];
        expectNear(vec3At(out, 13 * c), sampleCosineHemisphere(u), kTolerance, "cosine hemisphere", c);
        expectNear(vec3At(out, 13 * c + 3), sampleUniformSphere(u), kTolerance, "uniform sphere", c);
        expectNear(vec3At(out, 13 * c + 6), sampleUniformCone(u, asFloat(in[3 * c + 2])), kTolerance, "cone", c);
        const vec2 disk = sampleUniformDiskConcentric(u);
        EXPECT_NEAR(asFloat(o[9]), disk.x, kTolerance) << "disk, case " << c;
        EXPECT_NEAR(asFloat(o[10]), disk.y, kTolerance) << "disk, case " << c;
        const vec2 triangle = sampleUniformTriangle(u);
        EXPECT_NEAR(asFloat(o[11]), triangle.x, kTolerance) << "triangle, case " << c;
        EXPECT_NEAR(asFloat(o[12]), triangle.y, kTolerance) << "triangle, case " << c;
    }
}


TEST(GpuShaderParity, LightSamplersMatchCommon)
{
    // Book 3's samplers and NEE's three, each with a receiver normal (up: the lights are overhead; sideways:
    // the projected samplers' horizon cuts them): the GPU's compilation of Shared/LightSampling.h must give the
    // C++ samples and pdfs to float tolerance, and NEE's samples the same outcome bits (fallback, declined).
    // Triangles under SolidAngle and Projected take Arvo's map, in float on the GPU and in double on the CPU: a
    // ceiling triangle of 2500 units^2, triangle-lights' 300 x 3 sliver on the back wall, and a 6 x 6 triangle on
    // the ceiling (from 3e-3 sr down to below the 3e-4 sr where area sampling takes over).
    RT_REQUIRE_GPU();
    std::vector<LightData> lights;
    lights.push_back(makeQuadLight({213, 554, 227}, {130, 0, 0}, {0, 0, 105}, 0)); // a rectangle
    lights.push_back(makeTriangleLight({0, 500, 0}, {100, 500, 0}, {0, 500, 50}, 0));
    lights.push_back(makeSphereLight({277, 530, 277}, 50.0f, 0));
    lights.push_back(makeTriangleLight({428, 400, 554}, {128, 400, 554}, {278, 403, 554}, 0));
    lights.push_back(makeTriangleLight({270, 554, 270}, {276, 554, 270}, {270, 554, 276}, 0));
    const std::uint32_t strategies[] = {kNoIndex, std::uint32_t(LightSampler::Area),
                                        std::uint32_t(LightSampler::SolidAngle), std::uint32_t(LightSampler::Projected)};
    constexpr std::size_t kCases = 4 * 320;
    const std::vector<float> r = uniforms(5 * kCases, 0.0f, 1.0f, 5u);
    std::vector<std::uint32_t> in;
    for (std::size_t c = 0; c < kCases; ++c)
    {
        // Points in the Cornell box, some inside the sphere light (its uniform-area branch).
        vec3 p = vec3(555.0f * r[5 * c], 480.0f * r[5 * c + 1], 555.0f * r[5 * c + 2]);
        if (c % 8 == 0)
            p = lights[2].p0 + vec3(10.0f * r[5 * c], -20.0f * r[5 * c + 1], 5.0f);
        const vec3 n = c % 3 == 0 ? glm::normalize(vec3(1.0f, 0.3f, 0.2f)) : vec3(0.0f, 1.0f, 0.0f);
        in.insert(in.end(), {std::uint32_t(c % 5), bits(p.x), bits(p.y), bits(p.z), bits(r[5 * c + 3]),
                             bits(r[5 * c + 4]), strategies[(c / 5) % 4], bits(n.x), bits(n.y), bits(n.z)});
    }
    const std::vector<std::uint32_t> out = runParity(kLightSampling, in, lights);
    int compared = 0, outcomes = 0, fallbacks = 0;
    for (std::size_t c = 0; c < kCases; ++c)
    {
        const std::uint32_t* k = &in[10 * c];
        const LightData& light = lights[k[0]];
        const vec3 p = vec3At(in, 10 * c + 1);
        const vec2 u(asFloat(k[4]), asFloat(k[5]));
        const vec3 n = vec3At(in, 10 * c + 7);
        const bool book3 = k[6] == kNoIndex;
        const auto strategy = LightSampler(k[6]);
        LightSample ls;
        const bool ok = book3 ? sampleLight(light, p, u, ls) : sampleLight(light, strategy, p, n, u, ls);
        const std::uint32_t* o = &out[kParityLayouts[kLightSampling].outputWords * c];
        ASSERT_EQ(o[0] != 0, ok) << "case " << c;
        // How NEE's sample was made (fallback, declined), which --stats counts on either engine.
        if (!book3)
        {
            EXPECT_EQ(o[6], ls.outcome) << "outcome, case " << c;
        }
        outcomes += !book3;
        fallbacks += !book3 && (ls.outcome & shader::kLightSampleFallback) != 0;
        if (!ok)
            continue;
        ++compared;
        // 1e-4 in direction, 1e-3 in pdf for every sampler: the spherical rectangle's solid angle (four angles
        // minus 2 pi) cancels, and with GLSL's acos (Vulkan: 4096 ulp) lavapipe's pdfs were 2e-3 off until
        // Shared/SphericalRectangle.h took its own (preciseAcos).
        const float wiTolerance = 1e-4f;
        const float pdfTolerance = 1e-3f;
        expectNear(vec3(asFloat(o[1]), asFloat(o[2]), asFloat(o[3])), ls.wi, wiTolerance, "wi", c);
        EXPECT_NEAR(asFloat(o[4]), ls.pdf, pdfTolerance * ls.pdf) << "pdf, case " << c;
        const float pdfOfWi = book3 ? lightPdf(light, p, ls.wi) : lightPdf(light, strategy, p, n, ls.wi);
        EXPECT_NEAR(asFloat(o[5]), pdfOfWi, pdfTolerance * pdfOfWi + 1e-6f) << "lightPdf, case " << c;
    }
    EXPECT_GT(compared, int(kCases) / 2);
    EXPECT_GT(fallbacks, outcomes / 20) << "the small triangle's fallbacks: too few to compare";
}

TEST(GpuShaderParity, LightBvhSelectionMatchesCommon)
{
    // many-lights' light BVH (1012 emitters) descended from points of the room with and without a receiver
    // normal: the GPU's compilation of Shared/LightBvh.h selects the light C++ selects, with its pmf.
    RT_REQUIRE_GPU();
    const Scene scene = makeScene("many-lights");
    const LightBvh bvh = buildLightBvh(scene);
    constexpr std::size_t kCases = 2048;
    const std::vector<float> r = uniforms(6 * kCases, 0.0f, 1.0f, 11u);
    std::vector<std::uint32_t> in;
    for (std::size_t c = 0; c < kCases; ++c)
    {
        const vec3 p(555.0f * r[6 * c], 555.0f * r[6 * c + 1], 555.0f * r[6 * c + 2]);
        const vec3 n = c % 4 == 0 ? vec3(0.0f) : shader::sampleUniformSphere({r[6 * c + 3], r[6 * c + 4]});
        in.insert(in.end(), {bits(p.x), bits(p.y), bits(p.z), bits(n.x), bits(n.y), bits(n.z),
                             std::uint32_t(c % 3 == 0), bits(r[6 * c + 5])});
    }
    const std::vector<std::uint32_t> out = runParity(kLightBvh, in, scene.lights, &bvh);
    int differentLight = 0;
    int selected = 0;
    for (std::size_t c = 0; c < kCases; ++c)
    {
        const vec3 p = vec3At(in, 8 * c);
        const vec3 n = vec3At(in, 8 * c + 3);
        const bool twoSided = in[8 * c + 6] != 0;
        float pmf = 0.0f;
        const std::uint32_t light =
            shader::selectLightBvh(bvh.nodes.data(), p, n, twoSided, asFloat(in[8 * c + 7]), pmf);
        if (out[3 * c] != light)
        {
            // u on a boundary between two children, which rounding moves: rare.
            ++differentLight;
            continue;
        }
        EXPECT_NEAR(asFloat(out[3 * c + 1]), pmf, 1e-4f * pmf) << "case " << c;
        if (light == kNoIndex)
            continue;
        ++selected;
        const float pmfOfLight = shader::lightBvhPmf(bvh.nodes.data(), bvh.leaves.data(), light, p, n, twoSided);
        EXPECT_NEAR(asFloat(out[3 * c + 2]), pmfOfLight, 1e-4f * pmfOfLight) << "case " << c;
    }
    EXPECT_LE(differentLight, int(kCases) / 200);
    EXPECT_GT(selected, int(kCases) / 2);
}

TEST(GpuShaderParity, PerlinNoiseMatchesCommon)
{
    RT_REQUIRE_GPU();
    const std::vector<float> r = uniforms(3 * 256, -300.0f, 300.0f, 3u);
    std::vector<std::uint32_t> in;
    for (float x : r)
        in.push_back(bits(x));
    const std::vector<std::uint32_t> out = runParity(kPerlin, in);
    for (std::size_t c = 0; c < 256; ++c)
    {
        const vec3 p = vec3At(in, 3 * c);
        EXPECT_NEAR(asFloat(out[2 * c]), perlinNoise(perlinTables(), p), 1e-5f) << "case " << c;
        EXPECT_NEAR(asFloat(out[2 * c + 1]), perlinTurbulence(perlinTables(), p, 7), 1e-5f) << "case " << c;
    }
}

TEST(GpuShaderParity, SrgbDecodeMatchesCommon)
{
    RT_REQUIRE_GPU();
    std::vector<std::uint32_t> in(256);
    for (std::uint32_t code = 0; code < 256; ++code)
        in[code] = code;
    const std::vector<std::uint32_t> out = runParity(kSrgb, in);
    for (std::uint32_t code = 0; code < 256; ++code)
    {
        const float cpu = srgb8ToLinear(static_cast<unsigned char>(code));
        // GLSL's pow is exp2(y log2 x) within Vulkan's precision rules, a few ulps from std::pow at most
        // (lavapipe and NVIDIA: within 1e-6); the engines' agreement tests allow 1e-5 relative.
        EXPECT_NEAR(asFloat(out[code]), cpu, 4e-6f * cpu + 1e-9f) << "code " << code;
    }
}

TEST(GpuShaderParity, SphereRootsFindTheFarRootFromInside)
{
    RT_REQUIRE_GPU();
    struct Case
    {
        vec3 o, d, center;
        float radius;
        bool hit;
        float t0, t1;
    };
    const std::vector<Case> cases = {
        {{0, 0, 0}, {0, 0, -1}, {0, 0, -5}, 1.0f, true, 4.0f, 6.0f},
        {{0, 0, -5}, {0, 0, -2}, {0, 0, -5}, 1.0f, true, -0.5f, 0.5f}, // inside: far root 0.5
        {{0, 2, 0}, {0, 0, -1}, {0, 0, -5}, 1.0f, false, 0.0f, 0.0f},
        {{278, 278, -800}, {0, 0, 1}, {278, 278, 400}, 1e-2f, true, 1200.0f - 1e-2f, 1200.0f + 1e-2f},
        {{0, 1.5f, 0}, {0, -1, 0}, {0, -1000, 0}, 1000.0f, true, 1.5f, 2001.5f},
    };
    std::vector<std::uint32_t> in;
    for (const Case& c : cases)
        in.insert(in.end(), {bits(c.o.x), bits(c.o.y), bits(c.o.z), bits(c.d.x), bits(c.d.y), bits(c.d.z),
                             bits(c.center.x), bits(c.center.y), bits(c.center.z), bits(c.radius)});
    const std::vector<std::uint32_t> out = runParity(kSphere, in);
    for (std::size_t i = 0; i < cases.size(); ++i)
    {
        ASSERT_EQ(out[3 * i] != 0, cases[i].hit) << "case " << i;
        if (!cases[i].hit)
            continue;
        EXPECT_NEAR(asFloat(out[3 * i + 1]), cases[i].t0, 1e-3f) << "case " << i;
        EXPECT_NEAR(asFloat(out[3 * i + 2]), cases[i].t1, 1e-3f) << "case " << i;
    }
}
} // namespace
} // namespace rt::gpu::test
