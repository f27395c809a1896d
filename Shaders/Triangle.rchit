// Closest hit on a triangle BLAS (meshes and quads): the world-space point from the barycentrics of the
// object-space vertices (accurate, unlike o + t d), the geometric normal of the counter-clockwise winding,
// the uv (vertex uvs, else the barycentrics (b1, b2)) and the material.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#include "Bindings.glsl"
#include "Payload.glsl"
#include "RayOffset.glsl"

layout(location = kPayloadPath) rayPayloadInEXT HitPayload payload;
hitAttributeEXT vec2 barycentrics;

void main()
{
    InstanceRecord record = instances[gl_InstanceCustomIndexEXT];
    uvec3 triangle = triangles[record.firstTriangle + gl_PrimitiveID];
    vec3 p0 = positions[record.firstVertex + triangle.x];
    vec3 p1 = positions[record.firstVertex + triangle.y];
    vec3 p2 = positions[record.firstVertex + triangle.z];
    float b1 = barycentrics.x;
    float b2 = barycentrics.y;
    float b0 = 1.0 - b1 - b2;
    vec3 objectPoint = b0 * p0 + b1 * p1 + b2 * p2;

    payload.position = gl_ObjectToWorldEXT * vec4(objectPoint, 1.0);
    // Normals transform by the inverse transpose: n^T (worldFromObject)^-1.
    payload.normal = normalize(cross(p1 - p0, p2 - p0) * mat3(gl_WorldToObjectEXT));
    if (record.firstUv != kNoIndex)
        payload.uv = b0 * uvs[record.firstUv + triangle.x] + b1 * uvs[record.firstUv + triangle.y] +
                     b2 * uvs[record.firstUv + triangle.z];
    else
        payload.uv = vec2(b1, b2);
    payload.material = record.firstTriangleMaterial != kNoIndex
                           ? triangleMaterials[record.firstTriangleMaterial + gl_PrimitiveID]
                           : record.material;
    payload.light = primitiveLight(record, uint(gl_PrimitiveID));
    payload.flags = 0u;
    payload.offsetScale = planarOffsetScale(gl_ObjectToWorldEXT * vec4(p0, 1.0), gl_ObjectToWorldEXT * vec4(p1, 1.0),
                                            gl_ObjectToWorldEXT * vec4(p2, 1.0));
}
