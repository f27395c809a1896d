// The uv of a point of a quad that the GPU engine stores as two triangles (RayTracing/SceneLayout.cpp): the
// quad Q + a u + b v is split into triangles 2k = (Q, Q+u, Q+u+v) and 2k + 1 = (Q, Q+u+v, Q+v), whose corner
// uvs (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1) interpolate to the quad's edge coordinates (a, b). Computed from
// the triangle's parity and the barycentrics instead of read from a uv buffer: the three loads cost the H100
// 7 % of book 3's mixture on cornell-box-lights. Written once for the hit shader and its C++ test.
#ifndef RT_SHARED_QUAD_UV_H
#define RT_SHARED_QUAD_UV_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// (a, b) of the point with barycentrics (b1, b2) of triangle `primitive` of a quad record: b0 (0,0) + b1 uv1 +
/// b2 uv2 with the corner uvs above, the same float values as interpolating them (every product is by 0 or 1).
RT_FN vec2 quadUv(uint primitive, float b1, float b2)
{
    return (primitive & 1u) == 0u ? vec2(b1 + b2, b2) : vec2(b1, b1 + b2);
}

RT_SHADER_NAMESPACE_END

#endif
