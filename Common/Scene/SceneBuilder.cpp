#include "Scene/SceneBuilder.h"

#include <spdlog/fmt/fmt.h>

#include "Assets/ImageLoader.h"
#include "Error.h"
#include "Scene/EmitterLight.h"
#include "Sampling/LightSampling.h"

namespace rt
{
namespace
{
template <typename T>
std::uint32_t append(std::vector<T>& list, T value)
{
    list.push_back(std::move(value));
    return static_cast<std::uint32_t>(list.size() - 1);
}

} // namespace

SceneBuilder::SceneBuilder(std::string id) { m_scene.id = std::move(id); }

std::uint32_t SceneBuilder::solid(const vec3& color)
{
    TextureData t{};
    t.type = TextureType::Solid;
    t.color0 = color;
    return append(m_scene.textures, t);
}

std::uint32_t SceneBuilder::checker(float scale, const vec3& even, const vec3& odd)
{
    TextureData t{};
    t.type = TextureType::Checker;
    t.scale = scale;
    t.color0 = even;
    t.color1 = odd;
    return append(m_scene.textures, t);
}

std::uint32_t SceneBuilder::image(const std::string& assetPath)
{
    TextureData t{};
    t.type = TextureType::Image;
    t.image = append(m_scene.images, loadImage(assetPath));
    return append(m_scene.textures, t);
}

std::uint32_t SceneBuilder::perlin(TextureType type, float scale)
{
    TextureData t{};
    t.type = type;
    t.scale = scale;
    return append(m_scene.textures, t);
}

std::uint32_t SceneBuilder::material(MaterialData m)
{
    if (m.type != MaterialType::GltfPbr)
        m.metallicRoughnessTexture = kNoIndex; // one spelling of "none", as the scene reader writes it
    return append(m_scene.materials, m);
}

std::uint32_t SceneBuilder::lambertianTextured(std::uint32_t texture)
{
    return material({.type = MaterialType::Lambertian, .albedoTexture = texture, .emissionTexture = kNoIndex});
}

std::uint32_t SceneBuilder::metal(const vec3& albedo, float fuzz)
{
    return material({.type = MaterialType::Metal,
                     .albedoTexture = solid(albedo),
                     .emissionTexture = kNoIndex,
                     .fuzz = fuzz < 1.0f ? fuzz : 1.0f});
}

std::uint32_t SceneBuilder::dielectric(float ior)
{
    return material(
        {.type = MaterialType::Dielectric, .albedoTexture = kNoIndex, .emissionTexture = kNoIndex, .ior = ior});
}

std::uint32_t SceneBuilder::diffuseLight(const vec3& radiance)
{
    return material(
        {.type = MaterialType::DiffuseLight, .albedoTexture = kNoIndex, .emissionTexture = solid(radiance)});
}

std::uint32_t SceneBuilder::isotropic(const vec3& albedo)
{
    return material({.type = MaterialType::Isotropic, .albedoTexture = solid(albedo), .emissionTexture = kNoIndex});
}

std::uint32_t SceneBuilder::conductor(const vec3& eta, const vec3& k, float alphaX, float alphaY)
{
    return material({.type = MaterialType::Conductor,
                     .albedoTexture = kNoIndex,
                     .emissionTexture = kNoIndex,
                     .fresnel = FresnelModel::Exact,
                     .alphaX = alphaX,
                     .alphaY = alphaY,
                     .eta = eta,
                     .k = k,
                     .metallicRoughnessTexture = kNoIndex});
}

std::uint32_t SceneBuilder::conductorSchlick(const vec3& f0, float alphaX, float alphaY)
{
    return material({.type = MaterialType::Conductor,
                     .albedoTexture = solid(f0),
                     .emissionTexture = kNoIndex,
                     .fresnel = FresnelModel::Schlick,
                     .alphaX = alphaX,
                     .alphaY = alphaY,
                     .metallicRoughnessTexture = kNoIndex});
}

std::uint32_t SceneBuilder::roughDielectric(float alpha, float ior)
{
    return material({.type = MaterialType::RoughDielectric,
                     .albedoTexture = kNoIndex,
                     .emissionTexture = kNoIndex,
                     .ior = ior,
                     .fresnel = FresnelModel::Exact,
                     .alphaX = alpha,
                     .alphaY = alpha,
                     .metallicRoughnessTexture = kNoIndex});
}

std::uint32_t SceneBuilder::gltfPbr(std::uint32_t baseColorTexture, float metallic, float roughness,
                                    std::uint32_t metallicRoughnessTexture, float ior)
{
    return material({.type = MaterialType::GltfPbr,
                     .albedoTexture = baseColorTexture,
                     .emissionTexture = kNoIndex,
                     .ior = ior,
                     .alphaX = roughness * roughness, // glTF 2.0 Appendix B.3.2: alpha = roughness^2
                     .alphaY = roughness * roughness,
                     .metallic = metallic,
                     .metallicRoughnessTexture = metallicRoughnessTexture});
}

std::uint32_t SceneBuilder::emissiveLambertian(const vec3& albedo, const vec3& radiance)
{
    const std::uint32_t albedoTexture = solid(albedo);
    return material(
        {.type = MaterialType::Lambertian, .albedoTexture = albedoTexture, .emissionTexture = solid(radiance)});
}

std::uint32_t SceneBuilder::group(const std::string& name)
{
    GroupDesc g;
    g.name = name;
    return append(m_scene.groups, std::move(g));
}

std::uint32_t SceneBuilder::world()
{
    if (m_world == kNoIndex)
    {
        m_world = group("world");
        instance(m_world, Transform::identity());
    }
    return m_world;
}

void SceneBuilder::instance(std::uint32_t g, const Transform& worldFromObject)
{
    m_scene.instances.push_back({g, worldFromObject});
}

void SceneBuilder::sphere(std::uint32_t g, const vec3& center, float radius, std::uint32_t mat)
{
    m_scene.groups.at(g).spheres.push_back({center, center, radius, mat});
}

void SceneBuilder::movingSphere(std::uint32_t g, const vec3& center0, const vec3& center1, float radius,
                                std::uint32_t mat)
{
    m_scene.groups.at(g).spheres.push_back({center0, center1, radius, mat});
}

void SceneBuilder::quad(std::uint32_t g, const vec3& q, const vec3& u, const vec3& v, std::uint32_t mat)
{
    m_scene.groups.at(g).quads.push_back({q, u, v, mat});
}

void SceneBuilder::box(std::uint32_t g, const vec3& a, const vec3& b, std::uint32_t mat)
{
    const vec3 lo = glm::min(a, b);
    const vec3 hi = glm::max(a, b);
    const vec3 dx(hi.x - lo.x, 0.0f, 0.0f);
    const vec3 dy(0.0f, hi.y - lo.y, 0.0f);
    const vec3 dz(0.0f, 0.0f, hi.z - lo.z);
    quad(g, {lo.x, lo.y, hi.z}, dx, dy, mat); // front (+z)
    quad(g, {hi.x, lo.y, hi.z}, -dz, dy, mat); // right (+x)
    quad(g, {hi.x, lo.y, lo.z}, -dx, dy, mat); // back (-z)
    quad(g, {lo.x, lo.y, lo.z}, dz, dy, mat); // left (-x)
    quad(g, {lo.x, hi.y, hi.z}, dx, -dz, mat); // top (+y)
    quad(g, {lo.x, lo.y, lo.z}, dx, dz, mat); // bottom (-y)
}

std::uint32_t SceneBuilder::addMesh(MeshData mesh) { return append(m_scene.meshes, std::move(mesh)); }

void SceneBuilder::mesh(std::uint32_t g, std::uint32_t meshIndex, std::uint32_t mat)
{
    m_scene.groups.at(g).meshes.push_back({meshIndex, mat});
}

void SceneBuilder::sphereMedium(std::uint32_t g, const vec3& center, float radius, float density,
                                const vec3& albedo)
{
    MediumDesc m;
    m.boundary = MediumDesc::Boundary::Sphere;
    m.center = center;
    m.radius = radius;
    m.density = density;
    m.phaseMaterial = isotropic(albedo);
    m_scene.groups.at(g).media.push_back(m);
}

void SceneBuilder::boxMedium(std::uint32_t g, const vec3& a, const vec3& b, float density, const vec3& albedo)
{
    MediumDesc m;
    m.boundary = MediumDesc::Boundary::Box;
    m.boxMin = glm::min(a, b);
    m.boxMax = glm::max(a, b);
    m.density = density;
    m.phaseMaterial = isotropic(albedo);
    m_scene.groups.at(g).media.push_back(m);
}

void SceneBuilder::samplingTargetSphere(const vec3& center, float radius)
{
    m_scene.lights.push_back(makeSphereLight(center, radius, kNoIndex));
}

Scene SceneBuilder::finish()
{
    Scene& s = m_scene;
    std::vector<LightData> lights;
    std::vector<LightSource> sources;
    const auto add = [&](const LightData& light, LightSource source) {
        lights.push_back(light);
        sources.push_back(source);
    };
    const auto addIfLit = [&](LightSource source) {
        if (const auto light = emitterLight(s, source))
            add(*light, source);
    };
    for (std::uint32_t i = 0; i < s.instances.size(); ++i)
    {
        const InstanceDesc& inst = s.instances[i];
        if (inst.group >= s.groups.size())
            break; // validate() reports it
        const GroupDesc& g = s.groups[inst.group];
        for (std::uint32_t k = 0; k < g.quads.size(); ++k)
            if (s.isEmissive(g.quads[k].material))
                addIfLit({.kind = LightSource::Kind::Quad, .instance = i, .primitive = k});
        for (std::uint32_t k = 0; k < g.spheres.size(); ++k)
            if (s.isEmissive(g.spheres[k].material))
                addIfLit({.kind = LightSource::Kind::Sphere, .instance = i, .primitive = k});
        for (std::uint32_t r = 0; r < g.meshes.size(); ++r)
        {
            const MeshRef& ref = g.meshes[r];
            if (ref.mesh >= s.meshes.size())
                break;
            const MeshData& mesh = s.meshes[ref.mesh];
            for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t)
            {
                const std::uint32_t mat = mesh.triangleMaterials.empty() ? ref.material : mesh.triangleMaterials[t];
                if (s.isEmissive(mat))
                    addIfLit({.kind = LightSource::Kind::Triangle, .instance = i, .meshRef = r, .primitive = t});
            }
        }
    }
    // Emitters first, then the explicit sampling targets, in the order the scene added them.
    for (const LightData& target : s.lights)
        add(target, {.kind = LightSource::Kind::Target});
    s.lights = std::move(lights);
    s.lightSources = std::move(sources);
    s.validate();
    return std::move(m_scene);
}
} // namespace rt
