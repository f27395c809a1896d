// The scene description both engines render: plain data, no engine code, no pointers between objects
// (indices only). The CPU engine builds its BVH from it, the GPU engine its BLAS/TLAS; neither keeps a
// copy of a scene of its own.
//
// Structure (pbrt-v4's BasicScene idea, two levels like a TLAS over BLASes):
//   groups    - sets of primitives in object space (spheres, quads, meshes, media);
//   instances - a group placed in the world by an affine transform;
//   lights    - the world-space list the light samplers draw from: every emitting primitive of every
//               instance (added by SceneBuilder::finish), then the extra sampling targets a scene names;
//               lightSources says which primitive each light is, so an engine can tell the light it hit.
// Units are arbitrary world units; colours are linear RGB (albedo in [0,1], radiance unbounded).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Math/Aabb.h"
#include "Math/Math.h"
#include "Math/Transform.h"
#include "Scene/Camera.h"
#include "Shared/HostDevice.h"

namespace rt
{
using shader::BackgroundType;
using shader::Estimator;
using shader::FresnelModel;
using shader::PixelSampling;
using shader::kNoIndex;
using shader::LightData;
using shader::MaterialData;
using shader::MaterialType;
using shader::TextureData;
using shader::TextureType;

/// A sphere, moving linearly from center0 (time 0) to center1 (time 1) when the two differ (RTTNW §2).
struct SphereDesc
{
    vec3 center0{0.0f};
    vec3 center1{0.0f};
    float radius = 1.0f;
    std::uint32_t material = 0;

    bool moving() const { return center0 != center1; }
    vec3 centerAt(float time) const { return center0 + time * (center1 - center0); }
    Aabb bounds() const;
};

/// The parallelogram Q + a u + b v, a, b in [0, 1]; its front side faces along u x v (RTTNW §6).
struct QuadDesc
{
    vec3 q{0.0f};
    vec3 u{1.0f, 0.0f, 0.0f};
    vec3 v{0.0f, 1.0f, 0.0f};
    std::uint32_t material = 0;

    Aabb bounds() const;
};

/// An indexed triangle mesh (counter-clockwise front faces). Vertex normals and uvs are optional.
struct MeshData
{
    std::string name;
    std::vector<vec3> positions;
    std::vector<vec3> normals; // empty, or one per position
    std::vector<vec2> uvs; // empty, or one per position
    std::vector<std::uint32_t> indices; // 3 per triangle
    std::vector<std::uint32_t> triangleMaterials; // empty, or one material per triangle (overrides MeshRef's)

    std::size_t triangleCount() const { return indices.size() / 3; }
    Aabb bounds() const;
};

/// A mesh of Scene::meshes used in a group with a material.
struct MeshRef
{
    std::uint32_t mesh = 0;
    std::uint32_t material = 0;
};

/// A constant-density participating medium with an isotropic phase function, bounded by a sphere or an
/// axis-aligned box in object space (RTTNW §9). The phase material is an Isotropic material.
struct MediumDesc
{
    enum class Boundary : std::uint32_t
    {
        Sphere,
        Box
    };
    Boundary boundary = Boundary::Sphere;
    vec3 center{0.0f}; // Sphere
    float radius = 1.0f; // Sphere
    vec3 boxMin{0.0f}; // Box
    vec3 boxMax{0.0f}; // Box
    float density = 1.0f; // extinction coefficient, per world unit
    std::uint32_t phaseMaterial = 0;

    Aabb bounds() const;
};

struct GroupDesc
{
    std::string name;
    std::vector<SphereDesc> spheres;
    std::vector<QuadDesc> quads;
    std::vector<MeshRef> meshes;
    std::vector<MediumDesc> media;

