// Glass (RTIOW §11): refraction by Snell's law, reflection under total internal reflection or with
// Schlick's probability. The weight is 1 (clear glass).
#ifndef RT_DIELECTRIC_GLSL
#define RT_DIELECTRIC_GLSL

#include "Materials/Interaction.glsl"
#include "Math/Constants.glsl"
#include "Random.glsl"

/// Schlick's approximation of the Fresnel reflectance (C. Schlick, "An Inexpensive BRDF Model for
/// Physically-based Rendering", Computer Graphics Forum 13(3), 1994).
float schlickReflectance(float cosine, float refractionIndex)
{
    float r0 = (1.0 - refractionIndex) / (1.0 + refractionIndex);
    r0 *= r0;
    float m = 1.0 - cosine;
    return r0 + (1.0 - r0) * (m * m) * (m * m) * m;
}

bool scatterDielectric(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    float ri = hit.frontFace ? 1.0 / m.ior : m.ior; // eta_incident / eta_transmitted
    vec3 ud = normalize(hit.incoming);
    vec3 ns = hit.shadingNormal;
    float cosTheta = min(dot(-ud, ns), 1.0);
    float sin2Theta = 1.0 - cosTheta * cosTheta;
    s.weight = vec3(1.0);
    // Total internal reflection (ri sin(theta) > 1), or reflection with Schlick's probability. The random
    // number is drawn only when refraction is possible, like the CPU engine's short-circuit ||.
    if (ri * ri * sin2Theta > 1.0 || schlickReflectance(cosTheta, ri) > nextFloat(rng))
    {
        s.direction = reflect(ud, ns);
        return true;
    }
    vec3 perpendicular = ri * (ud + cosTheta * ns);
    vec3 parallel = -sqrt(abs(1.0 - lengthSquared(perpendicular))) * ns;
    s.direction = perpendicular + parallel;
    return true;
}

#endif
