// The CPU engine's compiled form of a Common scene: world-space primitive arrays (instance transforms baked
// in), one BVH over all of them, and references to the scene's materials, textures and lights.
#pragma once

#include <cstdint>
#include <vector>

#include "Accel/Bvh4.h"
#include "Accel/Bvh4Lanes.h"
#include "Geometry/Intersect.h"
#include "Geometry/Packets.h"
#include "Geometry/RayPackets.h"
#include "Geometry/Primitives.h"
#include "Sampling/LightBvh.h"
#include "Scene/Scene.h"

namespace rt::cpu
{
/// What a path needs to shade a hit.
struct SurfaceInteraction
{
    vec3 p; // world-space position
    vec3 n; // unit geometric normal, on the primitive's front side (outward for spheres)
    vec2 uv; // texture coordinates
    std::uint32_t material;
    std::uint32_t light = kNoIndex; // index into Scene::lights when the primitive is a light
    bool medium; // a scattering event inside a participating medium (n, uv meaningless)
    float offsetScale = 1.0f; // offsetRayOrigin's scale: the largest |vertex coordinate| of a triangle or quad
};

class CpuScene
{
public:
    /// Compiles `scene` (validated). Throws SceneError for what the CPU engine cannot represent.
    explicit CpuScene(const Scene& scene);

    const Scene& source() const { return *m_scene; }
    const Bvh& bvh() const { return m_bvh; }
    const Bvh4& bvh4() const { return m_bvh4; }
    std::size_t primitiveCount() const { return m_primitiveCount; }
    const std::vector<SphereRec>& spheres() const { return m_spheres; }
    const std::vector<QuadRec>& quads() const { return m_quads; }
    const std::vector<TriangleRec>& triangles() const { return m_triangles; }
    bool hasMedia() const { return !m_media.empty(); }
    /// Whether a sphere moves during the shutter: only then does a ray's time change what it hits.
    bool hasMotion() const { return m_hasMotion; }
    /// Scene::emitterCount(), counted once: NEE and the MIS weight need it at every vertex.
    std::uint32_t emitterCount() const { return m_emitterCount; }
    /// The emitters' power alias table (Sampling/LightPower.h) for NEE's power selection.
    const shader::AliasEntry* lightAlias() const { return m_lightAlias.data(); }
    /// The emitters' light BVH (Sampling/LightBvh.h) for NEE's bvh selection: its nodes and each emitter's leaf.
    const shader::LightBvhNode* lightBvh() const { return m_lightBvh.nodes.data(); }
    const std::uint32_t* lightBvhLeaves() const { return m_lightBvh.leaves.data(); }
    /// The Perlin tables of noise textures (Scene/Perlin.h), found once.
    const shader::PerlinData& perlinTables() const { return *m_perlinTables; }
    TraceRay::Needs rayNeeds() const { return {!m_triangles.empty(), !m_media.empty(), !m_bvh4.rootIsLeaf}; }

