// The uniform number that decides where a ray scatters inside a constant medium. An intersection shader
// cannot read the payload (the path's Rng), so the number is a PCG hash of what the shader can see: the
// path's pixel (tracedPixel()), the ray in object space (bits of origin and direction: distinct per path segment, and per
// sample, whose camera rays differ by their jitter), the instance and primitive. Deterministic: an
// implementation may run an intersection shader more than once per ray and primitive, and must get the same
// answer each time. Not the sample index: the shader sees only the first sample of its launch
// (push.firstSample), and the launches follow the render driver's batches, which are cut by time, so an
// image of a medium depended on how fast its first batch ran (a pipeline compiled at the first launch, as
// lavapipe does, changed rtnw-cornell-smoke's image: GpuDeterminism.SameSeedTwiceGivesTheSameImage).
#ifndef RT_MEDIUM_RANDOM_GLSL
#define RT_MEDIUM_RANDOM_GLSL

#include "Shared/Random.h"

/// In (0, 1]: usable in log(u).
float mediumUniform(uvec2 launch, vec3 origin, vec3 direction, uint instance, uint primitive, uint seed)
{
    uint h = pcgHash(seed);
    h = pcgHash(h ^ launch.x);
    h = pcgHash(h ^ launch.y);
    uvec3 o = floatBitsToUint(origin);
    uvec3 d = floatBitsToUint(direction);
    h = pcgHash(h ^ o.x);
    h = pcgHash(h ^ o.y);
    h = pcgHash(h ^ o.z);
    h = pcgHash(h ^ d.x);
    h = pcgHash(h ^ d.y);
    h = pcgHash(h ^ d.z);
    h = pcgHash(h ^ instance);
    h = pcgHash(h ^ primitive);
    return 1.0 - float(h >> 8) * (1.0 / 16777216.0);
}

#endif
