// Scattering by material type tag (HostDevice.h MaterialType), the twin of the CPU engine's dispatch.
#ifndef RT_SCATTER_GLSL
#define RT_SCATTER_GLSL

#include "Materials/Dielectric.glsl"
#include "Materials/Isotropic.glsl"
#include "Materials/Lambertian.glsl"
#include "Materials/Metal.glsl"

/// False when the path ends here (absorbed, a light, a failed light sample).
bool scatter(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    s.direction = vec3(0.0);
    s.weight = vec3(0.0);
    switch (m.type)
    {
    case MaterialType_Lambertian: return scatterLambertian(m, hit, rng, s);
    case MaterialType_Metal: return scatterMetal(m, hit, rng, s);
    case MaterialType_Dielectric: return scatterDielectric(m, hit, rng, s);
    case MaterialType_Isotropic: return scatterIsotropic(m, hit, rng, s);
    }
    return false; // DiffuseLight: emits, does not scatter
}

#endif
