#include "Scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
Aabb SphereDesc::bounds() const
{
    const vec3 r(radius);
    Aabb box(center0 - r, center0 + r);
    box.expand(Aabb(center1 - r, center1 + r)); // the whole sweep of a moving sphere
    return box;
}

Aabb QuadDesc::bounds() const
{
    Aabb box(q, q + u + v);
    box.expand(q + u);
    box.expand(q + v);
    return box;
}

Aabb MeshData::bounds() const
{
    Aabb box;
    for (const vec3& p : positions)
        box.expand(p);
    return box;
}

Aabb MediumDesc::bounds() const
{
    if (boundary == Boundary::Sphere)
        return Aabb(center - vec3(radius), center + vec3(radius));
    return Aabb(boxMin, boxMax);
}

bool Scene::hasMedia() const
{
    for (const InstanceDesc& inst : instances)
        if (!groups[inst.group].media.empty())
            return true;
    return false;
}

bool Scene::hasMotion() const
{
    for (const InstanceDesc& inst : instances)
        for (const SphereDesc& s : groups[inst.group].spheres)
            if (s.moving())
                return true;
    return false;
}

bool Scene::isEmissive(std::uint32_t material) const
{
    return material < materials.size() && materials[material].emissionTexture != kNoIndex;
}

bool Scene::hasMicrofacetMaterial() const
{
    return std::any_of(materials.begin(), materials.end(),
                       [](const MaterialData& m) { return isMicrofacetMaterial(m.type); });
}

std::uint32_t Scene::emitterCount() const
{
    std::uint32_t n = 0;
    while (n < lights.size() && lights[n].material != kNoIndex)
        ++n;
    return n;
}

std::size_t Scene::primitiveCount() const
{
    std::size_t count = 0;
    for (const InstanceDesc& inst : instances)
    {
        const GroupDesc& g = groups[inst.group];
        count += g.spheres.size() + g.quads.size() + g.media.size();
        for (const MeshRef& m : g.meshes)
            count += meshes[m.mesh].triangleCount();
    }
    return count;
}

Aabb Scene::bounds() const
{
    Aabb world;
    for (const InstanceDesc& inst : instances)
    {
        const GroupDesc& g = groups[inst.group];
        Aabb local;
        for (const SphereDesc& s : g.spheres)
            local.expand(s.bounds());
        for (const QuadDesc& q : g.quads)
            local.expand(q.bounds());
        for (const MeshRef& m : g.meshes)
            local.expand(meshes[m.mesh].bounds());
        for (const MediumDesc& m : g.media)
            local.expand(m.bounds());
        if (!local.empty())
            world.expand(inst.worldFromObject.bounds(local));
    }
    return world;
}

namespace
{
bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require(bool ok, const std::string& sceneId, const std::string& what)
{
    if (!ok)
        throw SceneError(fmt::format("scene '{}': {}", sceneId, what));
}
} // namespace

