// Everything of the path tracer that does not depend on the image size: the descriptor set layout of
// Bindings.glsl, the pipeline layout (push constants: TracePushConstants), the shader modules, and one
// ray-tracing pipeline per specialisation a render asked for (PipelineSpecialization, the cache key: the
// render's strategy and the scene's features; compiled on first use, then kept: compilation is the slow
// part), with one shader binding table per hit-record layout of the scenes it traced (the general pipeline
// serves scenes of every layout; a specialised one, the layout of its features).
// The Cost variant (the window's heatmap) swaps in the timed ray-generation shader and adds set kSetCost.
#pragma once

#include "Scene/Scene.h"

#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <vector>

#include "Engine/PipelineSpecialization.h"
#include "RayTracing/RayTracingPipeline.h"
#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/DescriptorSetLayout.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu
{
class GpuScene;
class RestirBuffers;
class WaveBuffers;

/// Every stage of the path tracer: the ray-tracing stages and the wavefront's compute kernels. Set 0 and the
/// push constants are visible to all of them.
inline constexpr VkShaderStageFlags kPathTracerStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
    VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_COMPUTE_BIT;

/// Where a render writes: bound to kBindingAccumulation, kBindingCompensation, kBindingUniforms, kBindingCounters
/// and kBindingTraceCounters, and restir-di's buffers to kBindingRestirSurfaces .. kBindingRestirTraced.
struct TargetBindings
{
    VkImageView accumulation = VK_NULL_HANDLE; // rgba32f storage image in GENERAL layout
    VkImageView compensation = VK_NULL_HANDLE; // rgba32f storage image in GENERAL layout, the sum's Kahan term
    VkBuffer uniforms = VK_NULL_HANDLE; // RenderUniforms
    VkBuffer counters = VK_NULL_HANDLE; // SampleCounters
    VkBuffer traceCounters = VK_NULL_HANDLE; // TraceCounters
    const RestirBuffers* restir = nullptr; // the frame's, for restir-di; null: the tracer's of one pixel
};

/// What a launch needs to know of the scene on the device (GpuScene::pipelineScene()).
struct PipelineScene
{
    std::uint32_t features = shader::kSpecDynamic; // featureBitsOf the scene
    bool hugeSpheres = true; // SceneFeatures::hugeSpheres: the sphere tests need the exact c
    HitGroupLayout hitGroups = HitGroupLayout::all(); // the hit records its TLAS instances name
    std::uint64_t tracedPrimitives = 0; // per TLAS instance, its BLAS's triangles, spheres and media, summed
};

enum class RayGenVariant
{
    Radiance, // RayGen.rgen
    Cost // RayGenCost.rgen: also times each sample (needs vk::Device::shaderClock())
};

class PathTracingPipeline final
{
public:
    /// Loads the shaders; compiles nothing yet. With Specialize::Off every render uses the general pipeline.
    /// Throws rt::AssetError for a missing shader, rt::DeviceError when the driver rejects a module.
    PathTracingPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                        RayGenVariant variant = RayGenVariant::Radiance, Specialize specialize = Specialize::Full);
    PathTracingPipeline(const PathTracingPipeline&) = delete;
    PathTracingPipeline& operator=(const PathTracingPipeline&) = delete;
    ~PathTracingPipeline() = default;

    const std::vector<vk::DescriptorBinding>& bindings() const { return m_bindings; }
    const vk::DescriptorSetLayout& setLayout() const { return m_setLayout; }
    /// Set kSetCost of the Cost variant (kBindingCost, kBindingCostStats); empty for Radiance.
    const std::vector<vk::DescriptorBinding>& costBindings() const { return m_costBindings; }
    const vk::DescriptorSetLayout& costSetLayout() const { return m_costSetLayout; }
    const vk::PipelineLayout& layout() const { return m_layout; }
    Specialize specializes() const { return m_specialize; }
    /// From the next launch on, how far pipelines are specialised; keeps what is compiled.
    void setSpecialize(Specialize specialize) { m_specialize = specialize; }
    /// The specialisation a render with `uniforms` of `scene` runs (PipelineSpecialization::of).
    PipelineSpecialization specializationFor(const shader::RenderUniforms& uniforms, const PipelineScene& scene) const;
    /// Compiles the pipeline a render with `uniforms` of `scene` needs, unless it already exists; recordLaunch
    /// calls it too, so call it first only to keep the compilation out of a timed span. Returns true at its first
    /// call for that pipeline (compiled now or by compileTogether): a driver may finish compiling at the first
    /// launch, which the caller then makes. Not thread-safe. Throws rt::DeviceError when the driver rejects the
    /// pipeline.
    bool prepare(const shader::RenderUniforms& uniforms, const PipelineScene& scene) const;
    /// Compiles the pipelines of `keys` not compiled yet, each on a thread of its own (CompileTogether.h).
    /// Throws rt::DeviceError when the driver rejects one (the others are kept).
    void compileTogether(std::span<const PipelineSpecialization> keys) const;
    /// Pipelines compiled so far.
    std::size_t compiledCount() const { return m_compiled.size(); }
    /// Size of the variable-count sampler array (the most images a scene may have).
    std::uint32_t maxImages() const { return m_maxImages; }

    /// Points every binding of `set` at the resources of `scene`, `target`, `waves` and `restir`.
    void writeDescriptors(const vk::Device& device, VkDescriptorSet set, const GpuScene& scene,
                          const TargetBindings& target, const WaveBuffers& waves, const RestirBuffers& restir) const;

    /// Records launches over `extent` tracing `count` camera samples per pixel, sample indices from
    /// `firstSample` on, at most `samplesPerLaunch` of them per launch (each thread loops over its samples:
    /// on an H100 that is 1.8x faster than one launch per sample), with `sets` bound from set 0, each launch
    /// ordered before whatever comes next, through the pipeline of `uniforms` (the contents of the uniform
    /// buffer the sets name) and `scene` (the scene the sets name), compiled first if need be. `extent` may be
    /// a band of the image's rows: positions from `firstRow` on in the row order of `rowInterleave`
    /// (Shared/BandOrder.h; launchPixel() in Bindings.glsl).
    void recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                      const shader::RenderUniforms& uniforms, const PipelineScene& scene, std::uint32_t firstSample,
                      std::uint32_t count, VkExtent2D extent, std::uint32_t samplesPerLaunch,
                      std::uint32_t firstRow = 0, std::uint32_t rowInterleave = 1) const;

private:
    struct Compiled
    {
        vk::Pipeline pipeline;
        HitGroupLayout hitGroups; // the pipeline's own
        mutable std::map<HitGroupLayout, ShaderBindingTable> sbts; // per scene layout: a cache, like m_compiled
        mutable bool prepared = false; // prepare() has returned true for it
    };
    std::unique_ptr<Compiled> make(const PipelineSpecialization& key) const;
    const Compiled& compiled(const PipelineSpecialization& key) const;
    const ShaderBindingTable& sbtFor(const Compiled& compiled, const HitGroupLayout& scene) const;

    const vk::Device* m_device;
    Specialize m_specialize;
    std::uint32_t m_maxImages;
    std::vector<vk::DescriptorBinding> m_bindings;
    vk::DescriptorSetLayout m_setLayout;
    std::vector<vk::DescriptorBinding> m_costBindings;
    vk::DescriptorSetLayout m_costSetLayout;
    vk::PipelineLayout m_layout;
    PathTracingShaders m_shaders;
    mutable std::map<PipelineSpecialization, std::unique_ptr<Compiled>> m_compiled;
};
} // namespace rt::gpu
