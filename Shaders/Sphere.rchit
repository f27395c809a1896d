// Closest hit on a sphere: the point re-projected onto the sphere (object space), the outward normal, the
// sphere uv of RTTNW §4.3 and the material.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require

#include "Bindings.glsl"
#include "Shared/Sphere.h"
#include "Payload.glsl"

layout(location = kPayloadPath) rayPayloadInEXT HitPayload payload;
hitAttributeEXT vec3 hitCenter;

void main()
{
    InstanceRecord record = instances[gl_InstanceCustomIndexEXT];
    SphereRecord sphere = spheres[record.firstSphere + gl_PrimitiveID];
    vec3 objectPoint = gl_ObjectRayOriginEXT + gl_HitTEXT * gl_ObjectRayDirectionEXT;
    vec3 q = normalize(objectPoint - hitCenter); // outward unit normal, object space
    objectPoint = hitCenter + sphere.radius * q;

    payload.position = gl_ObjectToWorldEXT * vec4(objectPoint, 1.0);
    payload.normal = normalize(q * mat3(gl_WorldToObjectEXT));
    payload.uv = kHitUv ? sphereUv(q) : vec2(0.0);
    payload.material = sphere.material;
    payload.lightSlot = primitiveLightSlot(record, uint(gl_PrimitiveID));
    payload.flags = 0u;
    payload.offsetScale = 1.0; // our own sphere test: its error scales with p (RayOffset.glsl)
}
