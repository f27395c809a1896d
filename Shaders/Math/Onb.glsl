// Orthonormal basis around a unit vector w (Common/Math/Onb.h): local (x, y, z) -> world x u + y v + z w.
// Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
#ifndef RT_ONB_GLSL
#define RT_ONB_GLSL

struct Onb
{
    vec3 u;
    vec3 v;
    vec3 w;
};

Onb onbFromNormal(vec3 n)
{
    // copysign(1, n.z) exactly, -0 included (GLSL's sign() returns 0 for 0).
    float s = (floatBitsToUint(n.z) & 0x80000000u) != 0u ? -1.0 : 1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    Onb onb;
    onb.u = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    onb.v = vec3(b, s + n.y * n.y * a, -n.y);
    onb.w = n;
    return onb;
}

vec3 onbToWorld(Onb onb, vec3 local)
{
    return local.x * onb.u + local.y * onb.v + local.z * onb.w;
}

#endif
