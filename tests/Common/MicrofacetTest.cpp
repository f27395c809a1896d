// The microfacet BSDFs of Shared/ (Microfacet.h, Fresnel.h, Bsdf/*.h), as research notes §2 asks of every
// sampler: chi-square of each sampling routine against its own pdf function (§2.1), every sample's record
// against the functions (§2.3), the densities' integrals (§2.2), and physics the formulas must obey whatever
// the sampling: GGX's normalisation (Heitz 2014), reciprocity, energy conservation and the single-scattering
// albedo of a white conductor against a float64 integral of the textbook formula and against Cycles'
// published table. The references here are written from the papers in double, never from the headers.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "Math/Math.h"
#include "Random/Pcg.h"
#include "Shared/Bsdf/Conductor.h"
#include "Shared/Bsdf/GltfPbr.h"
#include "Shared/Bsdf/RoughDielectric.h"
#include "Shared/Fresnel.h"
#include "Shared/Microfacet.h"
#include "Support/ChiSquare.h"
#include "Support/LobeDomain.h"
#include "Support/MicrofacetCases.h"
#include "Support/MicrofacetReferences.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using shader::BsdfSample;
using shader::ConductorParams;
using shader::GltfPbrParams;
using test::chiSquareTest;
using test::kChiSquareAlpha;
using test::LobeCap;
using test::LobeDomain;
using test::Side;
using test::conductorCases;
using test::dielectricCases;
using test::dielectricDomain;
using test::direction;
using test::DielectricCase;
using test::distributionCases;
using test::DistributionCase;
using test::gltfCases;
using test::gltfDomain;
using test::normalCells;
using test::reflectionDomain;
using test::fresnelRef;
using test::g1Ref;
using test::g2Ref;
using test::ggxAlbedoRef;
using test::lambdaRef;

constexpr long kSamples = 1'000'000;
constexpr double kPiD = 3.14159265358979323846;

std::string str(const dvec3& v)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}


bool closeRelative(double a, double b, double relative, double absolute = 0.0)
{
    return std::fabs(a - b) <= relative * std::max(std::fabs(a), std::fabs(b)) + absolute;
}

// ---- Sampling harness -------------------------------------------------------------------------------------

/// Counts the samples that break an invariant and keeps the first one's description.
class SampleAudit
{
public:
    template <class Describe>
    void require(bool ok, Describe&& describe)
    {
        if (!ok && m_bad++ == 0)
            m_first = describe();
    }
    long bad() const { return m_bad; }
    const std::string& first() const { return m_first; }

private:
    long m_bad = 0;
    std::string m_first;
};

/// The invariants of every returned record: finite, unit, pdf > 0 and what the pdf function says (1e-3: the
/// same float function of the same direction; the margin only admits a refactor's reordering), weight =
/// eval / pdf per channel (1e-3, likewise).
void auditRecord(SampleAudit& audit, const BsdfSample& s, double pdfFunction, const vec3& eval)
{
    const dvec3 wi(s.wi);
    audit.require(isFinite(s.wi) && isFinite(s.weight) && std::isfinite(s.pdf),
                  [&] { return "non-finite record, wi = " + str(wi); });
    audit.require(std::fabs(glm::length(wi) - 1.0) < 1e-5, [&] { return "wi not unit: " + str(wi); });
    audit.require(s.pdf > 0.0f, [&] { return "pdf " + std::to_string(s.pdf) + " at wi = " + str(wi); });
    audit.require(closeRelative(s.pdf, pdfFunction, 1e-3), [&] {
        return "record pdf " + std::to_string(s.pdf) + " but pdf function " + std::to_string(pdfFunction) +
               " at wi = " + str(wi);
    });
    for (int c = 0; c < 3; ++c)
        audit.require(closeRelative(s.weight[c], double(eval[c]) / double(s.pdf), 1e-3, 1e-7), [&] {
            return "weight " + std::to_string(s.weight[c]) + " but eval / pdf " +
                   std::to_string(double(eval[c]) / double(s.pdf)) + " at wi = " + str(wi);
        });
}

/// What a sampler's run over a domain found.
struct SamplerRun
{
    test::ChiSquareResult chiSquare;
    double pdfIntegral; // over the domain's cells: the sphere wherever the pdf is not 0
    double failed;      // fraction of samples that returned false
};

/// kSamples draws of `sample` (false: a failed sample, counted in the domain's other cell) histogrammed over
/// `domain`, against `pdf`; `tests` configurations share the significance level (Šidák).
template <class Domain>
SamplerRun runSampler(const Domain& domain, std::uint32_t seed, int tests,
                      const std::function<bool(Rng&, dvec3&)>& sample,
                      const std::function<double(const dvec3&)>& pdf)
{
    long failed = 0;
    const auto h = test::histogram(domain.cellCount(), kSamples, seed, [&](Rng& rng) {
        dvec3 d;
        if (sample(rng, d))
            return domain.cell(d);
        ++failed;
        return domain.otherCell();
    });
    const std::vector<double> expected = domain.expectedCounts(pdf, kSamples);
    double inCells = 0.0;
    for (std::size_t i = 0; i + 1 < expected.size(); ++i)
        inCells += expected[i];
    return {chiSquareTest(h.counts, expected, kChiSquareAlpha, tests), inCells / double(kSamples),
            double(failed) / double(kSamples)};
}

