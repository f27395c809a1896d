#include "Scene/SceneFeatures.h"

#include <vector>

namespace rt
{
namespace
{
bool isIdentity(const Transform& t)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
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
    }
    useTexture(scene, m.albedoTexture, f);
    useTexture(scene, m.emissionTexture, f);
}
} // namespace

SceneFeatures featuresOf(const Scene& scene)
{
    SceneFeatures f;
    std::vector<bool> seenMaterial(scene.materials.size(), false);
    std::vector<bool> seenGroup(scene.groups.size(), false);
    for (const InstanceDesc& instance : scene.instances)
    {
        f.transformedInstances = f.transformedInstances || !isIdentity(instance.worldFromObject);
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
    add(transformedInstances, "instances");
    add(lambertian, "lambertian");
    add(metal, "metal");
    add(dielectric, "dielectric");
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
            {"transformed_instances", transformedInstances},
            {"lambertian", lambertian},
            {"metal", metal},
            {"dielectric", dielectric},
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
