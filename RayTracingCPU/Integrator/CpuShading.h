// The CPU engine's host of the shared shading (Common/Shared/Shading/README.md): what Shaders/Bindings.glsl and
// Shaders/Specialization.glsl are to the shaders. The path vertex, NEE, the materials, textures, background and
// camera samples of Shared/Shading/ are compiled as member functions of CpuShading, whose members are the globals
// they name: pointers into the CPU's scene, the render's uniforms, and, as compile-time constants, what the
// path loop's instance is compiled for (PathCode: Integrator/PathVariants.h picks one per render), so that an
// instance without media or textures carries none of their code, as a specialised GPU pipeline does.
#pragma once

#include <cstdint>

#include "Image/ImageIO.h"
#include "Engine/CpuScene.h"
#include "Scene/Perlin.h"
// The namespace-level Shared headers that the shading includes: first here, so that inside the class their
// include guards leave nothing.
#include "Shared/Bsdf/MicrofacetBsdf.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/Estimator.h"
#include "Shared/HostDevice.h"
#include "Shared/LightSampling.h"
#include "Shared/LightSelection.h"
#include "Shared/Medium.h"
#include "Shared/Mis.h"
#include "Shared/PathState.h"
#include "Shared/Perlin.h"
#include "Shared/Random.h"
#include "Shared/RayOffset.h"
#include "Shared/Restir.h"
#include "Shared/RussianRoulette.h"
#include "Shared/SpecularScattering.h"
#include "Shared/Warps.h"

namespace rt::cpu
{
/// What an instance of the path loop is compiled for. A structural type: it is a template's argument.
struct PathCode
{
    bool general = true; // the estimator from the uniforms at run time; media and every texture kind
    Estimator estimator = Estimator::NeeMis; // when !general
    bool media = true; // when !general: the scene has participating media (isotropic vertices, medium hits)
    // when !general: a material reads a texture other than a solid colour, or is a microfacet material (their
    // code rides with the textures' instances rather than doubling their count; compiled into every instance,
    // it made the diffuse scenes' NEE test the lobe type at run time: 0.94-0.96x on one core)
    bool textures = true;
};
} // namespace rt::cpu

// In rt::shader, where the shading's unqualified calls find the Shared functions they were written beside.
namespace rt::shader
{
template <cpu::PathCode C>
class CpuShading
{
public:
    /// The shading of `scene` (which it must outlive) with `uniforms` (kept by reference).
    CpuShading(const cpu::CpuScene& scene, const RenderUniforms& renderUniforms)
        : materials(scene.source().materials.data()), textures(scene.source().textures.data()),
          lights(scene.source().lights.data()), mixtureLights(lights), lightAlias(scene.lightAlias()),
          lightBvh(scene.lightBvh()), lightBvhLeaves(scene.lightBvhLeaves()), perlinTables(scene.perlinTables()),
          uniforms(renderUniforms), m_images(scene.source().images.data()), m_scene(&scene)
    {
    }

    // Bindings.glsl's globals.
    const MaterialData* materials;
    const TextureData* textures;
    const LightData* lights;
    const LightData* mixtureLights; // unread: the GPU's uniform copy of the first lights (kHostHasMixtureLights)
    const AliasEntry* lightAlias;
    const LightBvhNode* lightBvh;
    const uint* lightBvhLeaves;
    const PerlinData& perlinTables;
    const RenderUniforms& uniforms;

    // Specialization.glsl's: the CPU compiles the estimator, media and textures into each instance.
    static constexpr bool kHasLambertian = true;
    static constexpr bool kHasMetal = true;
    static constexpr bool kHasDielectric = true;
    // The microfacet materials come with the textured instances (PathCode::textures).
    static constexpr bool kHasConductor = C.general || C.textures;
    static constexpr bool kHasRoughDielectric = C.general || C.textures;
    static constexpr bool kHasGltfPbr = C.general || C.textures;
    static constexpr bool kHasIsotropic = C.general || C.media;
    static constexpr bool kHasMedia = C.general || C.media;
    static constexpr bool kHasCheckerTextures = C.general || C.textures;
    static constexpr bool kHasImageTextures = C.general || C.textures;
    static constexpr bool kHasNoiseTextures = C.general || C.textures;
    static constexpr bool kHasThinLens = true;
    static constexpr bool kHasGradientBackground = true;
    Estimator settingEstimator() const { return C.general ? uniforms.estimator : C.estimator; }
    LightSampler settingLightSampler() const { return uniforms.lightSampler; }
    LightSelection settingLightSelection() const { return uniforms.lightSelection; }
    PixelSampling settingSampling() const { return uniforms.sampling; }