/// The chi-square, and the pdf's integral over the sphere: at most 1, and what the sampler does not lose, 1 -
/// the fraction of failed samples, within 4 binomial standard errors of that fraction plus 5e-5 (the
/// quadrature's error is below 1e-7; the float pdf's rounding and the slivers where a crease crosses a radial
/// line twice within a row stay below 1e-5).
void expectSamplerMatchesPdf(const SamplerRun& r)
{
    EXPECT_TRUE(r.chiSquare.passed) << r.chiSquare.message;
    const double f = r.failed;
    const double tolerance =
        4.0 * std::sqrt(std::max(f * (1.0 - f), 1.0 / kSamples) / double(kSamples)) + 5e-5;
    EXPECT_LE(r.pdfIntegral, 1.0 + 5e-5);
    EXPECT_NEAR(r.pdfIntegral, 1.0 - f, tolerance) << f << " of the samples failed";
}


// ---- Fresnel ----------------------------------------------------------------------------------------------

// Complex indices of refraction of the size renderers use for these metals at red, green and blue (after
// Johnson & Christy 1972 and Rakić 1995, rounded). Only the code's agreement with the Fresnel equations is
// tested, so their exact values do not matter; k from 1.6 to 9.2 spans the closed form's cancellations.
struct Metal
{
    const char* name;
    vec3 eta, k;
};
const Metal kMetals[] = {
    {"gold", {0.143f, 0.374f, 1.442f}, {3.983f, 2.385f, 1.603f}},
    {"copper", test::kCopperEta, test::kCopperK},
    {"aluminium", {1.657f, 0.880f, 0.521f}, {9.224f, 6.270f, 4.837f}},
};
const std::vector<float> kCosines = {1.0f, 0.95f, 0.8f, 0.5f, 0.3f, 0.1f, 0.02f, 0.0f};

TEST(Fresnel, ConductorMatchesTheComplexFresnelEquations)
{
    // 1e-5: the closed form in float loses a few ulps of its largest terms (k^2 = 85 for aluminium) where it
    // subtracts them; a wrong sign or a swapped polarisation is off by 1e-2 or more.
    for (const Metal& m : kMetals)
        for (float c : kCosines)
        {
            const vec3 rgb = shader::fresnelConductorRgb(c, m.eta, m.k);
            for (int ch = 0; ch < 3; ++ch)
            {
                const double expected = fresnelRef(c, {double(m.eta[ch]), double(m.k[ch])});
                EXPECT_NEAR(shader::fresnelConductor(c, m.eta[ch], m.k[ch]), expected, 1e-5)
                    << m.name << ", channel " << ch << ", cos " << c;
                EXPECT_EQ(rgb[ch], shader::fresnelConductor(c, m.eta[ch], m.k[ch]));
            }
        }
    // k = 0 is a dielectric: the conductor's form must agree with the real one, total reflection included.
    for (float eta : {1.5f, 1.0f / 1.5f, 2.4f})
        for (float c : kCosines)
            EXPECT_NEAR(shader::fresnelConductor(c, eta, 0.0f), fresnelRef(c, {double(eta), 0.0}), 1e-5)
                << "eta " << eta << ", cos " << c;
}

TEST(Fresnel, DielectricMatchesTheFresnelEquations)
{
    // etaRatio = eta_i / eta_t: the far side's relative index is its inverse. 1e-6: float rounding of
    // terms at most 1.
    for (float etaRatio : {1.0f / 1.5f, 1.5f, 1.0f / 1.33f, 1.0f / 2.4f, 1.2f})
        for (float c : kCosines)
            EXPECT_NEAR(shader::fresnelDielectric(c, etaRatio), fresnelRef(c, {1.0 / double(etaRatio), 0.0}),
                        1e-6)
                << "etaRatio " << etaRatio << ", cos " << c;
}

