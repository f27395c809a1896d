// Glass (RTIOW §11): refraction by Snell's law, reflection under total internal reflection or with
// Schlick's probability. The weight is 1 (clear glass).
#ifndef RT_DIELECTRIC_GLSL
#define RT_DIELECTRIC_GLSL

#include "Materials/Interaction.glsl"
#include "Random.glsl"

/// Schlick's approximation of the Fresnel reflectance (C. Schlick, "An Inexpensive BRDF Model for
/// Physically-based Rendering", Computer Graphics Forum 13(3), 1994).
float schlickReflectance(float cosine, float refractionIndex)
{
    float r0 = (1.0 - refractionIndex) / (1.0 + refractionIndex);
    r0 = r0 * r0;
    return r0 + (1.0 - r0) * pow(1.0 - cosine, 5.0);
}

/// RTIOW's refraction of the unit direction uv about n (n against uv), eta = eta_incident / eta_transmitted.
vec3 refractRtiow(vec3 uv, vec3 n, float etaiOverEtat)
{
    float cosTheta = min(dot(-uv, n), 1.0);
    vec3 perpendicular = etaiOverEtat * (uv + cosTheta * n);
    vec3 parallel = -sqrt(abs(1.0 - lengthSquared(perpendicular))) * n;
    return perpendicular + parallel;
}

bool scatterDielectric(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    float ri = hit.frontFace ? 1.0 / m.ior : m.ior;
    vec3 ud = normalize(hit.incoming);
    float cosTheta = min(dot(-ud, hit.shadingNormal), 1.0);
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    bool cannotRefract = ri * sinTheta > 1.0;
    // The random number is drawn only when refraction is possible (the CPU's short-circuit ||).
    if (cannotRefract || schlickReflectance(cosTheta, ri) > nextFloat(rng))
        s.direction = reflect(ud, hit.shadingNormal);
    else
        s.direction = refractRtiow(ud, hit.shadingNormal, ri);
    s.weight = vec3(1.0);
    return true;
}

#endif