    static constexpr bool kHostHasMixtureLights = false;

    /// The light of a hit primitive: the CPU's hits carry the light's index itself (CpuScene::interaction).
    static uint emitterOfSlot(uint slot) { return slot; }

    /// Nearest texel of image `image` at (u, v), v = 0 at the bottom; sRGB texels decoded to linear, or, where
    /// `linear` (data such as glTF's metallic-roughness), each byte / 255. The twin of
    /// Shaders/Textures/ImageTexture.glsl, which fetches the same texel (GpuCpuAgreement on rtnw-earth).
    vec3 imageTexel(uint image, vec2 uv, bool linear) const
    {
        const ImageData& data = m_images[image];
        const float u = clamp(uv.x, 0.0f, 1.0f);
        const float v = 1.0f - clamp(uv.y, 0.0f, 1.0f);
        const int i = std::min(static_cast<int>(u * static_cast<float>(data.width)), data.width - 1);
        const int j = std::min(static_cast<int>(v * static_cast<float>(data.height)), data.height - 1);
        const std::uint8_t* texel = &data.rgba[(std::size_t(j) * data.width + i) * 4];
        if (linear)
            return vec3(texel[0], texel[1], texel[2]) / 255.0f;
        return {srgb8ToLinear(texel[0]), srgb8ToLinear(texel[1]), srgb8ToLinear(texel[2])};
    }

    /// restir-di's visibility test (Shared/Shading/Restir.h): the shadow ray from v to `point` as camera sample
    /// `sampleIndex` of `pixel` traces it (its shutter time where a sphere moves, its medium seed where the scene
    /// has media), counted in restirShadowRays.
    bool restirVisible(const RestirVertex& v, vec3 point, uvec2 pixel, uint sampleIndex)
    {
        const ShadowRay s = restirShadowRay(v, point);
        ++restirShadowRays;
        const float time = m_scene->hasMotion() ? cameraSampleTime(pixel, sampleIndex) : 0.0f;
        const uint mediumSeed = kHasMedia && m_scene->hasMedia() ? mediumPathSeed(uniforms.seed, pixel) : 0u;
        return !m_scene->occluded(cpu::TraceRay(rt::Ray{s.origin, s.direction, time}, m_scene->rayNeeds()), 0.0f,
                                  s.distance, mediumSeed);
    }

    /// One input of a restir-di combination (combineReservoirs): a reservoir, the vertex it was resampled for and
    /// the camera sample whose path found that vertex.
    struct RestirInput
    {
        Reservoir reservoir;
        RestirVertex vertex;
        uvec2 pixel;
        uint sampleIndex = 0;
    };
    /// The inputs combineReservoirs reads: the passes point it at theirs before they combine.
    const RestirInput* restirInputs = nullptr;
    const Reservoir& restirInputReservoir(int i) const { return restirInputs[i].reservoir; }
    const RestirVertex& restirInputVertex(int i) const { return restirInputs[i].vertex; }
    uvec2 restirInputPixel(int i) const { return restirInputs[i].pixel; }
    uint restirInputSample(int i) const { return restirInputs[i].sampleIndex; }
    std::uint64_t restirShadowRays = 0;

#include "Shared/Shading/Background.h"
#include "Shared/Shading/Camera.h"
#include "Shared/Shading/PathVertex.h"
#include "Shared/Shading/Restir.h"

private:
    const ImageData* m_images;
    const cpu::CpuScene* m_scene;
};
} // namespace rt::shader

namespace rt::cpu
{
using shader::CpuShading;
} // namespace rt::cpu
