// The CPU engine's compiled form of a Common scene: world-space primitive arrays (instance transforms baked
// in), one BVH over all of them, and references to the scene's materials, textures and lights.
#pragma once

#include <cstdint>
#include <vector>

#include "Accel/Bvh.h"
#include "Geometry/Intersect.h"
#include "Geometry/Primitives.h"
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
    bool medium; // a scattering event inside a participating medium (n, uv meaningless)
};

class CpuScene
{
public:
    /// Compiles `scene` (validated). Throws SceneError for what the CPU engine cannot represent.
    explicit CpuScene(const Scene& scene);

    const Scene& source() const { return *m_scene; }
    const Bvh& bvh() const { return m_bvh; }
    std::size_t primitiveCount() const { return m_prims.size(); }
    bool hasMedia() const { return !m_media.empty(); }

    /// Closest hit along r in (tMin, tMax). Consumes random numbers only when the ray crosses a medium.
    bool intersect(const TraceRay& r, float tMin, float tMax, HitRecord& hit, Rng& rng) const
    {
        hit.t = tMax;
        hit.prim = kNoIndex;
        traverse(m_bvh, r, hit.t, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = first; k < first + count; ++k)
            {
                const PrimRef ref = m_prims[k];
                switch (ref.type())
                {
                case PrimType::Sphere: intersectSphere(m_spheres[ref.index()], r, tMin, hit, ref.bits); break;
                case PrimType::Quad: intersectQuad(m_quads[ref.index()], r, tMin, hit, ref.bits); break;
                case PrimType::Triangle: intersectTriangle(m_triangles[ref.index()], r, tMin, hit, ref.bits); break;
                case PrimType::Medium: intersectMedium(m_media[ref.index()], r, tMin, hit, ref.bits, rng); break;
                }
            }
        });
        return hit.prim != kNoIndex;
    }

    /// Position, normal, uv and material of a hit found by intersect().
    SurfaceInteraction interaction(const TraceRay& r, const HitRecord& hit) const;

private:
    const Scene* m_scene;
    std::vector<SphereRec> m_spheres;
    std::vector<QuadRec> m_quads;
    std::vector<TriangleRec> m_triangles;
    std::vector<MediumRec> m_media;
    std::vector<mat3> m_uvFrames; // object-from-world rotations of instanced spheres; [0] = identity
    std::vector<PrimRef> m_prims; // in BVH leaf order
    Bvh m_bvh;
};
} // namespace rt::cpu