    /// Closest hit along r in (tMin, tMax). A medium the ray crosses scatters it where the hash of the path's
    /// `mediumSeed` and the ray puts it (Shared/Medium.h).
    bool intersect(const TraceRay& r, float tMin, float tMax, HitRecord& hit, std::uint32_t mediumSeed) const
    {
        hit.t = tMax;
        hit.prim = kNoIndex;
        traverse(m_bvh4, r, hit.t, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = first; k < first + count; ++k)
                intersectLeafPacket(m_leafPackets[k], r, tMin, hit, mediumSeed);
        });
        return hit.prim != kNoIndex;
    }

    /// Whether intersect(RayLanes) serves the scene: its primitives are quads and spheres (no triangles, whose
    /// packet test hands some rays to a scalar test, and no media), at most kRayLanesPrimitivesAtMost of them.
    bool tracesRayLanes() const
    {
        return m_triangles.empty() && m_media.empty() && m_primitiveCount <= kRayLanesPrimitivesAtMost;
    }
    /// Beyond this many primitives the paths' rays part ways in the tree: on one core lamp-room (24,582
    /// primitives) took 1.05-1.07x its time in lanes and white-spheres (20,001) gained 1.09x, against 1.09-1.45x for
    /// the scenes of 18 to 486 (docs/notebook/PERFORMANCE.md §30).
    static constexpr std::size_t kRayLanesPrimitivesAtMost = 4096;

    /// The closest hit of each lane's ray in (tMin, hits.t), as intersect() finds it for that ray alone, bit for
    /// bit (in a scene of one leaf; over a BVH, where two primitives meet a ray at exactly the same t, either may
    /// win: Accel/Bvh4Lanes.h). Precondition: tracesRayLanes().
    void intersect(const RayLanes& r, float tMin, RayHits& hits) const
    {
        if (m_bvh4.rootIsLeaf)
            intersectOneLeaf(r, tMin, hits);
        else
            intersectTree(r, tMin, hits);
    }
    /// intersect(RayLanes) in a scene of one leaf: every lane against every primitive.
    void intersectOneLeaf(const RayLanes& r, float tMin, RayHits& hits) const
    {
        const RayLaneView rays = r.view();
        for (const LaneOf& q : m_leafQuads)
            intersectRays(m_quadPackets[q.packet], q.lane, rays, tMin, hits);
        for (const LaneOf& s : m_leafSpheres)
            intersectRays(m_spherePackets[s.packet], s.lane, rays, tMin, hits);
    }
    /// intersect(RayLanes) over the scene's BVH (Accel/Bvh4Lanes.h). Precondition: the scene is not one leaf.
    void intersectTree(const RayLanes& r, float tMin, RayHits& hits) const
    {
        const RayLaneView rays = r.view();
        const auto alone = [&](int lane, std::uint32_t subtree) {
            const TraceRay ray = r.ray(lane);
            HitRecord hit = hits.lane(lane);
            traverseFrom(m_bvh4, subtree, ray, hit.t, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = first; k < first + count; ++k)
                    intersectLeafPacket(m_leafPackets[k], ray, tMin, hit, 0u);
            });
            hits.setLane(lane, hit);
        };
        traverseLanes(m_bvh4, r.boxView(), hits.t, [&](std::uint32_t first, std::uint32_t count) {
            intersectLeafLanes(first, count, rays, tMin, hits);
        }, alone);
    }

    /// Bit l set where something lies along lane l's ray in (tMin, tMax[l]): occluded() for each lane's shadow
    /// ray, the same answers. A lane leaves the traversal at its first blocker. Precondition: tracesRayLanes().
    /// In a scene of one leaf the scalar test, which stops at the first blocker, is cheaper
    /// (docs/notebook/PERFORMANCE.md §25), so the paths use this over a BVH only.
    int occluded(const RayLanes& r, float tMin, const Lanes& tMax) const
    {
        const RayLaneView rays = r.view();
        RayHits hits(tMax);
        const BoxLaneView boxes = r.boxView();
        // A hit shrinks a lane's t below its tMax; a blocked lane's t of -1 then lets no box pass (every box is
        // entered at t >= 0).
        const auto alone = [&](int lane, std::uint32_t subtree) {
            const TraceRay ray = r.ray(lane);
            HitRecord hit = hits.lane(lane);
            traverseFrom(m_bvh4, subtree, ray, hit.t, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = first; k < first + count && hit.prim == kNoIndex; ++k)
                    intersectLeafPacket(m_leafPackets[k], ray, tMin, hit, 0u);
                if (hit.prim != kNoIndex)
                    hit.t = -1.0f;
            });
            hits.setLane(lane, hit);
        };
        traverseLanes(m_bvh4, boxes, hits.t, [&](std::uint32_t first, std::uint32_t count) {
            intersectLeafLanes(first, count, rays, tMin, hits);
            const Lanes found = hits.t < tMax;
            hits.t = select(found, Lanes(-1.0f), hits.t);
        }, alone);
        return movemask(hits.t < tMax) & boxes.active;
    }

    /// True when something lies along r in (tMin, tMax): a shadow ray. Stops at the first hit found. A medium
    /// the ray crosses occludes it with the probability that a particle stops it (1 - transmittance), so the
    /// visibility it returns is an unbiased estimate of the transmittance (RTTNW §9's distance sampling).
    bool occluded(const TraceRay& r, float tMin, float tMax, std::uint32_t mediumSeed) const
    {
        HitRecord hit;
        hit.t = tMax;
        hit.prim = kNoIndex;
        // Closest-hit traversal, cut short: after the first hit tMax = -1 lets no box pass (every box is
        // entered at t >= 0).
        traverse(m_bvh4, r, hit.t, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = first; k < first + count && hit.prim == kNoIndex; ++k)
                intersectLeafPacket(m_leafPackets[k], r, tMin, hit, mediumSeed);
            if (hit.prim != kNoIndex)
                hit.t = -1.0f;
        });
        return hit.prim != kNoIndex;
    }

    /// Position, normal, uv and material of a hit found by intersect(). Inline, so that the path loops compile
    /// it into themselves: out of line it returned its record through memory.
    SurfaceInteraction interaction(const TraceRay& r, const HitRecord& hit) const
    {
        return interaction(Ray{r.origin, r.direction, r.time}, hit);
    }
    SurfaceInteraction interaction(const Ray& r, const HitRecord& hit) const
    {
        SurfaceInteraction si{};
        const PrimRef ref{hit.prim};
        switch (ref.type())
        {
        case PrimType::Sphere:
        {
            const SphereRec& s = m_spheres[ref.index()];
            const vec3 center = s.center0 + r.time * s.velocity;
            const vec3 n = glm::normalize(r.origin + hit.t * r.direction - center);
            si.n = n;
            si.p = center + s.radius * n; // re-projected onto the surface: o + t d carries error ~ t |d|
            si.material = s.material;
            si.light = m_sphereLights[ref.index()];
            if (m_materialNeedsUv[s.material]) // acos + atan2 only where an image texture reads them
                si.uv = sphereUv(s.uvFrame ? m_uvFrames[s.uvFrame] * n : n);
            break;
        }
        case PrimType::Quad:
        {
            const QuadRec& q = m_quads[ref.index()];
            si.p = r.origin + hit.t * r.direction;
            si.n = q.normal;
            si.uv = {hit.b1, hit.b2};
            si.material = q.material;
            si.light = m_quadLights[ref.index()];
            si.offsetScale = q.offsetScale;
            break;
        }
        case PrimType::Triangle:
        {
            const TriangleRec& tri = m_triangles[ref.index()];
            const float b0 = 1.0f - hit.b1 - hit.b2;
            si.p = b0 * tri.p0 + hit.b1 * tri.p1 + hit.b2 * tri.p2; // from barycentrics: accurate (RTG ch. 6)
            si.n = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
            const MeshData& mesh = m_scene->meshes[tri.mesh];
            if (mesh.uvs.empty())
                si.uv = {hit.b1, hit.b2};
            else
            {
                const std::uint32_t* idx = &mesh.indices[3 * tri.triangle];
                si.uv = b0 * mesh.uvs[idx[0]] + hit.b1 * mesh.uvs[idx[1]] + hit.b2 * mesh.uvs[idx[2]];
            }
            si.material = tri.material;
            si.light = m_triangleLights[ref.index()];
            si.offsetScale = tri.offsetScale;
            break;
        }
        case PrimType::Medium:
            si.p = r.origin + hit.t * r.direction;
            si.n = vec3(1.0f, 0.0f, 0.0f);
            si.material = m_media[ref.index()].material;
            si.medium = true;
            break;
        }
        return si;
    }

