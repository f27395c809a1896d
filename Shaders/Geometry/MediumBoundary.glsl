// Where a ray is inside a medium's boundary (RTTNW §9): entry and exit parameters t1 < t2 of the whole line,
// which may be negative (the ray may start inside), in the medium's object space.
#ifndef RT_MEDIUM_BOUNDARY_GLSL
#define RT_MEDIUM_BOUNDARY_GLSL

#include "Geometry/Sphere.glsl"
#include "Shared/HostDevice.h"

/// Slab test of the line o + t d against the box [lo, hi]; false if it misses or touches only an edge.
bool boxInterval(vec3 o, vec3 d, vec3 lo, vec3 hi, out float t1, out float t2)
{
    t1 = -3.0e38;
    t2 = 3.0e38;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (d[axis] == 0.0)
        {
            // Parallel to the slab: inside it for every t, or never (no division by zero on the GPU).
            if (o[axis] < lo[axis] || o[axis] > hi[axis])
                return false;
            continue;
        }
        float inverse = 1.0 / d[axis];
        float a = (lo[axis] - o[axis]) * inverse;
        float b = (hi[axis] - o[axis]) * inverse;
        t1 = max(t1, min(a, b));
        t2 = min(t2, max(a, b));
    }
    return t1 < t2;
}

bool mediumInterval(MediumRecord m, vec3 o, vec3 d, out float t1, out float t2)
{
    if (m.boundary == MediumBoundary_Sphere)
    {
        SphereRoots roots;
        bool crosses = sphereRoots(o, d, m.center, m.radius, roots);
        t1 = roots.t0;
        t2 = roots.t1;
        return crosses && t1 < t2;
    }
    return boxInterval(o, d, m.boxMin, m.boxMax, t1, t2);
}

#endif
