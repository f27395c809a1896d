// Chi-square goodness of fit of the GPU's light samplers (issue 9): Shared/LightSampling.h compiled as GLSL
// draws directions through Shaders/Tests/Parity.comp (mode kLightSampling) from uniform points the host
// generates, and the host histograms them against the density the C++ compilation of the same header reports
// (lightPdf, integrated over each cell). ShaderParityTest compares the two compilations sample by sample at a
// few hundred points; only a histogram of many samples sees a density the GPU's float trigonometry bends a
// little everywhere, or a branch those points never took. The recipe is Mitsuba 3's (research notes §2.1,
// Support/ChiSquare.h): cells below 5 expected samples pooled, alpha = 0.01 with Šidák's correction over the
// configurations of a test. Each returned sample must also be finite with a positive pdf that the C++
// lightPdf of its direction finds again to 1e-3 (float32 on the GPU).
//
// Every sampler NEE has (LightSampler Area, SolidAngle, Projected) and book 3's (strategy kNoIndex), each on
// sphere, rectangle and triangle lights seen near and large, distant and small (below the spherical samplers'
// bounds: area sampling), at grazing incidence with the receiver's horizon across the light, and a sliver
// triangle. The histogram domains are the Common tests': the planar light's own surface (LightSurfaceDomain),
// the cone of directions to a sphere, and for Area sampling of a sphere the visible cap's normals (its
// density over directions diverges at the silhouette, where no grid of directions integrates it; over the
// surface it is uniform).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestEnvironment.h"
#include "ParityKernel.h"
#include "Random/Pcg.h"
#include "Render/RenderSettings.h"
#include "Sampling/LightSampling.h"
#include "Support/CapDomain.h"
#include "Support/CatalogueCases.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/ProjectedCapDomain.h"
#include "Support/StatisticsHelpers.h"