private:
    /// (u, v) of the unit sphere's point q (RTTNW §4.3): acos and atan2, out of line.
    static vec2 sphereUv(const vec3& q);

    void intersectLeafPacket(PrimRef ref, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t mediumSeed) const
    {
        switch (ref.type())
        {
        case PrimType::Sphere: intersectPacket(m_spherePackets[ref.index()], r, tMin, hit); break;
        case PrimType::Quad: intersectPacket(m_quadPackets[ref.index()], r, tMin, hit); break;
        case PrimType::Triangle:
        {
            const TrianglePacket& packet = m_trianglePackets[ref.index()];
            int undecided = 0;
            intersectPacket(packet, r, tMin, hit, undecided);
            for (; undecided; undecided &= undecided - 1)
            {
                const std::uint32_t prim = packet.prim[std::countr_zero(static_cast<unsigned>(undecided))];
                intersectTriangle(m_triangles[PrimRef{prim}.index()], r, tMin, hit, prim);
            }
            break;
        }
        case PrimType::Medium: intersectMedium(m_media[ref.index()], r, tMin, hit, ref.bits, mediumSeed); break;
        }
    }

    /// Every lane's ray against the primitives of leaf slots [first, first + count) (quads and spheres).
    void intersectLeafLanes(std::uint32_t first, std::uint32_t count, const RayLaneView& rays, float tMin,
                            RayHits& hits) const
    {
        for (std::uint32_t k = first; k < first + count; ++k)
        {
            const PrimRef ref = m_leafPackets[k];
            const int used = m_packetLanes[k];
            if (ref.type() == PrimType::Quad)
                for (int i = 0; i < used; ++i)
                    intersectRays(m_quadPackets[ref.index()], i, rays, tMin, hits);
            else
                for (int i = 0; i < used; ++i)
                    intersectRays(m_spherePackets[ref.index()], i, rays, tMin, hits);
        }
    }

    void buildLeafPackets(const std::vector<PrimRef>& refs);

    const Scene* m_scene;
    std::vector<SphereRec> m_spheres;
    std::vector<QuadRec> m_quads;
    std::vector<TriangleRec> m_triangles;
    std::vector<MediumRec> m_media;
    bool m_hasMotion = false;
    // Per record of m_spheres, m_quads, m_triangles: its index into Scene::lights, or kNoIndex.
    std::vector<std::uint32_t> m_sphereLights;
    std::vector<std::uint32_t> m_quadLights;
    std::vector<std::uint32_t> m_triangleLights;
    std::vector<shader::AliasEntry> m_lightAlias;
    LightBvh m_lightBvh;
    std::uint32_t m_emitterCount = 0;
    const shader::PerlinData* m_perlinTables;
    std::vector<bool> m_materialNeedsUv; // an image texture reads (u, v): spheres compute them only then
    std::vector<mat3> m_uvFrames; // object-from-world rotations of instanced spheres; [0] = identity
    // What traversal reads: per leaf, a run of packet references (type + index into the packet arrays; for
    // media the index of the medium itself).
    std::vector<PrimRef> m_leafPackets;
    std::vector<std::uint8_t> m_packetLanes; // per m_leafPackets entry: the primitives its packet holds
    // The primitives of a scene that is one leaf, in the order its packets test them: quads, then spheres.
    struct LaneOf
    {
        std::uint32_t packet;
        int lane;
    };
    std::vector<LaneOf> m_leafQuads;
    std::vector<LaneOf> m_leafSpheres;
    std::vector<SpherePacket> m_spherePackets;
    std::vector<QuadPacket> m_quadPackets;
    std::vector<TrianglePacket> m_trianglePackets;
    std::size_t m_primitiveCount = 0;
    Bvh m_bvh; // binary SAH tree; its leaves point at runs of m_leafPackets
    Bvh4 m_bvh4; // what traversal uses
};
} // namespace rt::cpu