TEST(Fresnel, DielectricIsZeroAtEqualIndicesAndOneUnderTotalReflection)
{
    for (float c : kCosines)
    {
        if (c > 0.0f)
        {
            EXPECT_NEAR(shader::fresnelDielectric(c, 1.0f), 0.0f, 1e-7f) << "cos " << c;
        }
    }
    // From glass (1.5) the critical cosine is sqrt(1 - 1/1.5^2) = 0.745: below it, exactly 1.
    for (float c : {0.74f, 0.5f, 0.1f, 0.0f})
        EXPECT_EQ(shader::fresnelDielectric(c, 1.5f), 1.0f) << "cos " << c;
    // Normal incidence: ((1 - 1.5) / (1 + 1.5))^2 = 0.04 from either side.
    EXPECT_NEAR(shader::fresnelDielectric(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(shader::fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);
}

TEST(Fresnel, SchlickMeetsItsEndpoints)
{
    // Schlick 1994: F0 at normal incidence, 1 at grazing, and F0 + (1 - F0)(1 - cos)^5 between.
    const vec3 f0(0.9f, 0.5f, 0.04f);
    EXPECT_EQ(shader::schlickFresnel(f0, 1.0f), f0);
    EXPECT_EQ(shader::schlickFresnel(f0, 0.0f), vec3(1.0f));
    const vec3 mid = shader::schlickFresnel(f0, 0.5f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(mid[c], f0[c] + (1.0 - f0[c]) / 32.0, 1e-6);
    EXPECT_NEAR(shader::schlickReflectance(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(shader::schlickReflectance(0.0f, 1.0f / 1.5f), 1.0f, 1e-6f);
}

// ---- GGX normalisation (deterministic quadrature) ---------------------------------------------------------

/// Integral of g(wm) over the hemisphere of normals, in GGX's own coordinates: stretched slopes
/// (x, y) = (-wm.x / (alphaX wm.z), -wm.y / (alphaY wm.z)) in polar form (rho, phi), then
/// rho^2 / (1 + rho^2) = 1 - (1 - p)^2. There d omega = cos^3 alphaX alphaY rho d rho d phi
/// = cos^3 alphaX alphaY dp dphi / (1 - p)^3: D's projected area is (1 - p) / pi per dp dphi however small
/// alpha is, and a visible normal's slope (~ 1 / (1 - p)) times dp stays bounded, so the midpoint rule
/// converges at every roughness. g gets the float normal the headers take.
double integrateOverNormals(float alphaX, float alphaY, const std::function<double(const vec3&)>& g,
                            int n = 800)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double p = (i + 0.5) / n;
        const double rho = std::sqrt(p * (2.0 - p)) / (1.0 - p);
        for (int j = 0; j < n; ++j)
        {
            const double phi = 2.0 * kPiD * (j + 0.5) / n;
            const dvec3 m =
                glm::normalize(dvec3(-alphaX * rho * std::cos(phi), -alphaY * rho * std::sin(phi), 1.0));
            const double jacobian = m.z * m.z * m.z * double(alphaX) * double(alphaY) / std::pow(1.0 - p, 3);
            sum += g(vec3(m)) * jacobian;
        }
    }
    return sum * (1.0 / n) * (2.0 * kPiD / n);
}

TEST(GgxDistribution, ProjectedAreaIsOne)
{
    // 1e-5: the integrand is (1 - p) / pi in these coordinates (exact for the midpoint rule) up to D's float
    // rounding; a missing pi or alpha, or D squared wrongly, is off by far more.
    for (const auto& c : distributionCases(89.0, 89.0))
    {
        if (c.wo.z != 1.0)
            continue; // one case per roughness
        const double area = integrateOverNormals(c.alphaX, c.alphaY, [&](const vec3& m) {
            return double(shader::ggxD(m, c.alphaX, c.alphaY)) * m.z;
        });
        EXPECT_NEAR(area, 1.0, 1e-5) << c.name;
    }
}

TEST(GgxDistribution, VisibleProjectedAreaIsTheViewCosine)
{
    // Heitz 2014 §2.2: the visible microsurface projects onto the view as the geometric surface does,
    // integral of G1(wo) max(0, wo.wm) D(wm) = wo.z (GgxVisibleNormals.ChiSquare integrates the pdf). 1e-4
    // relative: max(0, .) kinks the integrand along a curve, which the 800^2 midpoint grid resolves to about
    // 1e-6; a Lambda off by a constant factor misses by 1e-2 at 60 degrees for alpha 0.1.
    std::vector<DistributionCase> cases = distributionCases(89.0, 89.0);
    for (const auto& base : distributionCases(89.0, 89.0))
        for (double theta : {30.0, 60.0, 80.0})
            if (base.wo.z == 1.0)
                cases.push_back({base.name + " at theta_o " + std::to_string(theta), base.alphaX, base.alphaY,
                                 direction(theta)});
    for (const auto& c : cases)
    {
        const vec3 wo(c.wo);
        const double visible = integrateOverNormals(c.alphaX, c.alphaY, [&](const vec3& m) {
            return double(shader::ggxG1(wo, c.alphaX, c.alphaY)) *
                   std::max(0.0, glm::dot(dvec3(wo), dvec3(m))) * double(shader::ggxD(m, c.alphaX, c.alphaY));
        });
        EXPECT_NEAR(visible / c.wo.z, 1.0, 1e-4) << c.name;
    }
}

TEST(GgxDistribution, MaskingMatchesTheReference)
{
    // Lambda, G1 and G2 against Heitz's formulas in double, over directions down to 1 degree above the plane;
    // 1e-5 relative: float rounding of sqrt(1 + a^2 tan^2).
    for (const auto& c : distributionCases(89.0, 89.0))
        for (double theta : {0.0, 20.0, 45.0, 70.0, 85.0, 89.0})
            for (double phi : {0.0, 30.0, 90.0, 200.0})
            {
                const dvec3 w = direction(theta, phi), v = direction(60.0, phi + 100.0);
                EXPECT_NEAR(shader::ggxG1(vec3(w), c.alphaX, c.alphaY), g1Ref(w, c.alphaX, c.alphaY),
                            1e-5 * g1Ref(w, c.alphaX, c.alphaY))
                    << c.name << ", w = " << str(w);
                EXPECT_NEAR(shader::ggxG2(vec3(w), vec3(v), c.alphaX, c.alphaY),
                            g2Ref(w, v, c.alphaX, c.alphaY), 1e-5 * g2Ref(w, v, c.alphaX, c.alphaY))
                    << c.name << ", w = " << str(w);
            }
}

// ---- GGX visible normals ----------------------------------------------------------------------------------

/// Cells over wm about the visible normals' axis, the plane wo.wm = 0 that cuts them (1 degree from +z at 89
/// degrees) a crease.
LobeDomain visibleNormalDomain(const DistributionCase& c)
{
    const dvec3 wo = c.wo;
    return normalCells(wo, c.alphaX, c.alphaY, {[wo](const dvec3& m) { return glm::dot(wo, m); }});
}

TEST(GgxVisibleNormals, ChiSquare)
{
    // Every roughness gets a resolved lobe; grazing at 89 degrees, the visible normals lean towards wo and
    // are cut by wo.wm = 0, 1 degree from +z.
    const auto cases = distributionCases(89.0, 89.0);
    std::uint32_t seed = 100;
    for (const auto& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        const LobeDomain domain = visibleNormalDomain(c);
        SampleAudit audit;
        const SamplerRun r = runSampler(
            domain, seed++, int(cases.size()),
            [&](Rng& rng, dvec3& d) {
                const vec3 m = shader::sampleGgxVisibleNormal(wo, c.alphaX, c.alphaY, test::uniform2(rng));
                d = dvec3(m);
                audit.require(isFinite(m) && std::fabs(glm::length(d) - 1.0) < 1e-5 && m.z >= 0.0f,
                              [&] { return "normal not unit or below the plane: " + str(d); });
                audit.require(shader::ggxVisibleNormalPdf(wo, m, c.alphaX, c.alphaY) > 0.0f,
                              [&] { return "pdf 0 at a sampled normal " + str(d); });
                return true;
            },
            [&](const dvec3& m) {
                return double(shader::ggxVisibleNormalPdf(wo, vec3(m), c.alphaX, c.alphaY));
            });
        expectSamplerMatchesPdf(r);
        EXPECT_EQ(audit.bad(), 0) << audit.first();
    }
}

// ---- Rough conductor --------------------------------------------------------------------------------------

ConductorParams goldConductor(float alphaX, float alphaY)
{
    return {alphaX, alphaY, false, vec3(0.0f), kMetals[0].eta, kMetals[0].k};
}


/// Every record of sampleConductor: the common invariants, wi above the surface, and the weight the VNDF
/// sampling must give, F(wo.wm) G2 / G1(wo) (Heitz 2018), G from the double references (F from the header's
/// fresnelConductorRgb, which Fresnel.* holds to the complex Fresnel equations).
void auditConductorRecord(SampleAudit& audit, const ConductorParams& c, const vec3& wo, const BsdfSample& s)
{
    auditRecord(audit, s, shader::conductorPdf(c, wo, s.wi), shader::evalConductor(c, wo, s.wi));
    const dvec3 o(wo), i(s.wi);
    audit.require(s.wi.z > 0.0f, [&] { return "wi below the surface: " + str(i); });
    const dvec3 m = glm::normalize(o + i);
    const double ratio = g2Ref(o, i, c.alphaX, c.alphaY) / g1Ref(o, c.alphaX, c.alphaY);
    const vec3 fresnel = c.schlick ? shader::schlickFresnel(c.f0, float(glm::dot(o, m)))
                                   : shader::fresnelConductorRgb(float(glm::dot(o, m)), c.eta, c.k);
    for (int ch = 0; ch < 3; ++ch)
    {
        const double f = fresnel[ch];
        // 1e-3: float G and F against double; a pdf missing its 4 (wo.wm) is off by far more.
        audit.require(closeRelative(s.weight[ch], f * ratio, 1e-3, 1e-6), [&] {
            return "weight " + std::to_string(s.weight[ch]) +
                   " but F G2 / G1 = " + std::to_string(f * ratio) + " at wi = " + str(i);
        });
    }
}

TEST(ConductorBsdf, ChiSquare)
{
    const auto cases = conductorCases();
    std::uint32_t seed = 200;
    for (const auto& cc : cases)
    {
        SCOPED_TRACE(cc.name);
        const ConductorParams c = goldConductor(cc.alphaX, cc.alphaY);
        const vec3 wo(cc.wo);
        const auto domain = reflectionDomain(cc.wo, cc.alphaX, cc.alphaY);
        SampleAudit audit;
        const SamplerRun r = runSampler(
            domain, seed++, int(cases.size()),
            [&](Rng& rng, dvec3& d) {
                BsdfSample s;
                if (!shader::sampleConductor(c, wo, test::uniform2(rng), s))
                    return false;
                auditConductorRecord(audit, c, wo, s);
                d = dvec3(s.wi);
                return true;
            },
            [&](const dvec3& d) { return double(shader::conductorPdf(c, wo, vec3(d))); });
        expectSamplerMatchesPdf(r);
        EXPECT_EQ(audit.bad(), 0) << audit.first();
    }
}

TEST(ConductorBsdf, Reciprocity)
{
    // f(wo, wi) = eval / |cos_i| is symmetric (Helmholtz); pairs from the sampler, so that they lie in the
    // lobe where f is large, and from the whole hemisphere. 1e-4 relative: the two orders round differently.
    Rng rng(pcgHash(400));
    for (const auto& cc : conductorCases())
    {
        const ConductorParams c = goldConductor(cc.alphaX, cc.alphaY);
        for (double theta : {0.0, 30.0, 70.0, 85.0})
        {
            const vec3 wo(direction(theta, 40.0));
            for (int k = 0; k < 500; ++k)
            {
                BsdfSample s;
                vec3 wi;
                if (k % 2 == 0 && shader::sampleConductor(c, wo, test::uniform2(rng), s))
                    wi = s.wi;
                else
                    wi = shader::sampleCosineHemisphere(test::uniform2(rng));
                const vec3 forward = shader::evalConductor(c, wo, wi) / wi.z;
                const vec3 backward = shader::evalConductor(c, wi, wo) / wo.z;
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_TRUE(closeRelative(forward[ch], backward[ch], 1e-4, 1e-30))
                        << cc.name << ": f(wo, wi) = " << forward[ch] << ", f(wi, wo) = " << backward[ch]
                        << ", wo = " << str(dvec3(wo)) << ", wi = " << str(dvec3(wi));
            }
        }
    }
}

/// (mu, alpha) of Cycles' table (Blender 4.x, intern/cycles/scene/shader.tables, table_ggx_E): the
/// directional albedo of GGX with height-correlated G2 and F = 1, estimated by
/// intern/cycles/app/cycles_precompute.cpp from 2^23 Sobol samples at rough = x / 31, mu = y / 31 (entry
/// y * 32 + x), alpha = rough^2, printed to 6 digits. The value at (1, 1) is also 1 - ln 2 in closed form
/// (integrate 2 cos sin / (1 + Lambda) over theta_h < 45 degrees with Lambda = (1 / cos(2 theta_h) - 1) / 2).
struct PublishedAlbedo
{
    int y, x;
    double value;
    double mu() const { return y / 31.0; }
    double alpha() const { return (x / 31.0) * (x / 31.0); }
};
const PublishedAlbedo kCyclesGgxE[] = {
    {31, 31, 0.306853}, {15, 31, 0.457779}, {15, 15, 0.866586}, {5, 23, 0.800592}, {1, 31, 0.888202},
    {31, 15, 0.926694}, {10, 20, 0.770368}, {1, 4, 0.911203},   {1, 2, 0.990086},  {20, 8, 0.991163},
};

TEST(GgxAlbedoReference, MatchesCyclesPublishedTable)
{
    // The reference integral itself, before it judges the headers. 5e-4: the table's Monte Carlo error and
    // 6-digit rounding (its weights G2 / G1 lie in [0, 1]: a standard error below 2e-4 even without Sobol's
    // gain); the separable G1 G1 misses several entries by 1e-2 to 3e-1.
    for (const PublishedAlbedo& e : kCyclesGgxE)
        EXPECT_NEAR(ggxAlbedoRef(e.mu(), e.alpha()), e.value, 5e-4)
            << "mu " << e.mu() << ", alpha " << e.alpha();
    EXPECT_NEAR(ggxAlbedoRef(1.0, 1.0), 1.0 - std::log(2.0), 1e-6);
}

/// Directional albedos to test the headers at: the published points, and narrow lobes at normal and grazing
/// incidence (E close to 1 there: a missing factor shows at once).
std::vector<std::pair<double, double>> albedoCases()
{
    std::vector<std::pair<double, double>> cases;
    for (const PublishedAlbedo& e : kCyclesGgxE)
        cases.emplace_back(float(e.mu()), float(e.alpha()));
    for (double alpha : {0.001, 0.01, 0.1})
        for (double mu : {1.0, 0.0871557}) // 0 and 85 degrees
            cases.emplace_back(float(mu), float(alpha));
    return cases;
}

/// A BRDF seen through its sampler and its eval (red channel: the white furnaces are grey).
struct Brdf
{
    std::function<bool(const vec3& wo, Rng& rng, BsdfSample& s)> sample;
    std::function<double(const vec3& wo, const vec3& wi)> eval;
};

/// The albedo of a white BRDF of roughness alpha at wo = (sqrt(1 - mu^2), 0, mu), by its own sampler (mean
/// weight, 200k samples) and by quadrature of its eval over the reflection domain, each against the float64
/// reference within 1 % (the tolerance: the sampling estimate's standard error is below 1e-3, its
/// weights lying in [0, 1], and the quadrature's error is below 1e-4), and neither above 1.
void expectWhiteFurnaceAlbedo(const std::function<Brdf(float alpha)>& make, std::uint32_t seed)
{
    for (const auto& [mu, alpha] : albedoCases())
    {
        SCOPED_TRACE(testing::Message() << "mu " << mu << ", alpha " << alpha);
        const vec3 wo(dvec3(std::sqrt(1.0 - mu * mu), 0.0, mu));
        const Brdf brdf = make(float(alpha));
        const double reference = ggxAlbedoRef(double(wo.z), alpha);
        Rng rng(pcgHash(seed++));
        const auto sampled = test::estimateMean(200'000, [&](long) {
            BsdfSample s;
            return brdf.sample(wo, rng, s) ? double(s.weight.x) : 0.0;
        });
        const double quadrature = reflectionDomain(dvec3(wo), alpha, alpha).integrate([&](const dvec3& d) {
            return brdf.eval(wo, vec3(d));
        });
        EXPECT_NEAR(sampled.mean, reference, 0.01 * reference) << "sampling, +- " << sampled.standardError;
        EXPECT_NEAR(quadrature, reference, 0.01 * reference) << "quadrature of eval";
        EXPECT_LE(sampled.mean, 1.0 + 4.0 * sampled.standardError);
        EXPECT_LE(quadrature, 1.0 + 1e-3);
    }
}

ConductorParams whiteConductor(float alphaX, float alphaY)
{
    return {alphaX, alphaY, true, vec3(1.0f), vec3(0.0f), vec3(0.0f)};
}

TEST(ConductorBsdf, WhiteFurnaceMatchesTheGgxAlbedo)
{
    // Schlick with F0 = 1 is F = 1: the albedo is GGX's single-scattering E(mu, alpha).
    expectWhiteFurnaceAlbedo(
        [](float alpha) {
            const ConductorParams c = whiteConductor(alpha, alpha);
            return Brdf{
                [c](const vec3& wo, Rng& rng, BsdfSample& s) {
                    return shader::sampleConductor(c, wo, test::uniform2(rng), s);
                },
                [c](const vec3& wo, const vec3& wi) { return double(shader::evalConductor(c, wo, wi).x); }};
        },
        500);
}

TEST(ConductorBsdf, WhiteFurnaceOfAnisotropicRoughnessIsAtMostOne)
{
    // No published albedo for anisotropic GGX: sampling and quadrature agree (1 %, as above) and stay <= 1.
    std::uint32_t seed = 600;
    for (const auto& cc : conductorCases())
    {
        SCOPED_TRACE(cc.name);
        const ConductorParams c = whiteConductor(cc.alphaX, cc.alphaY);
        const vec3 wo(cc.wo);
        Rng rng(pcgHash(seed++));
        const auto sampled = test::estimateMean(200'000, [&](long) {
            BsdfSample s;
            return shader::sampleConductor(c, wo, test::uniform2(rng), s) ? double(s.weight.x) : 0.0;
        });
        const double quadrature =
            reflectionDomain(cc.wo, cc.alphaX, cc.alphaY).integrate([&](const dvec3& d) {
                return double(shader::evalConductor(c, wo, vec3(d)).x);
            });
        EXPECT_LE(sampled.mean, 1.0 + 4.0 * sampled.standardError);
        EXPECT_LE(quadrature, 1.0 + 1e-3);
        EXPECT_NEAR(sampled.mean, quadrature, 0.01 * quadrature) << "+- " << sampled.standardError;
    }
}

// ---- Rough dielectric -------------------------------------------------------------------------------------


/// eta' of a pair: 1 for a reflection, else eta_far / eta_wo (ior from outside, 1 / ior from inside).
double etaPrime(const dvec3& wo, const dvec3& wi, double ior)
{
    if (wo.z * wi.z > 0.0)
        return 1.0;
    return wo.z > 0.0 ? ior : 1.0 / ior;
}

/// Every record of sampleRoughDielectric: the common invariants, a grey weight, and the weight VNDF sampling
/// with Fresnel lobe selection must give: G2 / G1(wo) for a reflection, G2 / (G1(wo) eta'^2) for a refraction
/// (D, F and the Jacobians cancel; the 1 / eta'^2 is radiance's, Veach 1997 §5.2).
void auditDielectricRecord(SampleAudit& audit, const DielectricCase& c, const vec3& wo, const BsdfSample& s)
{
    const float pdf = shader::roughDielectricPdf(c.alpha, c.ior, wo, s.wi);
    auditRecord(audit, s, pdf, vec3(shader::evalRoughDielectric(c.alpha, c.ior, wo, s.wi)));
    const dvec3 o(wo), i(s.wi);
    const double e = etaPrime(o, i, c.ior);
    const double expected = g2Ref(o, i, c.alpha, c.alpha) / g1Ref(o, c.alpha, c.alpha) / (e * e);
    audit.require(s.weight.x == s.weight.y && s.weight.y == s.weight.z,
                  [&] { return "weight not grey at wi = " + str(i); });
    // 1e-3: float G against double.
    audit.require(closeRelative(s.weight.x, expected, 1e-3, 1e-6), [&] {
        return "weight " + std::to_string(s.weight.x) +
               " but G2 / (G1 eta'^2) = " + std::to_string(expected) + " at wi = " + str(i) +
               (e == 1.0 ? " (reflection)" : " (refraction)");
    });
}

bool sampleDielectric(const DielectricCase& c, const vec3& wo, Rng& rng, BsdfSample& s)
{
    const float uLobe = rng.nextFloat();
    return shader::sampleRoughDielectric(c.alpha, c.ior, wo, uLobe, test::uniform2(rng), s);
}

TEST(RoughDielectricBsdf, ChiSquare)
{
    const auto cases = dielectricCases();
    std::uint32_t seed = 700;
    for (const auto& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        const auto domain = dielectricDomain(c);
        SampleAudit audit;
        const SamplerRun r = runSampler(
            domain, seed++, int(cases.size()),
            [&](Rng& rng, dvec3& d) {
                BsdfSample s;
                if (!sampleDielectric(c, wo, rng, s))
                    return false;
                auditDielectricRecord(audit, c, wo, s);
                d = dvec3(s.wi);
                return true;
            },
            [&](const dvec3& d) { return double(shader::roughDielectricPdf(c.alpha, c.ior, wo, vec3(d))); });
        expectSamplerMatchesPdf(r);
        EXPECT_EQ(audit.bad(), 0) << audit.first();
    }
}

TEST(RoughDielectricBsdf, GeneralizedReciprocity)
{
    // Reflection: f(wo, wi) = f(wi, wo). Refraction: f(wo, wi) / eta_wo^2 = f(wi, wo) / eta_wi^2 (Veach 1997
    // §5.2; eta of each direction's medium: 1 outside, ior inside), f = eval / |cos_i|: equivalently f(wo,
    // wi) eta'(wo) is symmetric, to the first power (f eta'^2 is the energy form the furnace below
    // integrates). 2e-3 relative: the two orders find the generalised half vector from different float sums
    // (wi eta' + wo against wo / eta' + wi), a direction error of about 3e-7 that D of alpha 0.001 turns into
    // 2 (3e-7 / alpha).
    Rng rng(pcgHash(900));
    long reflections = 0, refractions = 0;
    for (float alpha : test::kMicrofacetAlphas)
        for (float ior : {1.5f, 1.0f / 1.5f})
            for (double theta : {0.0, 30.0, 70.0, 85.0, 150.0, 170.0})
            {
                const DielectricCase c{"", alpha, ior, direction(theta, 40.0)};
                const vec3 wo(c.wo);
                for (int k = 0; k < 500; ++k)
                {
                    BsdfSample s;
                    vec3 wi;
                    if (k % 2 == 0 && sampleDielectric(c, wo, rng, s))
                        wi = s.wi;
                    else
                        wi = shader::sampleUniformSphere(test::uniform2(rng));
                    const dvec3 o(wo), i(wi);
                    // Float Fresnel is ill-conditioned where a microfacet refracts near the critical angle
                    // (cos_t from 1 - sin^2 loses digits: 0.5 % at cos_t = 0.005, beyond any tolerance that
                    // still tests); such pairs, of negligible f, are left out.
                    dvec3 m = glm::normalize(
                        o + (o.z * i.z > 0.0 ? 1.0 : (o.z > 0.0 ? double(ior) : 1.0 / ior)) * i);
                    if (std::min(std::fabs(glm::dot(o, m)), std::fabs(glm::dot(i, m))) < 0.02)
                        continue;
                    const double forward = shader::evalRoughDielectric(alpha, ior, wo, wi) / std::fabs(i.z);
                    const double backward = shader::evalRoughDielectric(alpha, ior, wi, wo) / std::fabs(o.z);
                    const double etaO = o.z > 0.0 ? 1.0 : ior, etaI = i.z > 0.0 ? 1.0 : ior;
                    ASSERT_TRUE(closeRelative(forward / (etaO * etaO), backward / (etaI * etaI), 2e-3, 1e-30))
                        << "alpha " << alpha << ", ior " << ior << ": f(wo, wi) = " << forward
                        << ", f(wi, wo) = " << backward << ", wo = " << str(o) << ", wi = " << str(i);
                    if (forward > 0.0)
                        ++(o.z * i.z > 0.0 ? reflections : refractions);
                }
            }
    // Both modes were tested where f is not 0, not skipped.
    EXPECT_GT(reflections, 5000);
    EXPECT_GT(refractions, 5000);
}

TEST(RoughDielectricBsdf, WhiteFurnaceConservesEnergy)
{
    // Light arriving from wo leaves with the energy integral over wi of f(wi, wo) |cos_i|, which generalised
    // reciprocity turns into the integral of f(wo, wi) |cos_i| with a refraction's f times eta'(wo)^2 (the
    // radiance factor 1 / eta'^2 taken out: Veach 1997 §5.2), reflection and refraction summed. At most 1 by
    // sampling (each weight times eta'^2 is G2 / G1 <= 1; 100k samples, a standard error below 2e-3) and by
    // quadrature of eval (1e-4: float rounding; the quadrature itself is good to 1e-7); the two within 0.01
    // of each other; and at alpha 0.001, where G2 / G1 > 0.999 and hardly a sample fails, above 0.99: a
    // refraction weighted eta'^2 too much or too little misses that by 0.2 or more.
    std::uint32_t seed = 1000;
    for (const auto& c : dielectricCases())
    {
        SCOPED_TRACE(c.name);
        const vec3 wo(c.wo);
        Rng rng(pcgHash(seed++));
        const auto sampled = test::estimateMean(100'000, [&](long) {
            BsdfSample s;
            if (!sampleDielectric(c, wo, rng, s))
                return 0.0;
            const double e = etaPrime(c.wo, dvec3(s.wi), c.ior);
            return double(s.weight.x) * e * e;
        });
        const double quadrature = dielectricDomain(c).integrate([&](const dvec3& d) {
            const double e = etaPrime(c.wo, d, c.ior);
            return double(shader::evalRoughDielectric(c.alpha, c.ior, wo, vec3(d))) * e * e;
        });
        EXPECT_LE(sampled.mean, 1.0 + 4.0 * sampled.standardError);
        EXPECT_LE(quadrature, 1.0 + 1e-4);
        EXPECT_NEAR(sampled.mean, quadrature, 0.01) << "+- " << sampled.standardError;
        if (c.alpha == 0.001f)
        {
            EXPECT_GT(sampled.mean, 0.99);
        }
    }
}

