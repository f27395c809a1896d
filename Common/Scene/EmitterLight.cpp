#include "Scene/EmitterLight.h"

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Sampling/LightSampling.h"

namespace rt
{
std::optional<LightData> emitterLight(const Scene& s, const LightSource& source)
{
    const InstanceDesc& inst = s.instances[source.instance];
    const GroupDesc& g = s.groups[inst.group];
    const Transform& m = inst.worldFromObject;
    switch (source.kind)
    {
    case LightSource::Kind::Quad:
    {
        const QuadDesc& q = g.quads[source.primitive];
        const vec3 u = m.vector(q.u), v = m.vector(q.v);
        if (!(lengthSquared(glm::cross(u, v)) > 0.0f))
            return std::nullopt;
        return makeQuadLight(m.point(q.q), u, v, q.material);
    }
    case LightSource::Kind::Sphere:
    {
        const SphereDesc& sp = g.spheres[source.primitive];
        const auto scale = m.uniformScale();
        if (!scale || sp.moving())
            throw SceneError(fmt::format("scene '{}': an emitting sphere in group '{}' is moving or "
                                         "non-uniformly scaled; the light samplers need a static sphere",
                                         s.id, g.name));
        return makeSphereLight(m.point(sp.center0), sp.radius * *scale, sp.material);
    }
    case LightSource::Kind::Triangle:
    {
        const MeshRef& ref = g.meshes[source.meshRef];
        const MeshData& mesh = s.meshes[ref.mesh];
        const std::uint32_t t = source.primitive;
        const std::uint32_t mat = mesh.triangleMaterials.empty() ? ref.material : mesh.triangleMaterials[t];
        const vec3 a = m.point(mesh.positions[mesh.indices[3 * t]]);
        const vec3 b = m.point(mesh.positions[mesh.indices[3 * t + 1]]);
        const vec3 c = m.point(mesh.positions[mesh.indices[3 * t + 2]]);
        if (!(lengthSquared(glm::cross(b - a, c - a)) > 0.0f))
            return std::nullopt;
        return makeTriangleLight(a, b, c, mat);
    }
    case LightSource::Kind::Target: break;
    }
    return std::nullopt;
}
} // namespace rt