namespace rt::gpu::test
{
namespace
{
using ::rt::test::CapDomain;
using ::rt::test::LightSurfaceDomain;

struct SamplerCase
{
    std::string name;
    LightData light;
    vec3 p; // shading point
    vec3 n; // receiver normal (Projected's cosine; the other samplers ignore it)
};

/// `axis` turned by `degrees` about a fixed perpendicular: a receiver normal at a chosen angle to a light.
vec3 tiltedFrom(const vec3& axis, double degrees)
{
    const dvec3 a = glm::normalize(dvec3(axis));
    const dvec3 helper = std::fabs(a.x) > 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
    const dvec3 perpendicular = glm::normalize(glm::cross(a, helper));
    const double t = degrees * ::rt::test::kPiD / 180.0;
    return vec3(std::cos(t) * a + std::sin(t) * perpendicular);
}

vec3 towards(const LightData& l, const vec3& p)
{
    const vec3 centre = l.shape == LightShape::Sphere ? l.p0
                        : l.shape == LightShape::Quad ? l.p0 + 0.5f * (l.p1 + l.p2)
                                                      : l.p0 + (l.p1 + l.p2) / 3.0f;
    return glm::normalize(centre - p);
}

/// The configurations every sampler runs on; SamplerChiSquareCases.TakeEveryBranchOfTheSamplers checks that
/// they reach the branches their names promise. Spheres are seen from outside along the Common tests'
/// direction; the receiver normals tilt away from the light so that Projected's cosine varies across it.
std::vector<SamplerCase> samplerCases()
{
    namespace t = ::rt::test;
    const vec3 dir(0.3f, 1.0f, -0.2f);
    const auto sphere = [&](const std::string& name, float sin2, double normalDegrees)
    {
        const LightData l = t::sphereSeenAt(sin2, dir);
        return SamplerCase{name, l, vec3(0.0f), tiltedFrom(towards(l, vec3(0.0f)), normalDegrees)};
    };
    const auto planar = [](const std::string& name, const LightData& l, const vec3& p, double normalDegrees) {
        return SamplerCase{name, l, p, tiltedFrom(towards(l, p), normalDegrees)};
    };
    // Grazing: p almost in the light's plane, every direction within 3 degrees of it; the receiver's horizon
    // (normal (0.2, 1, 0.1)) cuts the light in two, so Projected's warp floors the corners below it.
    const vec3 acrossTheHorizon = glm::normalize(vec3(0.2f, 1.0f, 0.1f));
    return {
        // alpha = 65 degrees, the normal 15 degrees off the axis: the whole cap above the horizon.
        sphere("sphere near, large (sin^2 = 0.826)", 0.826f, 15.0),
        sphere("sphere distant, small (sin^2 = 1e-4)", 1e-4f, 50.0),
        // alpha = 17.5 degrees, its lower rim 2 degrees above the horizon: Projected's thinnest ellipse.
        sphere("sphere low, rim 2 degrees over the horizon (sin^2 = 0.09)", 0.09f, 90.0 - 17.4576 - 2.0),
        // alpha = 30 degrees, the centre 10 degrees up: Projected's ellipse joined to a disk segment.
        sphere("sphere straddling the horizon (sin^2 = 0.25)", 0.25f, 80.0),
        // alpha = 30 degrees, the centre 20 degrees down: Projected's crescent.
        sphere("sphere mostly below the horizon (sin^2 = 0.25)", 0.25f, 110.0),
        {"quad near field, large",
         t::makeQuadLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
         {0.3f, 0.6f, 0.02f},
         glm::normalize(vec3(0.3f, 0.2f, -1.0f))},
        planar("strip across the room", t::makeQuadLight({455, 100, 554}, {-355, 0, 0}, {0, 10, 0}),
               {278, 300, 254}, 40.0),
        planar("quad distant, small (4e-3 sr: area sampling)",
               t::makeQuadLight({-0.5f, -0.5f, 15}, {1, 0, 0}, {0, 1, 0}), vec3(0.0f), 30.0),
        {"quad grazing, horizon across it", t::makeQuadLight({1, -1, 0.05f}, {2, 0, 0}, {0, 2, 0}),
         vec3(0.0f), acrossTheHorizon},
        {"triangle near field, large",
         t::makeTriangleLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
         {0.25f, 0.25f, 0.01f},
         glm::normalize(vec3(0.3f, -0.2f, -1.0f))},
        planar("triangle distant (1e-3 sr)", t::makeTriangleLight({-10, 0, 400}, {10, 0, 400}, {0, 16, 400}),
               vec3(0.0f), 45.0),
        planar("triangle distant, small (1.6e-4 sr: area sampling)",
               t::makeTriangleLight({-1, 0, 100}, {1, 0, 100}, {0, 1.6f, 100}), vec3(0.0f), 30.0),
        {"triangle grazing, horizon across it",
         t::makeTriangleLight({2, -1, 0.03f}, {3, 1, 0.03f}, {2, 1, 0.03f}), vec3(0.0f), acrossTheHorizon},
        planar("sliver, near", t::sliverTriangle(), {280, 104, 550}, 30.0),
    };
}

/// The density C++ reports for a direction under `strategy` (kNoIndex: book 3's sampler).
float cpuPdf(const SamplerCase& c, std::uint32_t strategy, const vec3& wi)
{
    return strategy == kNoIndex ? lightPdf(c.light, c.p, wi)
                                : lightPdf(c.light, LightSampler(strategy), c.p, c.n, wi);
}

/// A sphere light seen from outside, histogrammed by the normal at the point each direction first meets:
/// the visible cap (normals within acos(R / d) of the axis towards p) cut into cells of equal area, where
/// Area sampling is uniform (SphereAreaSampling's chi-square on the C++ side). The expected counts turn the
/// solid-angle density into one per unit area, lightPdf(w) cos / r^2, as LightSurfaceDomain does for planar
/// lights, so that they come from the C++ pdf and nothing else. A direction that rounding puts just outside
/// the sphere's cone goes to its closest approach, on the silhouette: the edge row.
class SphereSurfaceDomain
{
  public:
    SphereSurfaceDomain(const LightData& sphere, const vec3& p, int thetaCells, int phiCells)
        : m_centre(sphere.p0), m_p(p), m_radius(sphere.radius),
          m_cap(m_p - m_centre, m_radius / glm::distance(m_p, m_centre), thetaCells, phiCells)
    {
    }

