// Moves a surface point off the surface along the geometric normal n (pointing to the side the new ray
// leaves from), so the new ray, started with tmin = 0, does not hit the surface it leaves.
// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, 2019,
// scaled by the largest coordinate the surface's intersection test computes with (see Common/Math/RayOffset.h:
// NVIDIA's triangle test errs by ulps of the vertices, not of p).
// The twin of Common/Math/RayOffset.h, bit for bit (the float path is `precise`: no fused multiply-add).
#ifndef RT_RAY_OFFSET_GLSL
#define RT_RAY_OFFSET_GLSL

vec3 offsetRayOrigin(vec3 p, vec3 n, float scale)
{
    float s = scale > 1.0 ? scale : 1.0;
    float origin = s * (1.0 / 32.0);
    float floatOffset = s * (1.0 / 65536.0);
    const float kIntScale = 256.0;
    ivec3 offset = ivec3(kIntScale * n);
    ivec3 bits = floatBitsToInt(p);
    vec3 moved = intBitsToFloat(ivec3(bits.x + (p.x < 0.0 ? -offset.x : offset.x),
                                      bits.y + (p.y < 0.0 ? -offset.y : offset.y),
                                      bits.z + (p.z < 0.0 ? -offset.z : offset.z)));
    precise vec3 near = p + floatOffset * n;
    return vec3(abs(p.x) < origin ? near.x : moved.x,
                abs(p.y) < origin ? near.y : moved.y,
                abs(p.z) < origin ? near.z : moved.z);
}

/// The scale of offsetRayOrigin for a planar primitive: its largest |vertex coordinate|, world space.
float planarOffsetScale(vec3 a, vec3 b, vec3 c)
{
    vec3 m = max(abs(a), max(abs(b), abs(c)));
    return max(m.x, max(m.y, m.z));
}

#endif
