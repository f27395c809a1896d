// How a Common scene is laid out for the GPU: flat arrays for the storage buffers of HostDevice.h, the
// BLASes to build from them and the TLAS instances that place the BLASes in the world. Plain data, built on
// the host without a device (tested in tests/Gpu/SceneLayoutTest.cpp).
//
// Mapping (docs/GPU.md has the picture):
//   mesh                          -> one triangle BLAS, shared by every group and instance that uses it;
//   the quads of a group          -> one triangle BLAS (two triangles per quad; no uvs: kQuadUvs, whose
//                                    edge coordinates the hit shader takes from Shared/QuadUv.h);
//   the spheres + media of a group -> one procedural (AABB) BLAS: geometry 0 = spheres, geometry 1 = media;
//   scene instance                -> one TLAS instance per BLAS its group uses, with the instance's transform;
//                                    its record is the group's, or a copy of it where the part holds lights
//                                    (a run of primitiveLights names them: light indices differ per instance);
//                                    its hit record is its geometry kind's in the scene's HitGroupLayout
//                                    (only the kinds the scene has).
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Math.h"
#include "RayTracing/HitGroupLayout.h"
#include "Scene/Scene.h"
#include "Shared/HostDevice.h"

namespace rt::gpu
{
/// An axis-aligned box in the layout of VkAabbPositionsKHR (min xyz, max xyz).
struct AabbRecord
{
    vec3 min;
    vec3 max;
};
static_assert(sizeof(AabbRecord) == 24);

struct BlasDesc
{
    enum class Kind
    {
        Triangles,
        Procedural
    };
    Kind kind = Kind::Triangles;
    // Triangles: a range of SceneLayout::positions and of SceneLayout::triangles (indices relative to firstVertex).
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t firstTriangle = 0;
    std::uint32_t triangleCount = 0;
    // Procedural: ranges of SceneLayout::aabbs, spheres (geometry 0 when sphereCount > 0) then media.
    std::uint32_t firstSphereAabb = 0;
    std::uint32_t sphereCount = 0;
    std::uint32_t firstMediumAabb = 0;
    std::uint32_t mediumCount = 0;
};

struct TlasInstanceDesc
{
    std::uint32_t blas = 0; // index into SceneLayout::blases
    mat4 worldFromObject{1.0f};
    std::uint32_t record = 0; // instanceCustomIndex: index into SceneLayout::records
    HitGroupKind kind = HitGroupKind::Triangles; // of geometry 0
    std::uint32_t hitGroup = 0; // instanceShaderBindingTableRecordOffset: hitGroups.record(kind)
};

struct SceneLayout
{
    std::vector<vec3> positions;
    std::vector<vec2> uvs;
    std::vector<glm::uvec3> triangles;
    std::vector<std::uint32_t> triangleMaterials;
    std::vector<shader::SphereRecord> spheres;
    std::vector<shader::MediumRecord> media;
    std::vector<AabbRecord> aabbs;
    std::vector<shader::InstanceRecord> records;
    std::vector<std::uint32_t> primitiveLights; // runs that InstanceRecord::firstPrimitiveLight points at
    std::vector<BlasDesc> blases;
    std::vector<TlasInstanceDesc> instances;
    HitGroupLayout hitGroups; // the kinds of geometry the instances hold: the hit records the SBT needs
};

/// Lays out `scene` (validated). Throws rt::SceneError when it has more TLAS instances or records than the
/// 24-bit instanceCustomIndex can address.
SceneLayout layoutScene(const Scene& scene);
} // namespace rt::gpu