    bool empty() const { return spheres.empty() && quads.empty() && meshes.empty() && media.empty(); }
};

/// A group placed in the world. Any invertible affine transform that keeps handedness (determinant > 0) for
/// quads and meshes (a mirror would turn their faces inward), any invertible one for media; groups with
/// spheres need a similarity (rotation, uniform scale, translation): an ellipsoid is not a sphere.
struct InstanceDesc
{
    std::uint32_t group = 0;
    Transform worldFromObject;
};

/// An image texture's texels: 8-bit sRGB-encoded RGBA, row 0 at the top of the image.
struct ImageData
{
    std::string path;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

struct Background
{
    BackgroundType type = BackgroundType::Constant;
    vec3 color0{0.0f};
    vec3 color1{0.0f};
};

/// What a scene renders with when the user does not say otherwise.
struct SceneDefaults
{
    int spp = 100;
    int depth = 50;
    int width = 600;
    float aspect = 1.0f; // width / height
    bool unidirectionalLight = true; // emitters emit from their front side only (RTTROYL §12.4)
    // This project's scenes use NEE + MIS; the books' keep book 3's mixture, so a render compares with theirs.
    shader::Estimator estimator = shader::Estimator::NeeMis;
    // This project's scenes draw Owen-scrambled Sobol samples, which keep the spherical samplers' stratification
    // (the largest gain after the projected samplers, docs/notebook/PERFORMANCE.md §4.1; pbrt-v4's default sampler is a
    // Sobol one too); the books' keep independent random samples.
    shader::PixelSampling sampling = shader::PixelSampling::Sobol;
};

/// The primitive a light of Scene::lights was made from, so that a hit on it can name its light (the
/// MIS weight of an emitter hit by a BSDF ray needs that light's selection pmf and pdf).
struct LightSource
{
    enum class Kind : std::uint32_t
    {
        Quad, // groups[instances[instance].group].quads[primitive]
        Sphere, // ... .spheres[primitive]
        Triangle, // triangle `primitive` of the mesh of ... .meshes[meshRef]
        Target // a sampling target (SceneBuilder::samplingTargetSphere): no primitive, emits nothing
    };
    Kind kind = Kind::Target;
    std::uint32_t instance = 0;
    std::uint32_t meshRef = 0;
    std::uint32_t primitive = 0;
};

/// The microfacet BSDFs (Shared/Bsdf/): conductor, rough dielectric, glTF metallic-roughness; their GGX alpha is
/// MaterialData::alphaX, alphaY.
constexpr bool isMicrofacetMaterial(MaterialType type)
{
    return type == MaterialType::Conductor || type == MaterialType::RoughDielectric || type == MaterialType::GltfPbr;
}

struct Scene
{
    std::string id;
    CameraDesc camera;
    Background background;
    SceneDefaults defaults;

    std::vector<TextureData> textures;
    std::vector<ImageData> images;
    std::vector<MaterialData> materials;
    std::vector<MeshData> meshes;
    std::vector<GroupDesc> groups;
    std::vector<InstanceDesc> instances;
    std::vector<LightData> lights;
    std::vector<LightSource> lightSources; // one per light
    /// Where this scene's coordinate origin lies in the world, in double: every position above is relative to
    /// it (3D Tiles' RTC_CENTER idea). 0 as built; --translate-scene and a scene file's "origin" move it, so a
    /// scene far from the world's origin keeps float32's precision near its own; toRenderSpace moves it to the
    /// camera (Scene/RenderSpace.h).
    dvec3 origin{0.0};

    bool hasMedia() const;
    bool hasMotion() const;
    bool isEmissive(std::uint32_t material) const;
    /// Whether some material is a microfacet one (isMicrofacetMaterial), used by a primitive or not.
    bool hasMicrofacetMaterial() const;
    /// The lights that emit: lights[0, emitterCount()) (the sampling targets follow them).
    std::uint32_t emitterCount() const;
    std::size_t primitiveCount() const; // spheres + quads + triangles + media over all instances
    Aabb bounds() const; // world-space bounds of every instance

    /// Checks every index and value a renderer relies on; throws rt::SceneError naming the first problem.
    void validate() const;
};
} // namespace rt
