// The wavefront integrator (Shaders/Wavefront/, after Laine, Karras & Aila, "Megakernels Considered Harmful:
// Wavefront Path Tracing on GPUs", HPG 2013): the megakernel's loop (RayGen.rgen) cut into kernels per
// segment, so that the shading code (materials, light selection and sampling, MIS) runs in a compute kernel
// of its own instead of between the traces of a ray-tracing invocation. Per specialisation
// (PipelineSpecialization, the megakernel's key), it compiles a ray-tracing pipeline with two raygens
// (Extend.rgen: path rays to their first hits; Shadow.rgen: NEE's shadow rays) and the compute kernels
// Generate, Shade, Prepare and Accumulate, all on PathTracingPipeline's set 0 and push constants. Each path
// shades its vertices with the megakernel's own code (PathVertex.glsl) and is summed in sample order, so the
// two integrators compute the same estimator.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <span>

#include "Engine/PathTracingPipeline.h"
#include "RayTracing/RayTracingPipeline.h"
#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/ShaderModule.h"

namespace rt::gpu
{
class WaveBuffers;
class WaveStageTimer;

class WavefrontPipeline final
{
public:
    /// Loads the shaders; compiles nothing yet. `layout` (which must outlive this) gives the descriptor set
    /// layout, the pipeline layout and the specialisation of a render. Throws rt::AssetError for a missing
    /// shader, rt::DeviceError when the driver rejects a module.
    WavefrontPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                      const PathTracingPipeline& layout);
    WavefrontPipeline(const WavefrontPipeline&) = delete;
    WavefrontPipeline& operator=(const WavefrontPipeline&) = delete;
    ~WavefrontPipeline();

    /// Compiles the pipelines a render with `uniforms` of `scene` needs, unless they exist; true when it
    /// compiled them. Throws rt::DeviceError when the driver rejects one.
    bool prepare(const shader::RenderUniforms& uniforms, const PipelineScene& scene) const;

    /// Records `count` camera samples per pixel of `extent` (a band of rows from `firstRow` on), sample
    /// indices from `firstSample` on, as waves of at most waves.capacity() paths: each sample of a pixel
    /// after the one before, added to the accumulation images in sample order. `sets` (set 0 naming `waves`)
    /// are bound for both bind points; `uniforms` are those of its uniform buffer. Everything recorded is
    /// ordered before what comes next. With `timer`, a timestamp follows each kernel (begun by the caller).
    void recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                      const shader::RenderUniforms& uniforms, const PipelineScene& scene, std::uint32_t firstSample,
                      std::uint32_t count, VkExtent2D extent, std::uint32_t firstRow, const WaveBuffers& waves,
                      WaveStageTimer* timer = nullptr) const;

private:
    struct Compiled;
    const Compiled& compiled(const PipelineSpecialization& key) const;
    struct Tables;
    const Tables& tablesFor(const Compiled& compiled, const HitGroupLayout& scene) const;

    const vk::Device* m_device;
    const PathTracingPipeline* m_layout;
    PathTracingShaders m_rayTracingShaders; // Extend.rgen, then the megakernel's miss and hit stages, Shadow.rgen
    vk::ShaderModule m_generate;
    vk::ShaderModule m_shade;
    vk::ShaderModule m_prepare;
    vk::ShaderModule m_accumulate;
    mutable std::map<PipelineSpecialization, std::unique_ptr<Compiled>> m_compiled;
};
} // namespace rt::gpu
