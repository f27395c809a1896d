// The materials' scattering (Shared/, both engines) against the physics it implements.
#include <gtest/gtest.h>

#include <cmath>

#include "Random/Pcg.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/SpecularScattering.h"

namespace rt::test
{
namespace
{
using shader::FresnelModel;

TEST(Dielectric, RefractionObeysSnellsLaw)
{
    const vec3 n(0.0f, 1.0f, 0.0f);
    const float eta = 1.0f / 1.5f; // air into glass
    const vec3 d = glm::normalize(vec3(0.6f, -1.0f, 0.2f));
    // u = 1: Schlick's reflectance is below 1, so the refracted branch is taken.
    const vec3 t = shader::sampleDielectric(d, n, eta, FresnelModel::Schlick, 0.999999f);
    ASSERT_LT(t.y, 0.0f);
    const float sinIn = std::sqrt(1.0f - d.y * d.y);
    const float sinOut = std::sqrt(1.0f - t.y * t.y) / glm::length(t);
    EXPECT_NEAR(sinOut, eta * sinIn, 1e-5f);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    // The refracted ray stays in the plane of incidence.
    EXPECT_NEAR(glm::dot(glm::cross(d, n), t), 0.0f, 1e-5f);
}

TEST(Dielectric, TotalInternalReflectionBeyondTheCriticalAngle)
{
    const vec3 n(0.0f, 1.0f, 0.0f); // facing the ray, which travels inside glass towards air
    const vec3 d = glm::normalize(vec3(1.0f, -0.5f, 0.0f)); // 63 degrees from the normal > 41.8
    const vec3 r = shader::sampleDielectric(d, n, 1.5f, FresnelModel::Exact, 0.0f);
    EXPECT_NEAR(r.x, d.x, 1e-6f);
    EXPECT_NEAR(r.y, -d.y, 1e-6f);
}

TEST(Dielectric, SchlickAtNormalIncidenceIsR0AndGrazingIsOne)
{
    EXPECT_NEAR(shader::schlickReflectance(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(shader::schlickReflectance(0.0f, 1.0f / 1.5f), 1.0f, 1e-6f);
}

// The exact reflectance against Fresnel's equations in their sine and tangent form (Hecht, Optics, §4.6.2:
// R_s = sin^2(ti - tt) / sin^2(ti + tt), R_p = tan^2(ti - tt) / tan^2(ti + tt)), in double: an independent
// formula, where the shared code uses the cosine form.
TEST(Dielectric, ExactReflectanceFollowsFresnelsEquations)
{
    for (const double eta : {1.0 / 1.5, 1.0 / 1.33, 1.0 / 2.4, 1.5, 1.33})
        for (int k = 1; k < 90; ++k)
        {
            const double ti = k * M_PI / 180.0;
            const double sinT = eta * std::sin(ti);
            const float f = shader::fresnelDielectric(static_cast<float>(std::cos(ti)), static_cast<float>(eta));
            if (sinT >= 1.0)
            {
                EXPECT_EQ(f, 1.0f) << "total internal reflection, eta " << eta << ", " << k << " degrees";
                continue;
            }
            const double tt = std::asin(sinT);
            const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2.0);
            const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2.0);
            EXPECT_NEAR(f, 0.5 * (rs + rp), 2e-5) << "eta " << eta << ", " << k << " degrees";
        }
    // Normal incidence: ((n - 1) / (n + 1))^2, 0.04 for glass, as Schlick's R0.
    EXPECT_NEAR(shader::fresnelDielectric(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
    // At Brewster's angle (tan = 1.5) the parallel part vanishes: R = R_s / 2.
    const double brewster = std::atan(1.5);
    const double tt = std::asin(std::sin(brewster) / 1.5);
    EXPECT_NEAR(shader::fresnelDielectric(static_cast<float>(std::cos(brewster)), 1.0f / 1.5f),
                0.5 * std::pow(std::sin(brewster - tt) / std::sin(brewster + tt), 2.0), 1e-6);
}

TEST(Dielectric, ReflectsWithTheModelsProbability)
{
    // Below the reflectance u reflects, above it refracts: the branch follows the model chosen.
    const vec3 n(0.0f, 1.0f, 0.0f);
    const vec3 d = glm::normalize(vec3(1.0f, -0.18f, 0.0f)); // about 80 degrees from the normal
    const float cosine = -d.y;
    const float exact = shader::fresnelDielectric(cosine, 1.0f / 1.5f);
    const float schlick = shader::schlickReflectance(cosine, 1.0f / 1.5f);
    ASSERT_GT(std::abs(exact - schlick), 0.01f) << "the models must differ here for the test to mean anything";
    const float u = 0.5f * (exact + schlick);
    const bool exactReflects = shader::sampleDielectric(d, n, 1.0f / 1.5f, FresnelModel::Exact, u).y > 0.0f;
    const bool schlickReflects = shader::sampleDielectric(d, n, 1.0f / 1.5f, FresnelModel::Schlick, u).y > 0.0f;
    EXPECT_EQ(exactReflects, u < exact);
    EXPECT_EQ(schlickReflects, u < schlick);
    EXPECT_NE(exactReflects, schlickReflects);
}

TEST(Metal, FuzzIsASphereAroundTheMirrorDirection)
{
    // The thesis' GPU app fuzzed in a fixed world frame: the fuzz must follow the reflected direction.
    // Near-normal incidence: the whole fuzz sphere stays above the surface, so none is absorbed and the
    // mean direction is the mirror direction.
    const vec3 n = glm::normalize(vec3(0.3f, 1.0f, -0.2f));
    const vec3 d = glm::normalize(vec3(-0.1f, -1.0f, 0.3f));
    const vec3 mirror = glm::normalize(reflect(d, n));
    const float fuzz = 0.3f;
    Rng rng(5);
    vec3 mean(0.0f);
    int kept = 0;
    for (int i = 0; i < 200000; ++i)
    {
        vec3 wi;
        ASSERT_TRUE(shader::sampleFuzzyMirror(d, n, fuzz, {rng.nextFloat(), rng.nextFloat()}, wi));
        ASSERT_LE(glm::length(wi - mirror), fuzz * 1.0001f);
        mean += wi;
        ++kept;
    }
    mean /= float(kept);
    EXPECT_GT(glm::dot(glm::normalize(mean), mirror), 0.999f);
    vec3 exact;
    ASSERT_TRUE(shader::sampleFuzzyMirror(d, n, 0.0f, {0.3f, 0.7f}, exact));
    EXPECT_LT(glm::length(exact - mirror), 1e-6f);
}

TEST(Metal, DirectionsBelowTheSurfaceAreAbsorbed)
{
    const vec3 n(0.0f, 1.0f, 0.0f);
    const vec3 grazing = glm::normalize(vec3(1.0f, -0.02f, 0.0f)); // mirror barely above the surface
    Rng rng(6);
    int absorbed = 0;
    for (int i = 0; i < 10000; ++i)
    {
        vec3 wi;
        if (!shader::sampleFuzzyMirror(grazing, n, 1.0f, {rng.nextFloat(), rng.nextFloat()}, wi))
            ++absorbed;
        else
            ASSERT_GT(wi.y, 0.0f);
    }
    EXPECT_GT(absorbed, 1000);
}

TEST(Material, LambertianStaysInTheShadingHemisphere)
{
    const vec3 n = glm::normalize(vec3(-0.4f, 0.2f, 0.9f));
    Rng rng(8);
    double meanCos = 0.0;
    constexpr int kSamples = 200000;
    for (int i = 0; i < kSamples; ++i)
    {
        const vec3 wi = shader::sampleDiffuse(false, n, {rng.nextFloat(), rng.nextFloat()});
        ASSERT_GE(glm::dot(wi, n), -1e-6f);
        meanCos += glm::dot(wi, n);
        EXPECT_NEAR(shader::diffusePdf(false, n, wi), std::fmax(0.0f, glm::dot(wi, n)) / kPi, 1e-6f);
    }
    // E[cos] under cos/pi is 2/3.
    EXPECT_NEAR(meanCos / kSamples, 2.0 / 3.0, 3e-3);
}
} // namespace
} // namespace rt::test
