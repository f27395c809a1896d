#include "Support/MicrofacetSphere.h"

#include "Scene/SceneBuilder.h"
#include "Scenes/SceneFactories.h"
#include "Support/MicrofacetCases.h"
#include "Support/MicrofacetReferences.h"
#include "Support/PixelStatistics.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>

namespace rt::test
{
namespace
{
constexpr double kPiD = 3.14159265358979323846;
constexpr double kGlassIor = 1.5;
} // namespace

std::vector<MicrofacetSphereCase> microfacetSphereCases()
{
    std::vector<MicrofacetSphereCase> cases;
    for (const bool conductor : {true, false})
        for (const float alpha :
             conductor ? std::vector<float>{0.05f, 0.3f, 0.8f} : std::vector<float>{0.05f, 0.3f})
            for (const double theta : {0.0, 60.0})
                cases.push_back({std::string(conductor ? "copper" : "glass") + " alpha " +
                                     std::to_string(alpha) + " at " + std::to_string(int(theta)) + " degrees",
                                 conductor, alpha, theta});
    return cases;
}

Scene microfacetSphereScene(const MicrofacetSphereCase& c)
{
    SceneBuilder b("microfacet-sphere");
    const std::uint32_t material = c.conductor
                                       ? b.conductor(kCopperEta, kCopperK, c.alpha, c.alpha)
                                       : b.roughDielectric(c.alpha, float(kGlassIor));
    b.sphere(b.world(), vec3(0.0f), 1.0f, material);
    Scene& s = b.scene();
    const double t = c.thetaDegrees * kPiD / 180.0;
    const vec3 patch(0.0f, 0.0f, 1.0f); // its normal is +z
    s.camera.lookAt = patch;
    s.camera.lookFrom = patch + 10.0f * vec3(float(std::sin(t)), 0.0f, float(std::cos(t)));
    s.camera.vfovDegrees = 0.005f;
    s.camera.focusDistance = 10.0f;
    s.camera.defocusAngleDegrees = 0.0f;
    scenes::setConstantBackground(s, vec3(1.0f));
    return b.finish();
}

int microfacetSphereDepth(const MicrofacetSphereCase& c)
{
    return c.conductor ? 8 : 2;
}

glm::dvec3 microfacetSphereReference(const MicrofacetSphereCase& c)
{
    const double mu = std::cos(c.thetaDegrees * kPiD / 180.0);
    glm::dvec3 out;
    for (int ch = 0; ch < 3; ++ch)
    {
        const std::complex<double> n = c.conductor ? std::complex<double>(kCopperEta[ch], kCopperK[ch])
                                                   : std::complex<double>(kGlassIor, 0.0);
        out[ch] = ggxReflectanceRef(mu, c.alpha, [n](double cosOH) { return fresnelRef(cosOH, n); });
    }
    return out;
}

void expectMicrofacetSphere(const Image& image, const MicrofacetSphereCase& c)
{
    const glm::dvec3 reference = microfacetSphereReference(c);
    for (int ch = 0; ch < 3; ++ch)
    {
        const MeanAndError m = pixelStatistics(image, ch);
        EXPECT_NEAR(m.mean, reference[ch], 4.0 * m.standardError + 5e-4)
            << c.name << ", channel " << ch << " (standard error " << m.standardError << ")";
    }
}
} // namespace rt::test
