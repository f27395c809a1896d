// The hit a material scatters at, and what scattering produces.
#ifndef RT_INTERACTION_GLSL
#define RT_INTERACTION_GLSL

struct SurfaceHit
{
    vec3 position; // world space
    vec3 normal; // unit geometric normal, outward
    vec3 shadingNormal; // `normal` turned against the incoming ray (ns)
    bool frontFace; // the ray arrived on the outward side (always true in a medium)
    vec2 uv;
    vec3 incoming; // direction of the arriving ray (not necessarily unit)
};

struct ScatterSample
{
    vec3 direction; // of the next ray (not necessarily unit)
    vec3 weight; // multiplies the path throughput beta
};

#endif
