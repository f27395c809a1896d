// Where a ray hit a sphere, written once for both engines (Shared/ShaderLang.h). Re-projecting o + t d onto
// the sphere (centre + radius n) removes the ray's error but adds the sphere's: both are rounding at the
// magnitude of the numbers involved, ulp(|o| + t |d|) against ulp(|centre| + radius). For a ball near the
// camera the sphere's is the smaller; for a huge sphere seen from near its surface (a 1e6-radius ground:
// ulp 0.06, while the ray's is 1e-6) the ray's is, and re-projection put the shading points up to 0.03 units
// off the ground (tests/Cpu/StressTest.cpp StressGroundSphere). So the smaller of the two is taken.
#ifndef RT_SHARED_SPHERE_HIT_POINT_H
#define RT_SHARED_SPHERE_HIT_POINT_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

RT_FN float largestMagnitude(vec3 v) { return max(abs(v.x), max(abs(v.y), abs(v.z))); }

/// The hit point of the ray o + t d on the sphere (center, radius) with outward unit normal n at it.
RT_FN vec3 sphereHitPoint(vec3 o, vec3 d, float t, vec3 center, float radius, vec3 n)
{
    const float sphereMagnitude = largestMagnitude(center) + radius;
    const float rayMagnitude = largestMagnitude(o) + t * largestMagnitude(d);
    return sphereMagnitude > rayMagnitude ? o + t * d : center + radius * n;
}

RT_SHADER_NAMESPACE_END

#endif
