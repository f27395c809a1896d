// Which hit groups a pipeline holds and which SBT hit record each kind of geometry takes: only the kinds a
// scene has (no sphere intersection group without spheres, no medium group without media), in the order
// triangles, spheres, media. traceRayEXT uses sbtRecordOffset 0 and sbtRecordStride 1, so a TLAS instance
// reaches record instanceShaderBindingTableRecordOffset + geometryIndex; a procedural BLAS holds its spheres
// as geometry 0 and its media as geometry 1, so the media record must follow the spheres' directly, which
// this order gives whenever both exist. Pure (tested in tests/Gpu/ShaderBindingTableTest.cpp).
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <vector>

namespace rt::gpu
{
enum class HitGroupKind : std::uint32_t
{
    Triangles, // Triangle.rchit: meshes and quads
    Spheres, // Sphere.rint + Sphere.rchit: procedural geometry 0
    Media // Medium.rint + Medium.rchit: procedural geometry 1 (0 in a BLAS without spheres)
};
inline constexpr std::uint32_t kHitGroupKindCount = 3;

class HitGroupLayout
{
public:
    /// No hit group.
    HitGroupLayout() = default;
    HitGroupLayout(bool triangles, bool spheres, bool media) : m_has{triangles, spheres, media} {}
    /// Every kind: the general pipeline's groups.
    static HitGroupLayout all() { return {true, true, true}; }

    bool has(HitGroupKind kind) const { return m_has[index(kind)]; }
    /// Hit records (= hit groups) in the layout.
    std::uint32_t count() const;
    /// The hit record of `kind` (an instance's instanceShaderBindingTableRecordOffset); the layout must have it.
    std::uint32_t record(HitGroupKind kind) const;
    /// The kind at hit record `record` (< count()).
    HitGroupKind kindAt(std::uint32_t record) const;
    /// Whether every kind of `other` is here too (a pipeline with these groups can trace a scene of `other`).
    bool covers(const HitGroupLayout& other) const;

    auto operator<=>(const HitGroupLayout&) const = default;

private:
    static std::uint32_t index(HitGroupKind kind) { return static_cast<std::uint32_t>(kind); }

    std::array<bool, kHitGroupKindCount> m_has{};
};

/// The pipeline shader group whose handle goes into each hit record of a scene laid out with `scene`, for a
/// pipeline built with the hit groups `pipeline` after its raygen group and `missCount` miss groups (group
/// 1 + missCount + pipeline.record(kind)). `pipeline` must cover `scene`.
std::vector<std::uint32_t> hitRecordGroups(const HitGroupLayout& scene, const HitGroupLayout& pipeline,
                                           std::uint32_t missCount);
} // namespace rt::gpu
