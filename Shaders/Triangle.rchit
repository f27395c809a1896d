// Closest hit on a triangle BLAS (meshes and quads): the world-space point from the barycentrics of the
// world-space corners (accurate, unlike o + t d), the geometric normal of their counter-clockwise winding,
// the uv (a quad's edge coordinates, a mesh's vertex uvs, else the barycentrics (b1, b2)) and the material.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#include "Bindings.glsl"
#include "Payload.glsl"
#include "Shared/RayOffset.h"
#include "Shared/QuadUv.h"

layout(location = kPayloadPath) rayPayloadInEXT HitPayload payload;
hitAttributeEXT vec2 barycentrics;

void main()
{
    InstanceRecord record = instances[gl_InstanceCustomIndexEXT];
    uvec3 triangle = triangles[record.firstTriangle + gl_PrimitiveID];
    // The world-space corners, from which the point, the normal and the offset scale follow as on the CPU (whose
    // triangles are stored in world space): one transform per corner, where transforming the object-space point
    // and the normal (by gl_WorldToObjectEXT) cost the H100 6 % more of book 3's mixture on cornell-box-lights.
    vec3 p0 = gl_ObjectToWorldEXT * vec4(positions[record.firstVertex + triangle.x], 1.0);
    vec3 p1 = gl_ObjectToWorldEXT * vec4(positions[record.firstVertex + triangle.y], 1.0);
    vec3 p2 = gl_ObjectToWorldEXT * vec4(positions[record.firstVertex + triangle.z], 1.0);
    float b1 = barycentrics.x;
    float b2 = barycentrics.y;
    float b0 = 1.0 - b1 - b2;

    payload.position = b0 * p0 + b1 * p1 + b2 * p2;
    payload.normal = normalize(cross(p1 - p0, p2 - p0));
    if (!kHitUv)
        payload.uv = vec2(0.0);
    else if (record.firstUv == kQuadUvs)
        payload.uv = quadUv(uint(gl_PrimitiveID), b1, b2);
    else if (record.firstUv != kNoIndex)
        payload.uv = b0 * uvs[record.firstUv + triangle.x] + b1 * uvs[record.firstUv + triangle.y] +
                     b2 * uvs[record.firstUv + triangle.z];
    else
        payload.uv = vec2(b1, b2);
    payload.material = record.firstTriangleMaterial != kNoIndex
                           ? triangleMaterials[record.firstTriangleMaterial + gl_PrimitiveID]
                           : record.material;
    payload.lightSlot = primitiveLightSlot(record, uint(gl_PrimitiveID));
    payload.flags = 0u;
    payload.offsetScale = planarOffsetScale(p0, p1, p2);
}
