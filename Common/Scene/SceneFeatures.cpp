#include "Scene/SceneFeatures.h"

#include <algorithm>
#include <vector>

#include "Shared/SphereQuadratic.h"

namespace rt
{
namespace
{
/// Whether the linear part is the identity: translations are not counted, as render space gives every instance one.
bool isIdentityLinear(const Transform& t)
{
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (t.m[c][r] != (c == r ? 1.0f : 0.0f))
                return false;
    return true;
}

void useTexture(const Scene& scene, std::uint32_t texture, SceneFeatures& f)
{
    if (texture == kNoIndex || texture >= scene.textures.size())
        return;
    switch (scene.textures[texture].type)
    {
    case TextureType::Solid: break;
    case TextureType::Checker: f.checkerTextures = true; break;
    case TextureType::Image: f.imageTextures = true; break;
    case TextureType::Noise:
    case TextureType::Turbulence:
    case TextureType::Marble: f.noiseTextures = true; break;
    }
}

void useMaterial(const Scene& scene, std::uint32_t material, std::vector<bool>& seen, SceneFeatures& f)
{
    if (material >= scene.materials.size() || seen[material])
        return;
    seen[material] = true;
    const MaterialData& m = scene.materials[material];
    switch (m.type)
    {
    case MaterialType::Lambertian: f.lambertian = true; break;
    case MaterialType::Metal: f.metal = true; break;
    case MaterialType::Dielectric: f.dielectric = true; break;
    case MaterialType::DiffuseLight: f.diffuseLight = true; break;
    case MaterialType::Isotropic: break; // the media's phase function: SceneFeatures::media
    case MaterialType::Conductor: f.conductor = true; break;
    case MaterialType::RoughDielectric: f.roughDielectric = true; break;
    case MaterialType::GltfPbr: f.gltfPbr = true; break;
    }
    useTexture(scene, m.albedoTexture, f);
    useTexture(scene, m.emissionTexture, f);
    if (m.type == MaterialType::GltfPbr)
        useTexture(scene, m.metallicRoughnessTexture, f);
}

/// The largest factor by which `t` stretches a length (the longest column of its linear part).
float lengthScale(const Transform& t)
{
    return std::max({glm::length(vec3(t.m[0])), glm::length(vec3(t.m[1])), glm::length(vec3(t.m[2]))});
}

/// A sphere of the scene, surface (spheres[index]) or medium boundary (media[index]), of an instance.
struct SphereRef
{
    std::size_t instance = 0;
    bool medium = false;
    std::size_t index = 0;
    float worldRadius = -1.0f;
};

/// Object-space bounds of `g`'s primitives but one: media[skip] if `skipMedium`, else spheres[skip] (kNoSkip:
/// none).
constexpr std::size_t kNoSkip = std::size_t(-1);
Aabb groupBoundsBut(const Scene& scene, const GroupDesc& g, bool skipMedium, std::size_t skip)
{
    Aabb box;
    for (std::size_t i = 0; i < g.spheres.size(); ++i)
        if (skipMedium || i != skip)
            box.expand(g.spheres[i].bounds());
    for (const QuadDesc& q : g.quads)
        box.expand(q.bounds());
    for (const MeshRef& m : g.meshes)
        box.expand(scene.meshes[m.mesh].bounds());
    for (std::size_t i = 0; i < g.media.size(); ++i)
        if (!skipMedium || i != skip)
            box.expand(g.media[i].bounds());
    return box;
}

/// SceneFeatures::hugeSpheres. Only the largest sphere can be huge: every other one lies in the rest.
bool hasHugeSphere(const Scene& scene)
{
    SphereRef largest;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
    {
        const GroupDesc& g = scene.groups[scene.instances[i].group];
        const float scale = lengthScale(scene.instances[i].worldFromObject);
        for (std::size_t k = 0; k < g.spheres.size(); ++k)
            if (scale * g.spheres[k].radius > largest.worldRadius)
                largest = {i, false, k, scale * g.spheres[k].radius};
        for (std::size_t k = 0; k < g.media.size(); ++k)
        {
            const bool sphere = g.media[k].boundary == MediumDesc::Boundary::Sphere;
            if (sphere && scale * g.media[k].radius > largest.worldRadius)
                largest = {i, true, k, scale * g.media[k].radius};
        }
    }
    if (largest.worldRadius < 0.0f)
        return false;
    Aabb rest;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
    {
        const InstanceDesc& instance = scene.instances[i];
        const Aabb local = groupBoundsBut(scene, scene.groups[instance.group], largest.medium,
                                          i == largest.instance ? largest.index : kNoSkip);
        if (!local.empty())
            rest.expand(instance.worldFromObject.bounds(local));
    }
    // Rays start from the rest and from the camera, which may hover over a lone planet: its point nearest the
    // camera counts too.
    const InstanceDesc& instance = scene.instances[largest.instance];
    const GroupDesc& g = scene.groups[instance.group];
    const vec3 centre = instance.worldFromObject.point(largest.medium ? g.media[largest.index].center
                                                                      : g.spheres[largest.index].center0);
    const vec3 toCamera = scene.camera.lookFrom - centre;
    const float cameraDistance = glm::length(toCamera);
    rest.expand(scene.camera.lookFrom);
    rest.expand(centre + (cameraDistance > 0.0f ? (largest.worldRadius / cameraDistance) * toCamera
                                                : vec3(largest.worldRadius, 0.0f, 0.0f)));
    const float restSize = glm::length(rest.extent());
    return shader::kSphereRootError * largest.worldRadius > kHugeSphereTolerance * restSize;
}
} // namespace

SceneFeatures featuresOf(const Scene& scene)
{
    SceneFeatures f;
    std::vector<bool> seenMaterial(scene.materials.size(), false);
    std::vector<bool> seenGroup(scene.groups.size(), false);
    for (const InstanceDesc& instance : scene.instances)
    {
        f.transformedInstances = f.transformedInstances || !isIdentityLinear(instance.worldFromObject);
        if (seenGroup[instance.group])
            continue;
        seenGroup[instance.group] = true;
        const GroupDesc& g = scene.groups[instance.group];
        for (const SphereDesc& s : g.spheres)
        {
            f.spheres = true;
            f.motionBlur = f.motionBlur || s.moving();
            useMaterial(scene, s.material, seenMaterial, f);
        }
        for (const QuadDesc& q : g.quads)
        {
            f.quads = true;
            useMaterial(scene, q.material, seenMaterial, f);
        }
        for (const MeshRef& m : g.meshes)
        {
            f.meshes = true;
            useMaterial(scene, m.material, seenMaterial, f);
            for (const std::uint32_t material : scene.meshes[m.mesh].triangleMaterials)
                useMaterial(scene, material, seenMaterial, f);
        }
        for (const MediumDesc& m : g.media)
        {
            f.media = true;
            useMaterial(scene, m.phaseMaterial, seenMaterial, f);
        }
    }
    const std::uint32_t emitters = scene.emitterCount();
    for (std::uint32_t i = 0; i < emitters; ++i)
        switch (scene.lights[i].shape)
        {
        case shader::LightShape::Quad: f.quadEmitters = true; break;
        case shader::LightShape::Sphere: f.sphereEmitters = true; break;
        case shader::LightShape::Triangle: f.triangleEmitters = true; break;
        }
    f.hugeSpheres = hasHugeSphere(scene);
    f.thinLens = scene.camera.defocusAngleDegrees > 0.0f;
    f.background = scene.background.type;
    f.blackBackground = scene.background.type == BackgroundType::Constant && scene.background.color0 == vec3(0.0f);
    return f;
}

std::string SceneFeatures::describe() const
{
    std::string s;
    const auto add = [&s](bool on, const char* word) {
        if (!on)
            return;
        if (!s.empty())
            s += ' ';
        s += word;
    };
    add(spheres, "spheres");
    add(quads, "quads");
    add(meshes, "meshes");
    add(media, "media");
    add(motionBlur, "motion-blur");
    add(hugeSpheres, "huge-spheres");
    add(transformedInstances, "instances");
    add(lambertian, "lambertian");
    add(metal, "metal");
    add(dielectric, "dielectric");
    add(conductor, "conductor");
    add(roughDielectric, "rough-dielectric");
    add(gltfPbr, "gltf-pbr");
    add(diffuseLight, "diffuse-light");
    add(checkerTextures, "checker");
    add(imageTextures, "image-textures");
    add(noiseTextures, "noise-textures");
    add(sphereEmitters, "sphere-emitters");
    add(quadEmitters, "quad-emitters");
    add(triangleEmitters, "triangle-emitters");
    add(thinLens, "thin-lens");
    add(background == BackgroundType::Gradient, "gradient-sky");
    add(blackBackground, "black-background");
    return s;
}

nlohmann::json SceneFeatures::toJson() const
{
    return {{"spheres", spheres},
            {"quads", quads},
            {"meshes", meshes},
            {"media", media},
            {"motion_blur", motionBlur},
            {"huge_spheres", hugeSpheres},
            {"transformed_instances", transformedInstances},
            {"lambertian", lambertian},
            {"metal", metal},
            {"dielectric", dielectric},
            {"conductor", conductor},
            {"rough_dielectric", roughDielectric},
            {"gltf_pbr", gltfPbr},
            {"diffuse_light", diffuseLight},
            {"checker_textures", checkerTextures},
            {"image_textures", imageTextures},
            {"noise_textures", noiseTextures},
            {"sphere_emitters", sphereEmitters},
            {"quad_emitters", quadEmitters},
            {"triangle_emitters", triangleEmitters},
            {"thin_lens", thinLens},
            {"background", background == BackgroundType::Gradient ? "gradient" : "constant"},
            {"black_background", blackBackground}};
}
} // namespace rt