// ---- glTF metallic-roughness ------------------------------------------------------------------------------

GltfPbrParams gltfMaterial(float alpha)
{
    return {vec3(0.8f, 0.5f, 0.2f), 0.5f, alpha, 0.04f};
}


bool sampleGltf(const GltfPbrParams& p, const vec3& wo, Rng& rng, BsdfSample& s)
{
    const float uLobe = rng.nextFloat();
    return shader::sampleGltfPbr(p, wo, uLobe, test::uniform2(rng), s);
}


TEST(GltfPbrBsdf, ChiSquare)
{
    const auto cases = gltfCases();
    std::uint32_t seed = 1100;
    for (const auto& c : cases)
    {
        SCOPED_TRACE(c.name);
        const GltfPbrParams p = gltfMaterial(c.alphaX);
        const vec3 wo(c.wo);
        SampleAudit audit;
        const SamplerRun r = runSampler(
            gltfDomain(c), seed++, int(cases.size()),
            [&](Rng& rng, dvec3& d) {
                BsdfSample s;
                if (!sampleGltf(p, wo, rng, s))
                    return false;
                auditRecord(audit, s, shader::gltfPbrPdf(p, wo, s.wi), shader::evalGltfPbr(p, wo, s.wi));
                audit.require(s.wi.z > 0.0f, [&] { return "wi below the surface: " + str(dvec3(s.wi)); });
                d = dvec3(s.wi);
                return true;
            },
            [&](const dvec3& d) { return double(shader::gltfPbrPdf(p, wo, vec3(d))); });
        expectSamplerMatchesPdf(r);
        EXPECT_EQ(audit.bad(), 0) << audit.first();
    }
}