void Scene::validate() const
{
    const auto textureOk = [&](std::uint32_t t) { return t == kNoIndex || t < textures.size(); };
    require(std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(origin.z), id,
            "the scene's origin is not finite");
    for (std::size_t i = 0; i < textures.size(); ++i)
    {
        const TextureData& t = textures[i];
        require(std::isfinite(t.origin.x) && std::isfinite(t.origin.y) && std::isfinite(t.origin.z), id,
                fmt::format("texture {}'s origin is not finite", i));
        require(t.type != TextureType::Image || t.image < images.size(), id,
                fmt::format("texture {} refers to image {} of {}", i, t.image, images.size()));
    }
    for (std::size_t i = 0; i < images.size(); ++i)
        require(images[i].width > 0 && images[i].height > 0 &&
                    images[i].rgba.size() == std::size_t(images[i].width) * images[i].height * 4,
                id, fmt::format("image '{}' has no texels", images[i].path));
    for (std::size_t i = 0; i < materials.size(); ++i)
    {
        const MaterialData& m = materials[i];
        require(textureOk(m.albedoTexture) && textureOk(m.emissionTexture), id,
                fmt::format("material {} refers to a missing texture", i));
        require(m.type != MaterialType::Dielectric || m.ior > 0.0f, id,
                fmt::format("material {} has index of refraction {}", i, m.ior));
        require(m.type != MaterialType::DiffuseLight || m.emissionTexture != kNoIndex, id,
                fmt::format("diffuse light material {} has no emission", i));
        require(m.type == MaterialType::DiffuseLight || m.albedoTexture != kNoIndex ||
                    m.type == MaterialType::Dielectric || m.type == MaterialType::RoughDielectric ||
                    (m.type == MaterialType::Conductor && m.fresnel == FresnelModel::Exact),
                id, fmt::format("material {} has no albedo texture", i));
        require(!isMicrofacetMaterial(m.type) ||
                    (m.alphaX >= 0.0f && m.alphaX <= 1.0f && m.alphaY >= 0.0f && m.alphaY <= 1.0f),
                id,
                fmt::format("material {} has roughness alpha ({}, {}) outside [0, 1]", i, m.alphaX, m.alphaY));
        require((m.type != MaterialType::RoughDielectric && m.type != MaterialType::GltfPbr) ||
                    (m.ior > 0.0f && std::isfinite(m.ior)), id,
                fmt::format("material {} has index of refraction {}", i, m.ior));
        require(m.type != MaterialType::Conductor || m.fresnel == FresnelModel::Schlick ||
                    (glm::all(glm::greaterThan(m.eta, vec3(0.0f))) && glm::all(glm::greaterThanEqual(m.k, vec3(0.0f))) &&
                     std::isfinite(m.eta.x + m.eta.y + m.eta.z + m.k.x + m.k.y + m.k.z)), id,
                fmt::format("conductor material {} needs eta > 0 and k >= 0", i));
        require(m.type != MaterialType::GltfPbr ||
                    (m.metallic >= 0.0f && m.metallic <= 1.0f && textureOk(m.metallicRoughnessTexture)), id,
                fmt::format("glTF material {} has metallic {} outside [0, 1] or a missing texture", i, m.metallic));
    }
    const auto materialOk = [&](std::uint32_t m) { return m < materials.size(); };
    for (std::size_t gi = 0; gi < groups.size(); ++gi)
    {
        const GroupDesc& g = groups[gi];
        for (const SphereDesc& s : g.spheres)
            require(materialOk(s.material) && s.radius > 0.0f && finite(s.center0) && finite(s.center1), id,
                    fmt::format("group '{}' has a bad sphere (radius {}, material {})", g.name, s.radius,
                                s.material));
        for (const QuadDesc& q : g.quads)
            require(materialOk(q.material) && lengthSquared(glm::cross(q.u, q.v)) > 0.0f, id,
                    fmt::format("group '{}' has a degenerate quad or a bad material", g.name));
        for (const MeshRef& r : g.meshes)
        {
            require(r.mesh < meshes.size() && materialOk(r.material), id,
                    fmt::format("group '{}' refers to a missing mesh or material", g.name));
            const MeshData& mesh = meshes[r.mesh];
            require(mesh.indices.size() % 3 == 0 && !mesh.indices.empty(), id,
                    fmt::format("mesh '{}' has no triangles", mesh.name));
            for (std::uint32_t index : mesh.indices)
                require(index < mesh.positions.size(), id,
                        fmt::format("mesh '{}' has vertex index {} of {}", mesh.name, index, mesh.positions.size()));
            require(mesh.triangleMaterials.empty() || mesh.triangleMaterials.size() == mesh.triangleCount(), id,
                    fmt::format("mesh '{}' has {} per-triangle materials for {} triangles", mesh.name,
                                mesh.triangleMaterials.size(), mesh.triangleCount()));
            for (std::uint32_t m : mesh.triangleMaterials)
                require(materialOk(m), id, fmt::format("mesh '{}' refers to material {}", mesh.name, m));
        }
        for (const MediumDesc& m : g.media)
            require(materialOk(m.phaseMaterial) && materials[m.phaseMaterial].type == MaterialType::Isotropic &&
                        m.density > 0.0f,
                    id, fmt::format("group '{}' has a medium without an isotropic phase or density", g.name));
    }
    for (const InstanceDesc& inst : instances)
    {
        require(inst.group < groups.size(), id, fmt::format("instance of missing group {}", inst.group));
        const GroupDesc& g = groups[inst.group];
        const float det = glm::determinant(mat3(inst.worldFromObject.m));
        require(det != 0.0f, id, "an instance transform is singular");
        // A sphere under a non-uniform scale is an ellipsoid: neither engine's sphere test covers it.
        require(g.spheres.empty() || inst.worldFromObject.uniformScale().has_value(), id,
                fmt::format("group '{}' holds spheres and is instanced with a non-uniform scale or a mirror",
                            g.name));
        // A mirror reverses the winding of the group's quads and triangles: their world-space normals (u x v,
        // the edges' cross product) would point inward, turning glass inside out and lights away on both
        // engines. glTF import bakes its transforms and swaps the winding itself; instances cannot.
        require(det > 0.0f || (g.quads.empty() && g.meshes.empty()), id,
                fmt::format("group '{}' is instanced with a mirroring transform (negative determinant), which would "
                            "turn its quads' and triangles' faces inward: mirror the geometry itself instead",
                            g.name));
    }
    for (const LightData& l : lights)
        require(l.material == kNoIndex || materialOk(l.material), id, "a light refers to a missing material");
    require(lightSources.size() == lights.size(), id, "every light needs its source (SceneBuilder::finish)");
    const std::uint32_t emitters = emitterCount();
    for (std::size_t i = 0; i < lights.size(); ++i)
        require((lights[i].material == kNoIndex) == (lightSources[i].kind == LightSource::Kind::Target) &&
                    (i < emitters || lights[i].material == kNoIndex),
                id, "the emitters come first in the light list, then the sampling targets");
    require(!instances.empty(), id, "the scene has no instances");
}
} // namespace rt
