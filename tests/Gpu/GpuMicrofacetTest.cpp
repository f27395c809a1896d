// The GPU's microfacet materials (issue 35). A rough copper and a rough glass sphere under a uniform sky
// against the float64 integral of their BSDFs (Support/MicrofacetSphere.h), as the CPU's MicrofacetSkyFurnace
// renders them. And the chi-square goodness of fit of the GPU's microfacet samplers: Shared/Bsdf/*.h compiled
// as GLSL draws a million directions per configuration through Shaders/Tests/Parity.comp (mode kMicrofacet,
// its uniforms from Shared/Random.h's stream of the case), and the host histograms them against the density
// the C++ compilation of the same header reports, over the cells the C++ tests use
// (Support/MicrofacetCases.h: the directions histogrammed over the microfacet normal that produces them). The
// configurations are the C++ tests': alpha 0.001 to 1, normal and grazing incidence (85 and 89 degrees), for
// the dielectric ior 1.5 and 1 / 1.5 from outside and inside, an anisotropic conductor; the recipe is Mitsuba
// 3's (research notes §2.1, Support/ChiSquare.h): cells below 5 expected samples pooled, alpha = 0.01 with
// Šidák's correction over a test's configurations. Every returned sample must also be finite and unit with a
// positive pdf that the C++ pdf function finds again for its direction (float32 on both sides: 2e-3 relative
// but for at most 10 in a million next to total reflection, 5e-2 always, where a pdf missing a factor is off
// by far more), and the failed samples must be what the pdf leaves out of the sphere.
#include "GpuTestEnvironment.h"
#include "Math/Math.h"
#include "ParityKernel.h"
#include "Shared/Bsdf/Conductor.h"
#include "Shared/Bsdf/GltfPbr.h"
#include "Shared/Bsdf/RoughDielectric.h"
#include "Support/ChiSquare.h"
#include "Support/MicrofacetCases.h"
#include "Support/MicrofacetSphere.h"
#include "Support/PixelStatistics.h"
#include "Support/StatisticsHelpers.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace rt::gpu::test
{
namespace
{
using ::rt::test::DielectricCase;
using ::rt::test::DistributionCase;
using ::rt::test::WarpedDomain;

constexpr long kSamples = 1'000'000;
using ::rt::test::kCopperEta;
using ::rt::test::kCopperK;
const vec3 kBaseColor(0.8f, 0.5f, 0.2f);
constexpr float kMetallic = 0.5f;
constexpr float kF0 = 0.04f;

/// Parity.comp's one input case of kMicrofacet: seed, kind, wo, then the material's words.
std::vector<std::uint32_t> materialInput(std::uint32_t seed, ParityMicrofacetKind kind, const vec3& wo,
                                         float alphaX, float alphaY, float iorOrMetallic)
{
    std::vector<std::uint32_t> in(kParityLayouts[kMicrofacet].inputWords, 0u);
    in[0] = seed;
    in[1] = kind;
    for (int i = 0; i < 3; ++i)
    {
        in[2 + i] = bits(wo[i]);
        in[8 + i] = bits(kind == kParityGltfPbr ? kBaseColor[i] : kCopperEta[i]);
        in[11 + i] = bits(kCopperK[i]);
    }
    in[5] = bits(alphaX);
    in[6] = bits(alphaY);
    in[7] = bits(iorOrMetallic);
    in[14] = bits(kF0);
    return in;
}

/// Histograms the GPU's samples over `domain` against `pdf` (the C++ compilation's) and checks each sample.
void expectGpuSamplesFollowPdf(const std::vector<std::uint32_t>& out, const WarpedDomain& domain, int tests,
                               const std::function<double(const vec3&)>& pdf)
{
    const int words = int(kParityLayouts[kMicrofacet].outputWords);
    std::vector<double> observed(std::size_t(domain.cellCount()), 0.0);
    long failed = 0, invalid = 0, mismatches = 0, gross = 0;
    for (long i = 0; i < kSamples; ++i)
    {
        const std::size_t o = std::size_t(words) * std::size_t(i);
        if (out[o] == 0)
        {
            ++failed;
            observed[std::size_t(domain.otherCell())] += 1.0;
            continue;
        }
        const vec3 wi = vec3At(out, o + 1);
        const float gpuPdf = asFloat(out[o + 4]);
        const vec3 weight = vec3At(out, o + 5);
        if (!isFinite(wi) || !isFinite(weight) || std::fabs(glm::length(wi) - 1.0f) > 1e-5f ||
            !std::isfinite(gpuPdf) || !(gpuPdf > 0.0f))
        {
            if (invalid++ < 3)
                ADD_FAILURE() << "sample " << i << ": wi (" << wi.x << ", " << wi.y << ", " << wi.z
                              << "), pdf " << gpuPdf;
            observed[std::size_t(domain.otherCell())] += 1.0;
            continue;
        }
        observed[std::size_t(domain.cell(dvec3(wi)))] += 1.0;
        const double cpu = pdf(wi);
        const double relative = std::fabs(cpu - gpuPdf) / std::max(cpu, double(gpuPdf));
        if (relative > 2e-3)
            ++mismatches;
        if (relative > 5e-2 && gross++ < 3)
            ADD_FAILURE() << "sample " << i << ": the GPU's pdf " << gpuPdf << ", the C++ pdf function's "
                          << cpu << " at wi (" << wi.x << ", " << wi.y << ", " << wi.z << ")";
    }
    EXPECT_EQ(invalid, 0);
    // Refractions next to total reflection, where the density falls steeply to 0 (pdfs of 1e-5 where the
    // lobe's peak is 1), see the GPU's and the CPU's roundings of the half vector differ by up to a percent:
    // a few in a million. A pdf off everywhere by a factor fails every sample.
    EXPECT_LE(mismatches, 10) << "samples whose pdf differs from the C++ function's by more than 2e-3";
    EXPECT_EQ(gross, 0);
    const std::vector<double> expected =
        domain.expectedCounts([&](const dvec3& d) { return pdf(vec3(d)); }, kSamples);
    const ::rt::test::ChiSquareResult r =
        ::rt::test::chiSquareTest(observed, expected, ::rt::test::kChiSquareAlpha, tests);
    EXPECT_TRUE(r.passed) << r.message << " (" << failed << " samples failed)";
}

TEST(GpuMicrofacetChiSquare, Conductor)
{
    RT_REQUIRE_GPU();
    const auto cases = ::rt::test::conductorCases();
    std::uint32_t seed = 12000;
    for (const DistributionCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        const shader::ConductorParams params{c.alphaX, c.alphaY, false, vec3(0.0f), kCopperEta, kCopperK};
        const auto out =
            runParity(kMicrofacet, materialInput(seed++, kParityConductor, wo, c.alphaX, c.alphaY, 0.0f), {},
                      nullptr, std::uint32_t(kSamples));
        expectGpuSamplesFollowPdf(
            out, ::rt::test::reflectionDomain(c.wo, c.alphaX, c.alphaY), int(cases.size()),
            [&](const vec3& wi) { return double(shader::conductorPdf(params, wo, wi)); });
    }
}

TEST(GpuMicrofacetChiSquare, RoughDielectric)
{
    RT_REQUIRE_GPU();
    const auto cases = ::rt::test::dielectricCases();
    std::uint32_t seed = 13000;
    for (const DielectricCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        const auto out =
            runParity(kMicrofacet, materialInput(seed++, kParityRoughDielectric, wo, c.alpha, c.alpha, c.ior),
                      {}, nullptr, std::uint32_t(kSamples));
        expectGpuSamplesFollowPdf(out, ::rt::test::dielectricDomain(c), int(cases.size()),
                                  [&](const vec3& wi)
                                  { return double(shader::roughDielectricPdf(c.alpha, c.ior, wo, wi)); });
    }
}

TEST(GpuMicrofacetChiSquare, GltfPbr)
{
    RT_REQUIRE_GPU();
    const auto cases = ::rt::test::gltfCases();
    std::uint32_t seed = 14000;
    for (const DistributionCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        const shader::GltfPbrParams params{kBaseColor, kMetallic, c.alphaX, kF0};
        const auto out =
            runParity(kMicrofacet, materialInput(seed++, kParityGltfPbr, wo, c.alphaX, c.alphaX, kMetallic),
                      {}, nullptr, std::uint32_t(kSamples));
        expectGpuSamplesFollowPdf(out, ::rt::test::gltfDomain(c), int(cases.size()),
                                  [&](const vec3& wi) { return double(shader::gltfPbrPdf(params, wo, wi)); });
    }
}
TEST(GpuMicrofacetSkyFurnace, RoughSpheresMatchTheIntegralOfTheBsdf)
{
    RT_REQUIRE_GPU();
    // One case of each material at 60 degrees: each is a pipeline of its own to compile on lavapipe.
    for (const ::rt::test::MicrofacetSphereCase& c : ::rt::test::microfacetSphereCases())
    {
        if (c.thetaDegrees != 60.0 || c.alpha != 0.3f)
            continue;
        SCOPED_TRACE(c.name);
        RenderSettings s;
        s.width = 16;
        s.aspect = 1.0f;
        s.spp = 512;
        s.depth = ::rt::test::microfacetSphereDepth(c);
        s.estimator = Estimator::BsdfOnly;
        s.sampling = PixelSampling::Random; // pixels independent: the patch's mean has a standard error
        s.russianRoulette = RussianRoulette::Off;
        ::rt::test::expectMicrofacetSphere(renderOnGpu(::rt::test::microfacetSphereScene(c), s).image, c);
    }
}
} // namespace
} // namespace rt::gpu::test