/// glTF 2.0 Appendix B.3.5's material, in double, with the specification's own D and visibility (B.3.2,
/// height-correlated: V = 1 / (2 (|N.V| sqrt(a^2 + (1 - a^2)(N.L)^2) + |N.L| sqrt(a^2 + (1 - a^2)(N.V)^2)))),
/// times cos_i: what evalGltfPbr must return.
dvec3 gltfEvalRef(const GltfPbrParams& p, const dvec3& v, const dvec3& l)
{
    const dvec3 h = glm::normalize(v + l);
    const double a2 = double(p.alpha) * p.alpha, nh = h.z, nv = v.z, nl = l.z;
    const double d = nh > 0.0 ? a2 / (kPiD * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2)) : 0.0;
    const double visibility = (glm::dot(h, l) > 0.0 && glm::dot(h, v) > 0.0)
                                  ? 1.0 / (2.0 * (nv * std::sqrt(a2 + (1.0 - a2) * nl * nl) +
                                                  nl * std::sqrt(a2 + (1.0 - a2) * nv * nv)))
                                  : 0.0;
    const double specular = visibility * d;
    const double w = std::pow(1.0 - std::fabs(glm::dot(v, h)), 5);
    const dvec3 base(p.baseColor);
    const double dielectricFresnel = p.f0 + (1.0 - p.f0) * w;
    const dvec3 dielectric = glm::mix(base / kPiD, dvec3(specular), dielectricFresnel);
    const dvec3 metal = (base + (1.0 - base) * w) * specular;
    return glm::mix(dielectric, metal, double(p.metallic)) * nl;
}

