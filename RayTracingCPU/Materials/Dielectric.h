#pragma once

#include <cmath>

#include "Math/Math.h"

namespace rt::cpu
{
/// Schlick's approximation of the Fresnel reflectance (Schlick, "An Inexpensive BRDF Model for
/// Physically-based Rendering", Computer Graphics Forum 13(3), 1994), RTIOW §11.4.
inline float schlickReflectance(float cosine, float etaRatio)
{
    float r0 = (1.0f - etaRatio) / (1.0f + etaRatio);
    r0 *= r0;
    const float m = 1.0f - cosine;
    return r0 + (1.0f - r0) * (m * m) * (m * m) * m;
}

/// Glass (RTIOW §11): reflect on total internal reflection or with probability Schlick(cos), else refract
/// by Snell's law. `ns` faces the incoming ray, `etaRatio` = eta_incident / eta_transmitted. Weight 1.
inline vec3 scatterDielectric(const vec3& d, const vec3& ns, float etaRatio, float u)
{
    const vec3 ud = glm::normalize(d);
    const float cosTheta = minf(glm::dot(-ud, ns), 1.0f);
    const float sin2Theta = 1.0f - cosTheta * cosTheta;
    if (etaRatio * etaRatio * sin2Theta > 1.0f || schlickReflectance(cosTheta, etaRatio) > u)
        return reflect(ud, ns);
    const vec3 perpendicular = etaRatio * (ud + cosTheta * ns);
    const vec3 parallel = -std::sqrt(std::fabs(1.0f - lengthSquared(perpendicular))) * ns;
    return perpendicular + parallel;
}
} // namespace rt::cpu
