// Orthonormal basis around a unit vector w: local (x, y, z) -> world x u + y v + z w, written once for both
// engines (Shared/ShaderLang.h). Branchless construction from Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017.
#ifndef RT_SHARED_ONB_H
#define RT_SHARED_ONB_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

struct Onb
{
    vec3 u;
    vec3 v;
    vec3 w;
};

/// The basis whose w is the unit vector `n`.
RT_FN Onb onbFromNormal(vec3 n)
{
    const float s = signNotZero(n.z);
    const float a = -1.0f / (s + n.z);
    const float b = n.x * n.y * a;
    Onb onb;
    onb.u = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    onb.v = vec3(b, s + n.y * n.y * a, -n.y);
    onb.w = n;
    return onb;
}

RT_FN vec3 onbToWorld(RT_IN(Onb) onb, vec3 local) { return local.x * onb.u + local.y * onb.v + local.z * onb.w; }

/// The inverse of onbToWorld: world -> (x, y, z) along (u, v, w).
RT_FN vec3 onbToLocal(RT_IN(Onb) onb, vec3 world) { return vec3(dot(world, onb.u), dot(world, onb.v), dot(world, onb.w)); }

RT_SHADER_NAMESPACE_END

#endif
