// World-space primitive records of the CPU engine, compiled from the Common scene by CpuScene: instance
// transforms are baked in (quads and triangles stay exact under any affine map, spheres under similarity
// maps), so traversal is one BVH over plain arrays with no per-instance ray transform.
#pragma once

#include <cstdint>

#include "Math/Math.h"

namespace rt::cpu
{
/// A sphere, possibly moving linearly over the shutter: centre(t) = center0 + t * velocity.
struct SphereRec
{
    vec3 center0;
    float radius;
    vec3 velocity;
    std::uint32_t material;
    std::uint32_t uvFrame; // index into CpuScene::uvFrames (object-from-world rotation for uvs); 0 = identity
};

/// A parallelogram q + a u + b v with its plane n . x = d and the dual edge vectors that turn a point of the
/// plane into (a, b) with two dot products: a = (x - q) . ua, b = (x - q) . vb (RTTNW §6.4 refactored).
struct QuadRec
{
    vec3 q;
    float d;
    vec3 normal; // unit, along u x v (the front side)
    std::uint32_t material;
    vec3 ua; // cross(v, w), w = n / |n|^2 with n = u x v
    vec3 vb; // cross(w, u)
    float offsetScale; // largest |corner coordinate|: offsetRayOrigin's scale
};

/// A triangle of a mesh, vertices in world space.
struct TriangleRec
{
    vec3 p0, p1, p2;
    std::uint32_t material;
    std::uint32_t mesh; // Common scene mesh index, for vertex uvs
    std::uint32_t triangle; // triangle index in that mesh
    float offsetScale; // largest |vertex coordinate|: offsetRayOrigin's scale
};

/// A constant-density medium; its boundary is tested in object space, where it is a sphere or a box.
struct MediumRec
{
    mat4 objectFromWorld;
    vec3 center; // Sphere boundary (object space)
    float radius;
    vec3 boxMin; // Box boundary (object space)
    vec3 boxMax;
    float density; // extinction coefficient per world unit
    std::uint32_t material;
    bool sphere;
};

enum class PrimType : std::uint32_t
{
    Sphere = 0,
    Quad = 1,
    Triangle = 2,
    Medium = 3
};

/// A primitive reference packed in 32 bits: type in the top 2 bits, index in the low 30.
struct PrimRef
{
    std::uint32_t bits;

    static PrimRef make(PrimType type, std::uint32_t index) { return {(static_cast<std::uint32_t>(type) << 30) | index}; }
    PrimType type() const { return static_cast<PrimType>(bits >> 30); }
    std::uint32_t index() const { return bits & 0x3FFFFFFFu; }
};
} // namespace rt::cpu
