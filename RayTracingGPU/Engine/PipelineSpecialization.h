// What a path-tracing pipeline is compiled for: one value per HostDevice.h kSpecId*. The render settings
// (estimator, light sampler, light selection, pixel sampling) come from the render's uniforms, or stay
// kSpecDynamic for the general pipeline that reads them at run time. The features (kSpecIdFeatures: a mask
// of HostDevice.h's kFeature* bits) come from the scene (featureBitsOf: its geometry kinds, media, motion,
// the materials and texture kinds its primitives use, the shapes of its lights) and from the uniforms (thin
// lens, gradient background); kSpecDynamic there is every feature. Specialised, the driver folds away every
// estimator, sampler and selection the render does not use (1.1x to 5x faster on an H100, docs/notebook/PERFORMANCE.md
// §4.2), the code of every feature the scene lacks, without huge spheres the sphere tests' exact c (§8.8),
// without image textures the hit's uv (§8.10), and the pipeline holds only the hit groups of the scene's
// geometry (hitGroups()). The value is the key of the pipeline cache (PathTracingPipeline): two renders with
// equal keys share one compilation. The general pipeline is what every render used before specialisation,
// kept for comparison (--specialize off).
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <string>

#include "RayTracing/HitGroupLayout.h"
#include "Render/EngineOptions.h"
#include "Scene/Scene.h"
#include "Scene/SceneFeatures.h"
#include "Shared/HostDevice.h"

namespace rt::gpu
{
/// How far pipelines are specialised (--specialize, Render/EngineOptions.h).
using rt::Specialize;

struct PipelineSpecialization
{
    /// Constant id i's value; kSpecDynamic: the shader reads the uniform (for the features: every feature).
    std::array<std::uint32_t, shader::kSpecIdCount> constants{};

    /// Every constant kSpecDynamic.
    static PipelineSpecialization general();
    /// The settings of `uniforms` that have a constant id; every feature.
    static PipelineSpecialization strategyOf(const shader::RenderUniforms& uniforms);
    /// strategyOf(uniforms) and the features: `sceneFeatures` (featureBitsOf) with the uniforms' own bits, the
    /// exact c in the sphere tests only with `hugeSpheres` (SceneFeatures::hugeSpheres) and a hit's uv only with
    /// image textures among `sceneFeatures`.
    static PipelineSpecialization of(const shader::RenderUniforms& uniforms, std::uint32_t sceneFeatures,
                                     bool hugeSpheres = true);
    /// What `specialize` asks for a render of `uniforms` on a scene of `sceneFeatures` and `hugeSpheres`.
    static PipelineSpecialization of(Specialize specialize, const shader::RenderUniforms& uniforms,
                                     std::uint32_t sceneFeatures, bool hugeSpheres = true);

    std::uint32_t features() const { return constants[shader::kSpecIdFeatures]; }
    bool has(std::uint32_t featureBit) const { return (features() & featureBit) != 0u; }
    /// The hit groups the pipeline holds: those of the features' geometry kinds (every one for the general
    /// features).
    HitGroupLayout hitGroups() const;
    /// "general", or the constants in words (for logs): "estimator=1 sampler=0 ... features=spheres+metal".
    std::string describe() const;

    auto operator<=>(const PipelineSpecialization&) const = default;

private:
    /// The constants that come from the scene but are not feature bits, which a mixture with media sets too:
    /// the sphere tests' c and the hit's uv.
    void setSceneConstants(std::uint32_t sceneFeatures, bool hugeSpheres);
};

/// The kFeature* bits of what `scene` (valid) uses, but for the render's own (thin lens, gradient
/// background): SceneFeatures (Scene/SceneFeatures.h), the shapes of every light (emitters and the mixture's
/// sampling targets), and the geometry kinds of its TLAS instances, `hitGroups` (SceneLayout::hitGroups).
std::uint32_t featureBitsOf(const Scene& scene, const HitGroupLayout& hitGroups);
/// The same from the scene's `features` (featuresOf(scene)), computed once by a caller that needs them too.
std::uint32_t featureBitsOf(const Scene& scene, const SceneFeatures& features, const HitGroupLayout& hitGroups);
} // namespace rt::gpu
