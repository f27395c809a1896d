#include "Engine/CpuScene.h"

#include <algorithm>
#include <cmath>

#include "Math/PlaneDuals.h"
#include "Math/RayOffset.h"
#include "Sampling/LightPower.h"
#include "Scene/LightLookup.h"
#include "Scene/Perlin.h"
#include "Shared/Sphere.h"

namespace rt::cpu
{
namespace
{
/// The box of the parallelogram's four corners.
Aabb quadCorners(const vec3& q, const vec3& u, const vec3& v)
{
    Aabb box(q, q + u + v);
    box.expand(q + u);
    box.expand(q + v);
    return box;
}

QuadRec makeQuad(const vec3& q, const vec3& u, const vec3& v, std::uint32_t material)
{
    QuadRec rec;
    rec.q = q;
    rec.normal = glm::normalize(glm::cross(u, v));
    rec.d = glm::dot(rec.normal, q);
    rec.material = material;
    const PlaneDuals duals = planeDuals(u, v);
    rec.ua = duals.ua;
    rec.vb = duals.vb;
    const Aabb corners = quadCorners(q, u, v);
    rec.offsetScale = maxComponent(glm::max(glm::abs(corners.min), glm::abs(corners.max))); // largest |corner coordinate|
    return rec;
}

Aabb quadBounds(const QuadRec& q, const vec3& u, const vec3& v)
{
    const Aabb box = quadCorners(q.q, u, v);
    // A flat box has no volume; pad it so the slab test does not depend on 0 * inf.
    const vec3 pad = glm::max(vec3(1e-4f), 1e-6f * glm::abs(box.max));
    return Aabb(box.min - pad, box.max + pad);
}

} // namespace

vec2 CpuScene::sphereUv(const vec3& q)
{
    return shader::sphereUv(q);
}

CpuScene::CpuScene(const Scene& scene)
    : m_scene(&scene), m_lightAlias(lightAliasTable(scene)), m_lightBvh(buildLightBvh(scene)), m_emitterCount(scene.emitterCount()),
      m_perlinTables(&rt::perlinTables())
{
    const auto isImage = [&](std::uint32_t t) { return t != kNoIndex && scene.textures[t].type == TextureType::Image; };
    for (const MaterialData& m : scene.materials)
        m_materialNeedsUv.push_back(isImage(m.albedoTexture) || isImage(m.emissionTexture) ||
                                    (m.type == MaterialType::GltfPbr && isImage(m.metallicRoughnessTexture)));

    m_uvFrames.push_back(mat3(1.0f));
    std::vector<Aabb> bounds;
    std::vector<PrimRef> refs;
    const auto add = [&](PrimType type, std::size_t index, const Aabb& box) {
        refs.push_back(PrimRef::make(type, static_cast<std::uint32_t>(index)));
        bounds.push_back(box);
    };

    const LightLookup lightOf(scene);
    for (std::uint32_t instance = 0; instance < scene.instances.size(); ++instance)
    {
        const InstanceDesc& inst = scene.instances[instance];
        const GroupDesc& group = scene.groups[inst.group];
        const Transform& m = inst.worldFromObject;
        const bool identity = m.isIdentity();

        std::uint32_t uvFrame = 0;
        float scale = 1.0f;
        if (!group.spheres.empty() && !identity)
        {
            scale = *m.uniformScale(); // Scene::validate guarantees it
            m_uvFrames.push_back(glm::transpose(mat3(m.m)) / scale); // M = s R: the object<-world rotation is R^T
            uvFrame = static_cast<std::uint32_t>(m_uvFrames.size() - 1);
        }
        for (std::uint32_t k = 0; k < group.spheres.size(); ++k)
        {
            const SphereDesc& s = group.spheres[k];
            m_sphereLights.push_back(lightOf.sphere(instance, k));
            SphereRec rec{m.point(s.center0), s.radius * scale, m.vector(s.center1 - s.center0), s.material, uvFrame};
            const vec3 r(rec.radius);
            Aabb box(rec.center0 - r, rec.center0 + r);
            box.expand(Aabb(rec.center0 + rec.velocity - r, rec.center0 + rec.velocity + r));
            add(PrimType::Sphere, m_spheres.size(), box);
            m_hasMotion = m_hasMotion || rec.velocity != vec3(0.0f);
            m_spheres.push_back(rec);
        }
        for (std::uint32_t k = 0; k < group.quads.size(); ++k)
        {
            const QuadDesc& q = group.quads[k];
            m_quadLights.push_back(lightOf.quad(instance, k));
            const vec3 u = m.vector(q.u), v = m.vector(q.v);
            const QuadRec rec = makeQuad(m.point(q.q), u, v, q.material);
            add(PrimType::Quad, m_quads.size(), quadBounds(rec, u, v));
            m_quads.push_back(rec);
        }
        for (std::uint32_t meshRef = 0; meshRef < group.meshes.size(); ++meshRef)
        {
            const MeshRef& ref = group.meshes[meshRef];
            const MeshData& mesh = scene.meshes[ref.mesh];
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
            {
                TriangleRec rec;
                rec.p0 = m.point(mesh.positions[mesh.indices[3 * t]]);
                rec.p1 = m.point(mesh.positions[mesh.indices[3 * t + 1]]);
                rec.p2 = m.point(mesh.positions[mesh.indices[3 * t + 2]]);
                if (lengthSquared(glm::cross(rec.p1 - rec.p0, rec.p2 - rec.p0)) == 0.0f)
                    continue; // zero area: rounding in the sheared edge functions could still report hits
                rec.material = mesh.triangleMaterials.empty() ? ref.material : mesh.triangleMaterials[t];
                rec.mesh = ref.mesh;
                rec.triangle = static_cast<std::uint32_t>(t);
                rec.offsetScale = planarOffsetScale(rec.p0, rec.p1, rec.p2);
                Aabb box(rec.p0, rec.p1);
                box.expand(rec.p2);
                add(PrimType::Triangle, m_triangles.size(), box);
                m_triangles.push_back(rec);
                m_triangleLights.push_back(lightOf.triangle(instance, meshRef, static_cast<std::uint32_t>(t)));
            }
        }
        for (const MediumDesc& md : group.media)
        {
            MediumRec rec;
            rec.objectFromWorld = m.inverse().m;
            rec.sphere = md.boundary == MediumDesc::Boundary::Sphere;
            rec.center = md.center;
            rec.radius = md.radius;
            rec.boxMin = md.boxMin;
            rec.boxMax = md.boxMax;
            rec.density = md.density;
            rec.material = md.phaseMaterial;
            add(PrimType::Medium, m_media.size(), m.bounds(md.bounds()));
            m_media.push_back(rec);
        }
    }

    m_primitiveCount = refs.size();
    m_bvh = Bvh::build(bounds);
    buildLeafPackets(refs);
    m_bvh4 = Bvh4::collapse(m_bvh);
}

void CpuScene::buildLeafPackets(const std::vector<PrimRef>& refs)
{
    // Each binary leaf's primitives, grouped by type into packets of kLanes; the leaf is then re-pointed from
    // its primitive slots to its run of packets.
    for (BvhNode& node : m_bvh.nodes)
    {
        if (node.count == 0)
            continue;
        const auto firstPacket = static_cast<std::uint32_t>(m_leafPackets.size());
        std::vector<std::uint32_t> byType[4];
        for (std::uint32_t slot = node.offset; slot < node.offset + node.count; ++slot)
        {
            const PrimRef ref = refs[m_bvh.order[slot]];
            byType[static_cast<int>(ref.type())].push_back(ref.bits);
        }
        const bool root = &node == &m_bvh.nodes.front();
        // rootLanes: where a scene of one leaf lists its primitives for the ray-lane test (none for triangles).
        const auto emit = [&](PrimType type, auto& packets, const auto& records, std::vector<LaneOf>* rootLanes) {
            const std::vector<std::uint32_t>& prims = byType[static_cast<int>(type)];
            for (std::size_t i = 0; i < prims.size(); i += kLanes)
            {
                auto& packet = packets.emplace_back();
                const auto index = static_cast<std::uint32_t>(packets.size() - 1);
                const int used = static_cast<int>(std::min<std::size_t>(kLanes, prims.size() - i));
                for (int lane = 0; lane < used; ++lane)
                {
                    setLane(packet, lane, records[PrimRef{prims[i + lane]}.index()], prims[i + lane]);
                    if (root && rootLanes)
                        rootLanes->push_back({index, lane});
                }
                padPacket(packet, used);
                m_leafPackets.push_back(PrimRef::make(type, index));
                m_packetLanes.push_back(static_cast<std::uint8_t>(used));
            }
        };
        emit(PrimType::Quad, m_quadPackets, m_quads, &m_leafQuads);
        emit(PrimType::Sphere, m_spherePackets, m_spheres, &m_leafSpheres);
        emit(PrimType::Triangle, m_trianglePackets, m_triangles, nullptr);
        for (std::uint32_t bits : byType[static_cast<int>(PrimType::Medium)])
        {
            m_leafPackets.push_back(PrimRef{bits});
            m_packetLanes.push_back(1);
        }
        node.offset = firstPacket;
        node.count = static_cast<std::uint16_t>(m_leafPackets.size() - firstPacket);
    }
}
} // namespace rt::cpu