/// Direction pairs of the glTF BRDF at every test roughness, each metallic of `metallics` and four view angles:
/// `pairs` wi per wo, every other one sampled by the BRDF (its lobe's peak), the rest cosine-distributed.
void forEachGltfPair(std::initializer_list<float> metallics, int pairs, std::uint32_t seed,
                     const std::function<void(const GltfPbrParams&, const vec3&, const vec3&)>& check)
{
    Rng rng(pcgHash(seed));
    for (float alpha : test::kMicrofacetAlphas)
        for (float metallic : metallics)
        {
            GltfPbrParams p = gltfMaterial(alpha);
            p.metallic = metallic;
            for (double theta : {0.0, 30.0, 70.0, 85.0})
            {
                const vec3 wo(direction(theta, 40.0));
                for (int k = 0; k < pairs; ++k)
                {
                    BsdfSample s;
                    const vec3 wi = k % 2 == 0 && sampleGltf(p, wo, rng, s)
                                        ? s.wi
                                        : shader::sampleCosineHemisphere(test::uniform2(rng));
                    check(p, wo, wi);
                    if (::testing::Test::HasFatalFailure())
                        return; // the first failing pair, as an ASSERT in the loop would
                }
            }
        }
}

TEST(GltfPbrBsdf, EvalMatchesAppendixB)
{
    // The sampling tests check eval only against the sampler's own pdf; this checks it against the
    // specification, diffuse and Fresnel mixing included. 1e-4 relative: float against double (below 1e-6
    // here).
    forEachGltfPair({0.0f, 0.3f, 1.0f}, 200, 1250, [](const GltfPbrParams& p, const vec3& wo, const vec3& wi) {
        const vec3 eval = shader::evalGltfPbr(p, wo, wi);
        const dvec3 expected = gltfEvalRef(p, dvec3(wo), dvec3(wi));
        for (int ch = 0; ch < 3; ++ch)
            ASSERT_TRUE(closeRelative(eval[ch], expected[ch], 1e-4, 1e-30))
                << "alpha " << p.alpha << ", metallic " << p.metallic << ", channel " << ch << ": eval " << eval[ch]
                << ", Appendix B " << expected[ch] << ", wo = " << str(dvec3(wo)) << ", wi = " << str(dvec3(wi));
    });
}

