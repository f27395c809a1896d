#include "Support/MicrofacetReferences.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Support/LobeDomain.h"

namespace rt::test
{
namespace
{
constexpr double kPiD = 3.14159265358979323846;
using glm::dvec3;
} // namespace

double lambdaRef(const dvec3& w, double ax, double ay)
{
    const double a2Tan2 = (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z);
    return 0.5 * (std::sqrt(1.0 + a2Tan2) - 1.0);
}

double g1Ref(const dvec3& w, double ax, double ay)
{
    return 1.0 / (1.0 + lambdaRef(w, ax, ay));
}

double g2Ref(const dvec3& wo, const dvec3& wi, double ax, double ay)
{
    return 1.0 / (1.0 + lambdaRef(wo, ax, ay) + lambdaRef(wi, ax, ay));
}

double fresnelRef(double cosI, std::complex<double> n)
{
    const double sin2 = std::max(0.0, 1.0 - cosI * cosI);
    const std::complex<double> nCosT = std::sqrt(n * n - sin2);
    const std::complex<double> rs = (cosI - nCosT) / (cosI + nCosT);
    const std::complex<double> rp = (n * n * cosI - nCosT) / (n * n * cosI + nCosT);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

double ggxReflectanceRef(double mu, double alpha, const std::function<double(double cosOH)>& fresnel)
{
    constexpr int n = 1024;
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    const dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double beta = x[i] * kPiD / 2.0, wBeta = w[i] * kPiD / 2.0;
        const double tanBeta = std::tan(beta);
        const double thetaH = std::atan(alpha * tanBeta);
        const double dThetaH =
            alpha / (std::cos(beta) * std::cos(beta)) / (1.0 + alpha * alpha * tanBeta * tanBeta);
        const double cosH = std::cos(thetaH), sinH = std::sin(thetaH);
        // Walter 2007 eq. 33 with tan^2 = alpha^2 tan^2(beta).
        const double d =
            1.0 / (kPiD * alpha * alpha * std::pow(cosH, 4) * std::pow(1.0 + tanBeta * tanBeta, 2));
        for (int j = 0; j < n; ++j)
        {
            // phi in [0, pi], doubled: the integrand is symmetric about the plane of incidence.
            const double phi = x[j] * kPiD, wPhi = 2.0 * w[j] * kPiD;
            const dvec3 h(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
            const double oh = glm::dot(wo, h);
            if (oh <= 0.0)
                continue;
            const dvec3 wi = 2.0 * oh * h - wo;
            if (wi.z <= 0.0)
                continue;
            const double f = d * g2Ref(wo, wi, alpha, alpha) * fresnel(oh) / (4.0 * mu); // times mu_i / mu_i
            sum += f * 4.0 * oh * sinH * dThetaH * wBeta * wPhi;
        }
    }
    return sum;
}

double ggxAlbedoRef(double mu, double alpha)
{
    return ggxReflectanceRef(mu, alpha, [](double) { return 1.0; });
}
} // namespace rt::test
