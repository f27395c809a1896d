// The vocabulary the scene catalogue is written in: textures, materials, shapes, groups and instances in
// the books' terms, and finish(), which derives the world-space light list and validates the result.
#pragma once

#include <cstdint>
#include <string>

#include "Scene/Scene.h"

namespace rt
{
class SceneBuilder
{
public:
    explicit SceneBuilder(std::string id);

    Scene& scene() { return m_scene; }

    // Textures (indices into Scene::textures).
    std::uint32_t solid(const vec3& color);
    std::uint32_t checker(float scale, const vec3& even, const vec3& odd);
    std::uint32_t image(const std::string& assetPath); // loads the image now; throws AssetError if missing
    std::uint32_t perlin(TextureType type, float scale);

    // Materials (indices into Scene::materials).
    std::uint32_t lambertian(const vec3& albedo) { return lambertianTextured(solid(albedo)); }
    std::uint32_t lambertianTextured(std::uint32_t texture);
    std::uint32_t metal(const vec3& albedo, float fuzz);
    std::uint32_t dielectric(float ior);
    std::uint32_t diffuseLight(const vec3& radiance);
    std::uint32_t isotropic(const vec3& albedo);
    /// A rough conductor of GGX roughness (alphaX, alphaY) with the exact Fresnel term of eta + i k (per channel).
    std::uint32_t conductor(const vec3& eta, const vec3& k, float alphaX, float alphaY);
    /// A rough conductor whose Fresnel term is Schlick's from the reflectance f0 at normal incidence.
    std::uint32_t conductorSchlick(const vec3& f0, float alphaX, float alphaY);
    /// Rough glass of GGX roughness alpha and index of refraction ior (inside / outside).
    std::uint32_t roughDielectric(float alpha, float ior);
    /// glTF 2.0's metallic-roughness material: factors, textures (kNoIndex: none) and the dielectric's ior.
    std::uint32_t gltfPbr(std::uint32_t baseColorTexture, float metallic, float roughness,
                          std::uint32_t metallicRoughnessTexture, float ior = 1.5f);
    /// A Lambertian surface that also emits: the white furnace's walls.
    std::uint32_t emissiveLambertian(const vec3& albedo, const vec3& radiance);

    // Groups of primitives in object space, and their instances.
    std::uint32_t group(const std::string& name);
    /// The group placed with the identity transform, created on first use.
    std::uint32_t world();
    void instance(std::uint32_t group, const Transform& worldFromObject);

    void sphere(std::uint32_t group, const vec3& center, float radius, std::uint32_t material);
    void movingSphere(std::uint32_t group, const vec3& center0, const vec3& center1, float radius,
                      std::uint32_t material);
    void quad(std::uint32_t group, const vec3& q, const vec3& u, const vec3& v, std::uint32_t material);
    /// The six outward-facing quads of the axis-aligned box between corners a and b (RTTNW §6.6).
    void box(std::uint32_t group, const vec3& a, const vec3& b, std::uint32_t material);
    std::uint32_t addMesh(MeshData mesh);
    void mesh(std::uint32_t group, std::uint32_t mesh, std::uint32_t material);
    void sphereMedium(std::uint32_t group, const vec3& center, float radius, float density, const vec3& albedo);
    void boxMedium(std::uint32_t group, const vec3& a, const vec3& b, float density, const vec3& albedo);

    /// A sphere the light samplers aim at although it does not emit (RTTROYL §12.5: the glass sphere).
    void samplingTargetSphere(const vec3& center, float radius);

    /// Adds every emitting primitive of every instance to the light list (world space), validates, returns.
    Scene finish();

private:
    std::uint32_t material(MaterialData m);

    Scene m_scene;
    std::uint32_t m_world = kNoIndex;
};
} // namespace rt
