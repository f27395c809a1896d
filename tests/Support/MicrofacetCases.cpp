#include "Support/MicrofacetCases.h"

#include "Math/Math.h"

#include <cmath>
#include <sstream>

namespace rt::test
{
namespace
{
constexpr double kPiD = 3.14159265358979323846;
} // namespace

const std::vector<float> kMicrofacetAlphas = {0.001f, 0.01f, 0.1f, 0.5f, 1.0f};

dvec3 direction(double thetaDegrees, double phiDegrees)
{
    if (thetaDegrees == 0.0)
        return {0.0, 0.0, 1.0};
    const double t = thetaDegrees * kPiD / 180.0, p = phiDegrees * kPiD / 180.0;
    return dvec3(
        vec3(glm::normalize(dvec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)))));
}

dvec3 visibleAxis(const dvec3& wo, double ax, double ay)
{
    if (wo.x == 0.0 && wo.y == 0.0)
        return {0.0, 0.0, 1.0};
    const dvec3 b = glm::normalize(glm::normalize(dvec3(ax * wo.x, ay * wo.y, wo.z)) + dvec3(0.0, 0.0, 1.0));
    return glm::normalize(dvec3(ax * b.x, ay * b.y, b.z));
}

LobeDomain normalCells(const dvec3& woUp, double ax, double ay, std::vector<Crease> creases)
{
    return LobeDomain({LobeCap{visibleAxis(woUp, ax, ay), 0.5 * ax * ay, Side::Upper}}, std::move(creases));
}

WarpedPart reflectionPart(const dvec3& wo, double ax, double ay)
{
    const double side = wo.z > 0.0 ? 1.0 : -1.0;
    auto reflected = [wo, side](const dvec3& x, double& cosine)
    {
        const dvec3 n = side * x; // the normal facing wo
        cosine = glm::dot(wo, n);
        return 2.0 * cosine * n - wo;
    };
    const Crease horizon = [=](const dvec3& x)
    {
        double cosine;
        return side * reflected(x, cosine).z;
    };
    const Crease facing = [=](const dvec3& x) { return side * glm::dot(wo, x); };
    return {normalCells(side * wo, ax, ay, {horizon, facing}),
            [=](const dvec3& wi, dvec3& x)
            {
                if (!(wi.z * side > 0.0))
                    return false;
                x = side * glm::normalize(wo + wi);
                return true;
            },
            [=](const dvec3& x, dvec3& wi, double& jacobian)
            {
                double cosine;
                wi = reflected(x, cosine);
                jacobian = 4.0 * cosine;
                return cosine > 0.0 && wi.z * side > 0.0;
            }};
}

WarpedDomain reflectionDomain(const dvec3& wo, double ax, double ay)
{
    return WarpedDomain({reflectionPart(wo, ax, ay)});
}

std::vector<DistributionCase> distributionCases(double grazingPeaked, double grazingBroad)
{
    std::vector<DistributionCase> cases;
    for (float a : kMicrofacetAlphas)
        for (double theta : {0.0, a <= 0.01f ? grazingPeaked : grazingBroad})
            cases.push_back({"alpha " + std::to_string(a) + ", theta_o " + std::to_string(theta), a, a,
                             direction(theta)});
    for (double theta : {0.0, grazingBroad})
        cases.push_back(
            {"alpha (0.05, 0.4), theta_o " + std::to_string(theta), 0.05f, 0.4f, direction(theta)});
    return cases;
}

std::vector<DistributionCase> conductorCases()
{
    return distributionCases(85.0, 89.0);
}

std::vector<DielectricCase> dielectricCases()
{
    std::vector<DielectricCase> cases;
    for (float a : kMicrofacetAlphas)
        for (float ior : {1.5f, 1.0f / 1.5f})
            for (bool inside : {false, true})
                for (double theta : {0.0, a <= 0.01f ? 85.0 : 89.0})
                {
                    dvec3 wo = direction(theta);
                    if (inside)
                        wo.z = -wo.z;
                    std::ostringstream name;
                    name << "alpha " << a << ", ior " << ior << ", wo " << (inside ? "inside" : "outside")
                         << " at " << theta << " degrees";
                    cases.push_back({name.str(), a, ior, wo});
                }
    return cases;
}

WarpedPart refractionPart(const dvec3& wo, double alpha, double ior)
{
    const double side = wo.z > 0.0 ? 1.0 : -1.0;
    const double etaPrime = wo.z > 0.0 ? ior : 1.0 / ior;
    const double etaRatio = 1.0 / etaPrime; // eta_wo / eta_wi
    // The refraction of wo through x, and 1 - sin^2(theta_t): <= 0 under total reflection.
    auto refracted = [=](const dvec3& x, dvec3& wi)
    {
        const dvec3 n = side * x;
        const double cosI = glm::dot(wo, n);
        const double cos2T = 1.0 - etaRatio * etaRatio * (1.0 - cosI * cosI);
        if (cosI > 0.0 && cos2T > 0.0)
            wi = -etaRatio * wo + (etaRatio * cosI - std::sqrt(cos2T)) * n;
        return cos2T;
    };
    const Crease horizon = [=](const dvec3& x)
    {
        dvec3 wi(0.0, 0.0, side);
        refracted(x, wi);
        return -side * wi.z;
    };
    const Crease facing = [=](const dvec3& x) { return side * glm::dot(wo, x); };
    const Crease totalReflection = [=](const dvec3& x)
    {
        dvec3 wi;
        return refracted(x, wi);
    };
    return {normalCells(side * wo, alpha, alpha, {horizon, facing, totalReflection}),
            [=](const dvec3& wi, dvec3& x)
            {
                if (!(wi.z * side < 0.0))
                    return false;
                x = glm::normalize(wo + etaPrime * wi);
                if (x.z < 0.0)
                    x = -x;
                return true;
            },
            [=](const dvec3& x, dvec3& wi, double& jacobian)
            {
                wi = dvec3(0.0, 0.0, side);
                if (!(refracted(x, wi) > 0.0) || !(side * glm::dot(wo, x) > 0.0) || !(wi.z * side < 0.0))
                    return false;
                const double s = glm::dot(wi, x) + glm::dot(wo, x) / etaPrime;
                jacobian = s * s / std::fabs(glm::dot(wi, x));
                return true;
            }};
}

WarpedDomain dielectricDomain(const DielectricCase& c)
{
    return WarpedDomain({reflectionPart(c.wo, c.alpha, c.alpha), refractionPart(c.wo, c.alpha, c.ior)});
}

std::vector<DistributionCase> gltfCases()
{
    std::vector<DistributionCase> cases;
    for (const auto& c : conductorCases())
        if (c.alphaX == c.alphaY)
            cases.push_back(c);
    return cases;
}

WarpedDomain gltfDomain(const DistributionCase& c)
{
    return reflectionDomain(c.wo, c.alphaX, c.alphaX);
}
} // namespace rt::test
