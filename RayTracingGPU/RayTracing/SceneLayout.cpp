#include "RayTracing/SceneLayout.h"

#include <algorithm>
#include <map>
#include <optional>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Scene/LightLookup.h"

namespace rt::gpu
{
namespace
{
using shader::InstanceRecord;

constexpr std::size_t kMaxCustomIndex = 1u << 24; // VkAccelerationStructureInstanceKHR::instanceCustomIndex

std::uint32_t u32(std::size_t n) { return static_cast<std::uint32_t>(n); }

InstanceRecord emptyRecord()
{
    return {.firstVertex = kNoIndex,
            .firstUv = kNoIndex,
            .firstTriangle = kNoIndex,
            .firstTriangleMaterial = kNoIndex,
            .material = kNoIndex,
            .firstSphere = kNoIndex,
            .firstMedium = kNoIndex,
            .firstPrimitiveLight = kNoIndex};
}

/// A BLAS and the record its TLAS instances point at.
struct Part
{
    enum class Kind
    {
        Quads,
        Mesh,
        Procedural
    };
    std::uint32_t blas;
    std::uint32_t record;
    HitGroupKind hitGroup; // of geometry 0
    Kind kind;
    std::uint32_t meshRef = 0; // Mesh: index into the group's meshes
};

class Builder
{
public:
    explicit Builder(const Scene& scene) : m_scene(scene), m_lightOf(scene) {}

    SceneLayout build()
    {
        std::map<std::uint32_t, std::vector<Part>> groupParts;
        for (std::uint32_t i = 0; i < m_scene.instances.size(); ++i)
        {
            const InstanceDesc& instance = m_scene.instances[i];
            auto [it, added] = groupParts.try_emplace(instance.group);
            if (added)
                it->second = partsOf(instance.group);
            for (const Part& part : it->second)
                m_out.instances.push_back({.blas = part.blas,
                                           .worldFromObject = instance.worldFromObject.m,
                                           .record = recordWithLights(part, i),
                                           .kind = part.hitGroup});
        }
        // Hit records for the kinds present only; a procedural instance with spheres reaches its media at
        // record + 1 (geometry 1), which HitGroupLayout's order gives.
        bool has[kHitGroupKindCount] = {};
        for (const TlasInstanceDesc& t : m_out.instances)
            has[static_cast<std::uint32_t>(t.kind)] = true;
        for (const BlasDesc& b : m_out.blases)
            has[static_cast<std::uint32_t>(HitGroupKind::Media)] |= b.sphereCount > 0 && b.mediumCount > 0;
        m_out.hitGroups = HitGroupLayout(has[0], has[1], has[2]);
        for (TlasInstanceDesc& t : m_out.instances)
            t.hitGroup = m_out.hitGroups.record(t.kind);
        if (m_out.instances.size() >= kMaxCustomIndex || m_out.records.size() >= kMaxCustomIndex)
            throw SceneError(fmt::format("scene '{}' needs {} TLAS instances; the GPU engine addresses at most {}",
                                         m_scene.id, m_out.instances.size(), kMaxCustomIndex - 1));
        return std::move(m_out);
    }

private:
    std::vector<Part> partsOf(std::uint32_t groupIndex)
    {
        const GroupDesc& group = m_scene.groups[groupIndex];
        std::vector<Part> parts;
        if (!group.quads.empty())
            parts.push_back(quadPart(group));
        for (std::uint32_t r = 0; r < group.meshes.size(); ++r)
        {
            parts.push_back(meshPart(group.meshes[r]));
            parts.back().meshRef = r;
        }
        if (!group.spheres.empty() || !group.media.empty())
            parts.push_back(proceduralPart(group));
        return parts;
    }

    /// The part's record, or for an instance whose part holds lights a copy of it that finds them: the light
    /// indices differ between instances of one group, the geometry does not.
    std::uint32_t recordWithLights(const Part& part, std::uint32_t instance)
    {
        if (m_scene.lights.empty() || m_scene.lights[0].material == kNoIndex) // no emitter (they come first)
            return part.record;
        const GroupDesc& group = m_scene.groups[m_scene.instances[instance].group];
        std::vector<std::uint32_t> lights; // per BLAS primitive
        switch (part.kind)
        {
        case Part::Kind::Quads:
            for (std::uint32_t k = 0; k < group.quads.size(); ++k)
                lights.insert(lights.end(), 2, m_lightOf.quad(instance, k)); // two triangles per quad
            break;
        case Part::Kind::Mesh:
        {
            const MeshRef& ref = group.meshes[part.meshRef];
            const MeshData& mesh = m_scene.meshes[ref.mesh];
            if (mesh.triangleMaterials.empty() && !m_scene.isEmissive(ref.material))
                return part.record;
            for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t)
                lights.push_back(m_lightOf.triangle(instance, part.meshRef, t));
            break;
        }
        case Part::Kind::Procedural:
            for (std::uint32_t k = 0; k < group.spheres.size(); ++k)
                lights.push_back(m_lightOf.sphere(instance, k));
            break;
        }
        if (std::all_of(lights.begin(), lights.end(), [](std::uint32_t l) { return l == kNoIndex; }))
            return part.record;
        InstanceRecord record = m_out.records[part.record];
        record.firstPrimitiveLight = u32(m_out.primitiveLights.size());
        m_out.primitiveLights.insert(m_out.primitiveLights.end(), lights.begin(), lights.end());
        return addRecord(record);
    }

    std::uint32_t addRecord(const InstanceRecord& record)
    {
        m_out.records.push_back(record);
        return u32(m_out.records.size() - 1);
    }

