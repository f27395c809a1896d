// Scattering by material type tag (HostDevice.h MaterialType), the twin of the CPU engine's dispatch. A
// material the pipeline's scene does not use is dead code (kHas*, Specialization.glsl).
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
    case MaterialType_Lambertian:
        if (kHasLambertian)
            return scatterLambertian(m, hit, rng, s);
        break;
    case MaterialType_Metal:
        if (kHasMetal)
            return scatterMetal(m, hit, rng, s);
        break;
    case MaterialType_Dielectric:
        if (kHasDielectric)
            return scatterDielectric(m, hit, rng, s);
        break;
    case MaterialType_Isotropic:
        if (kHasIsotropic)
            return scatterIsotropic(m, hit, rng, s);
        break;
    }
    return false; // DiffuseLight: emits, does not scatter
}

#endif
