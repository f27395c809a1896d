// Direct lighting with a closed form (research notes §4): a Lambertian floor of albedo rho under one light,
// seen through a narrow camera, rendered with two segments (camera -> floor -> light). Each pixel's expected
// radiance is rho / pi * E(x) at the floor point x it sees, with E the analytic irradiance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "RenderTestSupport.h"
#include "Scene/SceneBuilder.h"

namespace rt::test
{
namespace
{
constexpr float kAlbedo = 0.5f;
constexpr float kRadiance = 4.0f;

/// A floor (y = 0, normal +y) seen from above and aside, looking at `target`.
Scene floorScene(const std::function<void(SceneBuilder&, std::uint32_t)>& addLight, const vec3& target)
{
    SceneBuilder b("direct-lighting");
    const std::uint32_t w = b.world();
    // Small: rays leave the floor from points offset in proportion to its largest coordinate (RayOffset.h), and
    // NEE's precision (a standard error of 5e-5) sees the irradiance of a 100-unit floor's offset (+0.07 %).
    b.quad(w, {-3.0f, 0.0f, 3.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -6.0f}, b.lambertian(vec3(kAlbedo)));
    addLight(b, w);
    Scene& s = b.scene();
    s.camera.lookFrom = target + vec3(3.0f, 4.0f, 5.0f);
    s.camera.lookAt = target;
    s.camera.vfovDegrees = 4.0f;
    s.background = {BackgroundType::Constant, vec3(0.0f), vec3(0.0f)};
    return b.finish();
}

/// Floor point seen through the centre of pixel (x, y).
vec3 floorPoint(const Scene& scene, const RenderSettings& s, int x, int y)
{
    const Camera camera(scene.camera, s.width, s.height());
    const Ray r = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f, vec2(0.0f), 0.0f);
    const float t = -r.origin.y / r.direction.y;
    return r.at(t);
}

/// Mean of (pixel - expected) over the image is 0 within 3 standard errors, and the relative bias is small.
void expectMatches(const Scene& scene, const RenderSettings& s, const std::function<double(const vec3&)>& irradiance)
{
    const RenderResult r = renderCpu(scene, s);
    ASSERT_EQ(r.stats.nanSamples + r.stats.infSamples, 0u);
    double sum = 0.0, sum2 = 0.0, expectedSum = 0.0;
    const int n = s.width * s.height();
    for (int y = 0; y < s.height(); ++y)
        for (int x = 0; x < s.width; ++x)
        {
            const double expected = kAlbedo / kPi * irradiance(floorPoint(scene, s, x, y));
            const double d = r.image.at(x, y).x - expected;
            sum += d;
            sum2 += d * d;
            expectedSum += expected;
        }
    const double meanDiff = sum / n;
    const double se = std::sqrt((sum2 / n - meanDiff * meanDiff) / (n - 1));
    // Plus 1e-4 of the value: rays leave from points offset ~5e-5 above this floor (RayOffset.h), where the
    // irradiance differs by ~2e-5 relative; NEE with projected caps has almost no variance and sees it.
    EXPECT_NEAR(meanDiff, 0.0, 3.0 * se + 1e-4 * expectedSum / n)
        << "expected mean radiance " << expectedSum / n << ", standard error " << se;
    EXPECT_LT(std::fabs(meanDiff) / (expectedSum / n), 0.02);
}

class DirectLighting : public ::testing::TestWithParam<Estimator>
{
};

TEST_P(DirectLighting, SphereLightAboveTheHorizonGivesPointLightIrradiance)
{
    // A sphere fully above the tangent plane: E = pi L (R / d)^2 cos(theta) (notes §4.1).
    const vec3 center(0.5f, 2.0f, -0.3f);
    const float radius = 0.6f;
    const Scene scene = floorScene([&](SceneBuilder& b, std::uint32_t w) {
        b.sphere(w, center, radius, b.diffuseLight(vec3(kRadiance)));
    }, vec3(0.0f));
    RenderSettings s = smallSettings(40, GetParam() == Estimator::Mixture ? 64 : 512, 2, GetParam());
    expectMatches(scene, s, [&](const vec3& x) {
        const vec3 toCenter = center - x;
        const double d2 = glm::dot(toCenter, toCenter);
        const double cosTheta = toCenter.y / std::sqrt(d2);
        return kPi * kRadiance * radius * radius / d2 * cosTheta;
    });
}

TEST_P(DirectLighting, RectangleParallelToTheFloorMatchesTheFormFactor)
{
    // An a x b rectangle at height c, facing down, one corner straight above the target point; the floor
    // points near the target see it through the superposition of four corner rectangles (notes §4.3).
    const float a = 1.5f, bLen = 1.0f, c = 1.2f;
    const vec3 corner(0.0f, c, 0.0f);
    const Scene scene = floorScene([&](SceneBuilder& b, std::uint32_t w) {
        // u x v must point down (-y) so the light's front faces the floor.
        b.quad(w, corner, {a, 0.0f, 0.0f}, {0.0f, 0.0f, bLen}, b.diffuseLight(vec3(kRadiance)));
    }, vec3(0.1f, 0.0f, 0.2f));
    const auto cornerFactor = [](double aa, double bb, double cc) {
        // Signed form factor of an aa x bb rectangle with a corner above the point (signs carry superposition).
        const double A = aa / cc, B = bb / cc;
        const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
        return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * kPi);
    };
    RenderSettings s = smallSettings(40, GetParam() == Estimator::Mixture ? 64 : 512, 2, GetParam());
    expectMatches(scene, s, [&](const vec3& x) {
        // Rectangle spans [0, a] in x and [0, bLen] in z; x sees it as four corner rectangles.
        const double x0 = 0.0 - x.x, x1 = a - x.x, z0 = 0.0 - x.z, z1 = bLen - x.z;
        const auto f = [&](double ex, double ez) {
            return (ex >= 0 ? 1 : -1) * (ez >= 0 ? 1 : -1) * cornerFactor(std::fabs(ex), std::fabs(ez), c);
        };
        const double formFactor = f(x1, z1) - f(x0, z1) - f(x1, z0) + f(x0, z0);
        return kRadiance * kPi * formFactor; // E = L * projected solid angle = L * pi * F
    });
}

INSTANTIATE_TEST_SUITE_P(Estimators, DirectLighting,
                         ::testing::Values(Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis),
                         [](const auto& param) {
                             std::string name = toString(param.param);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });
} // namespace
} // namespace rt::test