TEST(GltfPbrBsdf, Reciprocity)
{
    // As the conductor's: f = eval / cos_i is symmetric, its Fresnel terms taken at |wo.h| = |wi.h|.
    forEachGltfPair({0.0f, 0.5f, 1.0f}, 500, 1300, [](const GltfPbrParams& p, const vec3& wo, const vec3& wi) {
        const vec3 forward = shader::evalGltfPbr(p, wo, wi) / wi.z;
        const vec3 backward = shader::evalGltfPbr(p, wi, wo) / wo.z;
        for (int ch = 0; ch < 3; ++ch)
            ASSERT_TRUE(closeRelative(forward[ch], backward[ch], 1e-4, 1e-30))
                << "alpha " << p.alpha << ", metallic " << p.metallic << ": f(wo, wi) = " << forward[ch]
                << ", f(wi, wo) = " << backward[ch] << ", wo = " << str(dvec3(wo)) << ", wi = " << str(dvec3(wi));
    });
}

TEST(GltfPbrBsdf, WhiteFurnaceOfWhiteMetalMatchesTheGgxAlbedo)
{
    // Metallic 1 and base colour 1: conductor_fresnel is 1, the BRDF is GGX's alone (Appendix B.3.5).
    expectWhiteFurnaceAlbedo(
        [](float alpha) {
            const GltfPbrParams p{vec3(1.0f), 1.0f, alpha, 0.04f};
            return Brdf{
                [p](const vec3& wo, Rng& rng, BsdfSample& s) { return sampleGltf(p, wo, rng, s); },
                [p](const vec3& wo, const vec3& wi) { return double(shader::evalGltfPbr(p, wo, wi).x); }};
        },
        1400);
}
} // namespace
} // namespace rt