    int cellCount() const { return m_cap.cellCount(); }

    int cell(const vec3& wi) const
    {
        const dvec3 w = glm::normalize(dvec3(wi)), toCentre = m_centre - m_p;
        const double b = glm::dot(toCentre, w);
        if (!(b > 0.0))
            return -1;
        const dvec3 closest = toCentre - b * w;
        const double disc = std::max(0.0, m_radius * m_radius - glm::dot(closest, closest));
        return m_cap.cell(m_p + (b - std::sqrt(disc)) * w - m_centre);
    }

    std::vector<double> expectedCounts(long samples, int subdivisions,
                                       const std::function<double(const dvec3&)>& solidAnglePdf) const
    {
        return m_cap.expectedCounts(
            [&](const dvec3& normal)
            {
                dvec3 w = m_centre + m_radius * normal - m_p;
                const double r2 = glm::dot(w, w);
                w /= std::sqrt(r2);
                return solidAnglePdf(w) * std::max(0.0, -glm::dot(normal, w)) * m_radius * m_radius / r2;
            },
            samples, subdivisions);
    }

  private:
    dvec3 m_centre, m_p;
    double m_radius;
    CapDomain m_cap;
};

/// Cells of a case's histogram and their expected counts from the C++ pdf.
struct Histogramming
{
    std::function<int(const vec3&)> cell;
    std::vector<double> expected;
};

Histogramming histogrammingFor(const SamplerCase& c, std::uint32_t strategy, long samples, int cells)
{
    const auto pdf = [&c, strategy](const dvec3& w) { return double(cpuPdf(c, strategy, vec3(w))); };
    if (c.light.shape == LightShape::Sphere && strategy == std::uint32_t(LightSampler::Area))
    {
        const SphereSurfaceDomain domain(c.light, c.p, cells / 2, cells);
        return {[domain](const vec3& wi) { return domain.cell(wi); }, domain.expectedCounts(samples, 4, pdf)};
    }
    if (c.light.shape == LightShape::Sphere && (strategy == std::uint32_t(LightSampler::Projected) ||
                                                strategy == std::uint32_t(LightSampler::ProjectedExact)))
    {
        // Uniform over the region the visible cap projects to: cells in the tangent plane, the region from its
        // definition in double (a cap cut by the horizon has cells of directions cut by it, where the midpoint
        // rule misses slivers and the chi-square fails outright on their samples).
        const ::rt::test::ProjectedCapDomain domain(::rt::test::capGeometry(c.light, c.p, c.n), cells / 2 + 8);
        return {[domain](const vec3& wi) { return domain.cell(wi); }, domain.expectedCounts(samples)};
    }
    if (c.light.shape == LightShape::Sphere)
    {
        // The other samplers draw from the cone of directions to the sphere with a bounded density (uniform,
        // or the receiver's cosine): cells of directions, as LightSampling's chi-square. Over the surface
        // their density would peak at the point nearest p, (d - R)^-2, too sharply for a near sphere's
        // quadrature.
        const ::rt::test::Cone cone = ::rt::test::coneOf(c.light, c.p);
        const CapDomain domain(cone.axis, cone.cosMax, cells / 2, cells);
        return {[domain](const vec3& wi) { return domain.cell(dvec3(wi)); },
                domain.expectedCounts(pdf, samples, 4)};
    }
    // 16 x 16 quadrature points per cell: the area density of the near-field cases peaks under the point.
    const LightSurfaceDomain domain(c.light, c.p, cells);
    return {[domain](const vec3& wi) { return domain.cell(wi); }, domain.expectedCounts(samples, 16, pdf)};
}

/// The GPU's samples of `strategy` for `samples` uniform points of a fixed seed: Parity.comp's
/// kLightSampling output, (ok, wi, pdf, lightPdf(wi), outcome) per sample.
std::vector<std::uint32_t> sampleOnGpu(const SamplerCase& c, std::uint32_t strategy, long samples,
                                       std::uint32_t seed)
{
    Rng rng(pcgHash(seed));
    std::vector<std::uint32_t> in;
    in.reserve(std::size_t(samples) * kParityLayouts[kLightSampling].inputWords);
    for (long i = 0; i < samples; ++i)
    {
        const vec2 u = ::rt::test::uniform2(rng);
        in.insert(in.end(), {0u, bits(c.p.x), bits(c.p.y), bits(c.p.z), bits(u.x), bits(u.y), strategy,
                             bits(c.n.x), bits(c.n.y), bits(c.n.z)});
    }
    return runParity(kLightSampling, in, {c.light});
}

/// Mitsuba's and the Common tests' size: 1e6 samples over 32 x 32 cells of a planar light (32 x 16 of a
/// sphere's cap), ~1000 expected per cell. One light shape's configurations under one sampler, the host's
/// quadrature and pdf checks included, take 1 to 3 s on lavapipe with 2 cores: the default suite's size.
constexpr long kSamples = 1'000'000;
constexpr int kCells = 32;

/// One test: a sampler over the configurations of one light shape.
struct SamplerRun
{
    std::uint32_t strategy; // a LightSampler, or kNoIndex for book 3's sampler
    LightShape shape;
};

std::string runName(const ::testing::TestParamInfo<SamplerRun>& info)
{
    const SamplerRun& r = info.param;
    const std::string strategy = r.strategy == kNoIndex ? "book3" : toString(LightSampler(r.strategy));
    const char* shape = r.shape == LightShape::Sphere ? "sphere"
                        : r.shape == LightShape::Quad ? "quad"
                                                      : "triangle";
    return ::rt::test::testNameOf(strategy + "_" + shape); // '-' -> '_'
}

void PrintTo(const SamplerRun& r, std::ostream* out)
{
    *out << runName({r, 0});
}

class GpuSamplerChiSquare : public ::testing::TestWithParam<SamplerRun>
{
};

TEST_P(GpuSamplerChiSquare, SamplesFollowTheCpuPdf)
{
    RT_REQUIRE_GPU();
    const SamplerRun run = GetParam();
    std::vector<SamplerCase> cases;
    for (const SamplerCase& c : samplerCases())
        if (c.light.shape == run.shape)
            cases.push_back(c);
    const bool area = run.strategy == std::uint32_t(LightSampler::Area);
    std::uint32_t seed =
        9000 + 100 * (run.strategy == kNoIndex ? 3u : run.strategy) + 20 * std::uint32_t(run.shape);
    for (const SamplerCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const std::vector<std::uint32_t> out = sampleOnGpu(c, run.strategy, kSamples, seed++);
        const Histogramming h = histogrammingFor(c, run.strategy, kSamples, kCells);
        std::vector<double> observed(h.expected.size(), 0.0);
        const bool sphere = c.light.shape == LightShape::Sphere;
        const double distance = glm::distance(dvec3(c.p), dvec3(c.light.p0));
        long declined = 0, outside = 0, invalid = 0, mismatches = 0, rim = 0, illConditioned = 0;
        for (long i = 0; i < kSamples; ++i)
        {
            const std::size_t o = kParityLayouts[kLightSampling].outputWords * std::size_t(i);
            if (out[o] == 0)
            {
                ++declined;
                continue;
            }
            const vec3 wi = vec3At(out, o + 1);
            const float pdf = asFloat(out[o + 4]);
            if (!isFinite(wi) || std::fabs(glm::length(wi) - 1.0f) > 1e-5f || !std::isfinite(pdf) ||
                !(pdf > 0.0f))
            {
                if (invalid++ < 3)
                    ADD_FAILURE() << "sample " << i << ": wi (" << wi.x << ", " << wi.y << ", " << wi.z
                                  << "), pdf " << pdf;
                continue;
            }
            const int cell = h.cell(wi);
            if (cell < 0)
                ++outside;
            else
                observed[std::size_t(cell)] += 1.0;

            const float cpu = cpuPdf(c, run.strategy, wi);
            double tolerance = 1e-3;
            if (sphere && area)
            {
                // Area sampling of a sphere: C++ finds the point again from the float direction, whose
                // rounding (6e-8 of d across) moves the cosine at a silhouette point, the root of a
                // discriminant, by about 1e-7 (d / r) / cos^2 relative (LightSampling's SphereAreaSampling
                // test). Where that is beyond 1 % the density diverges and the histogram, not the pdf, checks
                // the samples.
                const dvec3 w(wi), toCentre = dvec3(c.light.p0) - dvec3(c.p);
                const dvec3 closest = toCentre - glm::dot(toCentre, w) * w;
                const double r = c.light.radius;
                const double cos2 = std::max(0.0, 1.0 - glm::dot(closest, closest) / (r * r));
                const double conditioning = 3e-7 * (distance / r) / cos2;
                if (conditioning >= 1e-2)
                {
                    ++illConditioned;
                    continue;
                }
                tolerance += conditioning;
            }
            const bool projected = run.strategy == std::uint32_t(LightSampler::Projected) ||
                                   run.strategy == std::uint32_t(LightSampler::ProjectedExact);
            // Projected's warp of polygons is not cos / P (its pdf is the warp's, floored): only the exact ones.
            if ((sphere && projected) || run.strategy == std::uint32_t(LightSampler::ProjectedExact))
            {
                // The exact projected samplers' pdf is cos / P: a direction near the horizon has a cosine of the order
                // of its components' rounding, which differs between drivers (NVIDIA's relaxed float arithmetic):
                // 2e-7 / cos relative. Beyond 1 % the histogram, not the pdf, checks the sample (counted below).
                const double cosine = glm::dot(dvec3(c.n), dvec3(wi));
                const double conditioning = 2e-7 / std::max(cosine, 1e-12);
                if (conditioning >= 1e-2)
                {
                    ++illConditioned;
                    continue;
                }
                tolerance += conditioning;
            }
            if (sphere && projected && run.strategy != kNoIndex &&
                cpu == 0.0f)
            {
                // Projected keeps a rim sample that rounding moved a few ulps out of the cone, with its
                // density cos / F, where lightPdf's chord test says 0 (LightSampling.h): a set of no measure,
                // at most 1e-5 of the samples (ProjectedCap's test on the C++ side).
                ++rim;
                continue;
            }
            if (std::fabs(double(pdf) - double(cpu)) > tolerance * double(cpu) && mismatches++ < 3)
                ADD_FAILURE() << "sample " << i << ": GPU pdf " << pdf << ", C++ lightPdf of its direction "
                              << cpu;
        }
        EXPECT_EQ(invalid, 0);
        EXPECT_EQ(mismatches, 0) << "samples whose pdf C++ does not find again, of " << kSamples;
        EXPECT_LE(rim, kSamples / 100'000) << "rim samples outside the cone";
        // Within 1 % ill-conditioned: cos below sqrt(3e-5 d / r), 5.5 % of the visible samples of a sphere
        // seen at d = 100 r. The chi-square checks those too.
        EXPECT_LE(illConditioned, (kSamples - declined) / 10)
            << "samples too near the silhouette to compare pdfs";
        EXPECT_EQ(outside, 0) << "samples missing the light";
        std::vector<double> expected = h.expected;
        if (area && sphere)
        {
            // The sphere's far side faces away from p: its samples are declined, one more cell whose expected
            // count is what the visible cap leaves of the whole.
            double visible = 0.0;
            for (double e : h.expected)
                visible += e;
            observed.push_back(double(declined));
            expected.push_back(double(kSamples) - visible);
        }
        else
        {
            EXPECT_EQ(declined, 0) << "samples declined";
        }
        const auto r =
            ::rt::test::chiSquareTest(observed, expected, ::rt::test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

std::vector<SamplerRun> runs()
{
    std::vector<SamplerRun> out;
    for (std::uint32_t strategy : {std::uint32_t(LightSampler::Area), std::uint32_t(LightSampler::SolidAngle),
                                   std::uint32_t(LightSampler::Projected), std::uint32_t(LightSampler::ProjectedExact),
                                   kNoIndex})
        for (LightShape shape : {LightShape::Sphere, LightShape::Quad, LightShape::Triangle})
            out.push_back({strategy, shape});
    return out;
}

INSTANTIATE_TEST_SUITE_P(Lights, GpuSamplerChiSquare, ::testing::ValuesIn(runs()), runName);

TEST(SamplerChiSquareCases, TakeEveryBranchOfTheSamplers)
{
    // The configurations' names promise the samplers' branches: the spherical rectangle and triangle within
    // their bounds or area sampling below them, a sphere's cap above the horizon (the ellipse), across it with
    // its centre above (ellipse and disk segment) or below (the crescent).
    const auto cases = samplerCases();
    const auto find = [&](const std::string& prefix) -> const SamplerCase&
    {
        for (const SamplerCase& c : cases)
            if (c.name.rfind(prefix, 0) == 0)
                return c;
        throw std::runtime_error("no case " + prefix);
    };
    for (const char* name : {"quad near field", "strip across the room", "quad grazing"})
    {
        const SamplerCase& c = find(name);
        ASSERT_TRUE(shader::isRectangle(c.light)) << name;
        EXPECT_GE(shader::makeSphericalRectangle(c.p, c.light.p0, c.light.p1, c.light.p2).solidAngle,
                  shader::kMinSphericalRectangle)
            << name;
    }
    const SamplerCase& smallQuad = find("quad distant, small");
    EXPECT_LT(shader::makeSphericalRectangle(smallQuad.p, smallQuad.light.p0, smallQuad.light.p1,
                                             smallQuad.light.p2)
                  .solidAngle,
              shader::kMinSphericalRectangle);
    for (const char* name : {"triangle near field", "triangle distant (", "triangle grazing", "sliver"})
    {
        shader::SphericalTriangle t;
        EXPECT_TRUE(shader::sphericalTriangleApplies(find(name).light, find(name).p, t)) << name;
    }
    shader::SphericalTriangle t;
    EXPECT_FALSE(shader::sphericalTriangleApplies(find("triangle distant, small").light,
                                                  find("triangle distant, small").p, t));
    const auto capKind = [&](const char* name) {
        shader::ProjectedCap cap;
        return shader::projectedCap(find(name).light, find(name).p, find(name).n, cap);
    };
    for (const char* name : {"sphere near", "sphere distant", "sphere low"})
        EXPECT_EQ(capKind(name), shader::kCapWhole) << name;
    EXPECT_EQ(capKind("sphere straddling"), shader::kCapClipped);
    EXPECT_EQ(capKind("sphere mostly below"), shader::kCapCrescent);
    // The horizon crosses the grazing lights: some corner below it, some above.
    for (const char* name : {"quad grazing", "triangle grazing"})
    {
        const SamplerCase& c = find(name);
        const vec3 corners[] = {c.light.p0, c.light.p0 + c.light.p1, c.light.p0 + c.light.p2};
        int above = 0;
        for (const vec3& y : corners)
            above += glm::dot(c.n, y - c.p) > 0.0f ? 1 : 0;
        EXPECT_TRUE(above == 1 || above == 2) << name;
    }
}
} // namespace
} // namespace rt::gpu::test
