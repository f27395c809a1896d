// What a traced ray brings back to the raygen shader (payload location 0). Hit shaders describe the hit;
// all shading (textures, materials, the estimator) happens in raygen.
#ifndef RT_PAYLOAD_GLSL
#define RT_PAYLOAD_GLSL

const uint kHitMedium = 1u; // scattered inside a constant medium: frontFace = true, next origin = position

struct HitPayload
{
    vec3 position; // world-space hit point, computed accurately (barycentrics, re-projection)
    uint material; // kNoIndex: the ray missed
    vec3 normal; // world-space unit geometric normal, outward (arbitrary inside a medium)
    uint flags; // kHitMedium
    vec2 uv;
    float offsetScale; // offsetRayOrigin's scale: the largest |vertex coordinate| of a triangle, else 1
    vec3 background; // radiance of the background on a miss
    uint lightSlot; // primitiveLightSlot of the hit primitive: primitiveLights[lightSlot] is its light, if any
};

#endif
