// What the path vertex (Shared/Shading/PathVertex.h) carries and hands on, for both engines
// (Shared/ShaderLang.h): a path between two vertices, the shadow ray of next-event estimation, the surface a
// material scatters at, a scattered direction and a camera sample. Plain structs; the GPU's wavefront keeps
// PathState in its kWave* fields between kernels (Shaders/Wavefront/WavePath.glsl).
#ifndef RT_SHARED_PATH_STATE_H
#define RT_SHARED_PATH_STATE_H

#include "Shared/Random.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// One camera path between two of its vertices.
struct PathState
{
    vec3 origin; // the ray to trace next, world space; the direction need not be unit length
    vec3 direction;
    vec3 radiance; // gathered so far (linear RGB)
    vec3 beta; // throughput
    // A roulette decided at the last vertex, applied once this segment's emission is gathered
    // (rouletteAfterNextHit): 0 ends the path, else the throughput is scaled by 1 / pendingSurvival.
    float pendingSurvival;
    // The vertex the current ray left, for the MIS weight of the emission it finds: the ray's origin, the
    // receiver normal there for the projected samplers (0 in a medium) and the BSDF strategy's solid-angle pdf
    // of the ray's direction; 0 when NEE did not run there (the camera, a specular vertex): the emission counts
    // in full; negated after restir-di's resampled vertex, where that emission counts 0 (Shading/PathVertex.h).
    vec3 previousPoint;
    vec3 previousNormal;
    float previousBsdfPdf;
    Rng rng; // the camera sample's stream
};

/// A path about to trace its camera ray (origin, direction) with the numbers of `rng`.
RT_FN PathState startPath(vec3 origin, vec3 direction, Rng rng)
{
    PathState path;
    path.origin = origin;
    path.direction = direction;
    path.radiance = vec3(0.0f);
    path.beta = vec3(1.0f);
    path.pendingSurvival = 1.0f;
    path.previousPoint = vec3(0.0f);
    path.previousNormal = vec3(0.0f);
    path.previousBsdfPdf = 0.0f;
    path.rng = rng;
    return path;
}

/// NEE's shadow ray of a vertex: when `pending`, `contribution` (radiance, throughput included) counts if nothing
/// lies between origin and origin + distance direction.
struct ShadowRay
{
    bool pending;
    vec3 origin;
    vec3 direction; // unit
    float distance;
    vec3 contribution;
    // NEE's light sample at the vertex, for the stats: kLightSampleDrawn with the sample's outcome
    // (Lights/LightSample.h: made by a fallback sampler, declined), 0 when the vertex drew none.
    uint lightSample;
};

/// The hit a material scatters at.
struct SurfaceHit
{
    vec3 position; // world space
    vec3 normal; // unit geometric normal, outward
    vec3 shadingNormal; // `normal` turned against the incoming ray (ns)
    bool frontFace; // the ray arrived on the outward side (always true in a medium)
    vec2 uv;
    vec3 incoming; // direction of the arriving ray (not necessarily unit)
};

/// A direction a material scattered into.
struct ScatterSample
{
    vec3 direction; // of the next ray (not necessarily unit)
    vec3 weight; // multiplies the path throughput beta
};

/// The numbers of a camera sample that place its ray (Shared/Shading/Camera.h).
struct CameraSample
{
    vec2 raster; // continuous raster position, pixel centres at +0.5, y down
    vec2 lens; // in [0, 1)^2, used only with a thin lens
    float time; // in [shutterOpen, shutterClose)
};

RT_SHADER_NAMESPACE_END

#endif