    /// Quad Q + a u + b v as triangles (Q, Q+u, Q+u+v) and (Q, Q+u+v, Q+v): both face along u x v, and the
    /// hit shader computes the quad's edge coordinates (a, b) from the triangle's parity (Shared/QuadUv.h).
    Part quadPart(const GroupDesc& group)
    {
        BlasDesc blas{.kind = BlasDesc::Kind::Triangles,
                      .firstVertex = u32(m_out.positions.size()),
                      .firstTriangle = u32(m_out.triangles.size())};
        InstanceRecord record = emptyRecord();
        record.firstVertex = blas.firstVertex;
        record.firstUv = shader::kQuadUvs;
        record.firstTriangle = blas.firstTriangle;
        record.firstTriangleMaterial = u32(m_out.triangleMaterials.size());
        for (const QuadDesc& q : group.quads)
        {
            const std::uint32_t base = u32(m_out.positions.size()) - blas.firstVertex;
            m_out.positions.insert(m_out.positions.end(), {q.q, q.q + q.u, q.q + q.u + q.v, q.q + q.v});
            m_out.triangles.push_back({base, base + 1, base + 2});
            m_out.triangles.push_back({base, base + 2, base + 3});
            m_out.triangleMaterials.insert(m_out.triangleMaterials.end(), {q.material, q.material});
        }
        blas.vertexCount = u32(m_out.positions.size()) - blas.firstVertex;
        blas.triangleCount = u32(m_out.triangles.size()) - blas.firstTriangle;
        m_out.blases.push_back(blas);
        return {u32(m_out.blases.size() - 1), addRecord(record), HitGroupKind::Triangles, Part::Kind::Quads};
    }

    Part meshPart(const MeshRef& ref)
    {
        auto [it, added] = m_meshes.try_emplace(ref.mesh);
        if (added)
            it->second = addMesh(m_scene.meshes[ref.mesh]);
        const MeshEntry& mesh = it->second;
        InstanceRecord record = mesh.record;
        record.material = ref.material;
        // Records of one mesh differ only in the MeshRef's material: share them.
        auto [recordIt, newRecord] = m_meshRecords.try_emplace({ref.mesh, ref.material});
        if (newRecord)
            recordIt->second = addRecord(record);
        return {mesh.blas, recordIt->second, HitGroupKind::Triangles, Part::Kind::Mesh};
    }

    struct MeshEntry
    {
        std::uint32_t blas;
        InstanceRecord record;
    };

    MeshEntry addMesh(const MeshData& mesh)
    {
        BlasDesc blas{.kind = BlasDesc::Kind::Triangles,
                      .firstVertex = u32(m_out.positions.size()),
                      .vertexCount = u32(mesh.positions.size()),
                      .firstTriangle = u32(m_out.triangles.size()),
                      .triangleCount = u32(mesh.triangleCount())};
        InstanceRecord record = emptyRecord();
        record.firstVertex = blas.firstVertex;
        record.firstTriangle = blas.firstTriangle;
        m_out.positions.insert(m_out.positions.end(), mesh.positions.begin(), mesh.positions.end());
        if (!mesh.uvs.empty())
        {
            record.firstUv = u32(m_out.uvs.size());
            m_out.uvs.insert(m_out.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
        }
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
            m_out.triangles.push_back({mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
        if (!mesh.triangleMaterials.empty())
        {
            record.firstTriangleMaterial = u32(m_out.triangleMaterials.size());
            m_out.triangleMaterials.insert(m_out.triangleMaterials.end(), mesh.triangleMaterials.begin(),
                                           mesh.triangleMaterials.end());
        }
        m_out.blases.push_back(blas);
        return {u32(m_out.blases.size() - 1), record};
    }

    Part proceduralPart(const GroupDesc& group)
    {
        BlasDesc blas{.kind = BlasDesc::Kind::Procedural};
        InstanceRecord record = emptyRecord();
        blas.firstSphereAabb = u32(m_out.aabbs.size());
        blas.sphereCount = u32(group.spheres.size());
        record.firstSphere = u32(m_out.spheres.size());
        for (const SphereDesc& s : group.spheres)
        {
            m_out.spheres.push_back({s.center0, s.radius, s.center1, s.material});
            const Aabb box = s.bounds(); // the whole sweep of a moving sphere
            m_out.aabbs.push_back({box.min, box.max});
        }
        blas.firstMediumAabb = u32(m_out.aabbs.size());
        blas.mediumCount = u32(group.media.size());
        record.firstMedium = u32(m_out.media.size());
        for (const MediumDesc& m : group.media)
        {
            const bool sphere = m.boundary == MediumDesc::Boundary::Sphere;
            m_out.media.push_back({.center = m.center,
                                   .radius = m.radius,
                                   .boxMin = m.boxMin,
                                   .density = m.density,
                                   .boxMax = m.boxMax,
                                   .boundary = sphere ? shader::MediumBoundary::Sphere : shader::MediumBoundary::Box,
                                   .phaseMaterial = m.phaseMaterial,
                                   .pad0 = 0,
                                   .pad1 = 0,
                                   .pad2 = 0});
            const Aabb box = m.bounds();
            m_out.aabbs.push_back({box.min, box.max});
        }
        m_out.blases.push_back(blas);
        // Geometry 0 takes the instance's first record: spheres if any, else the media.
        const HitGroupKind hitGroup = blas.sphereCount > 0 ? HitGroupKind::Spheres : HitGroupKind::Media;
        return {u32(m_out.blases.size() - 1), addRecord(record), hitGroup, Part::Kind::Procedural};
    }

    const Scene& m_scene;
    const LightLookup m_lightOf;
    SceneLayout m_out;
    std::map<std::uint32_t, MeshEntry> m_meshes;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> m_meshRecords;
};
} // namespace

SceneLayout layoutScene(const Scene& scene) { return Builder(scene).build(); }
} // namespace rt::gpu
