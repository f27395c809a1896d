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
#include <vector>

#include "Engine/PathTracingPipeline.h"
#include "RayTracing/RayTracingPipeline.h"
#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/ShaderModule.h"

namespace rt::gpu
{
class WaveBuffers;
class WaveStageTimer;
enum class WaveStage;

/// One wave of a launch: `samples` camera samples from `firstSample` on of each pixel of [pixelBegin, pixelBegin +
/// pixelCount), an index being position * width + x in the frame's row order (Shared/BandOrder.h; y * width + x
/// where the rows are in order).
struct Wave
{
    std::uint32_t firstSample = 0;
    std::uint32_t samples = 0;
    std::uint32_t pixelBegin = 0;
    std::uint32_t pixelCount = 0;
};

/// The waves of `count` samples per pixel from `firstSample` on over `extent` (rows from position `firstRow` on of
/// the frame's row order; a wave's pixels are indices position * width + x of that order), at
/// most `capacity` paths each, the pixels spread evenly over the waves of a sample range, in the order they must
/// run: a pixel's earlier samples first. Pure.
std::vector<Wave> planWaves(std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent, std::uint32_t firstRow,
                            std::uint32_t capacity);

class WavefrontPipeline final
{
    struct Compiled;
    struct Tables;

public:
    /// Loads the shaders; compiles nothing yet. `layout` (which must outlive this) gives the descriptor set
    /// layout, the pipeline layout and the specialisation of a render. Throws rt::AssetError for a missing
    /// shader, rt::DeviceError when the driver rejects a module.
    WavefrontPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                      const PathTracingPipeline& layout);
    WavefrontPipeline(const WavefrontPipeline&) = delete;
    WavefrontPipeline& operator=(const WavefrontPipeline&) = delete;
    ~WavefrontPipeline();

    /// Compiles the pipelines a render with `uniforms` of `scene` needs, unless they exist; true at its first
    /// call for them (compiled now or by compileTogether; as PathTracingPipeline::prepare). Throws
    /// rt::DeviceError when the driver rejects one.
    bool prepare(const shader::RenderUniforms& uniforms, const PipelineScene& scene) const;
    /// Compiles the pipelines of `keys` not compiled yet, a key's on a thread of its own (CompileTogether.h).
    /// Throws rt::DeviceError when the driver rejects one (the others are kept).
    void compileTogether(std::span<const PipelineSpecialization> keys) const;
    /// Keys compiled so far.
    std::size_t compiledCount() const { return m_compiled.size(); }

    /// Records a launch's waves into one command buffer, a wave at a time: start, its segments (all of them,
    /// or in chunks over several submissions, stopping once the caller sees the queues empty: the engine's
    /// headless batches), finish. Binds `sets` for both bind points (set 0, naming `waves`); `uniforms` are
    /// those of its uniform buffer. With `timer`, a timestamp follows each kernel (begun by the caller).
    class Recorder final
    {
    public:
        Recorder(const WavefrontPipeline& pipeline, VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                 const shader::RenderUniforms& uniforms, const PipelineScene& scene, std::uint32_t firstRow,
                 std::uint32_t rowInterleave,
                 const WaveBuffers& waves, WaveStageTimer* timer = nullptr);

        /// The counters reset, the camera rays of `wave` and its first queue.
        void start(const Wave& wave);
        /// Segments [first, last) of `wave`: path rays, vertices, the next queue's size, shadow rays.
        void segments(const Wave& wave, std::uint32_t first, std::uint32_t last);
        /// The sums of `wave`'s pixels, ordered before whatever comes next.
        void finish(const Wave& wave);

    private:
        void use(const Wave& wave);
        void pushConstants() const;
        void ordered(WaveStage stage) const;
        void dispatch(WaveStage stage, const vk::Pipeline& pipeline, std::uint32_t groups) const;
        void trace(WaveStage stage, const ShaderBindingTable& sbt, std::size_t sizeOffset) const;

        VkCommandBuffer m_cmd;
        const WavefrontPipeline::Compiled* m_compiled;
        const WavefrontPipeline::Tables* m_tables;
        VkPipelineLayout m_layout;
        const WaveBuffers* m_waves;
        WaveStageTimer* m_timer;
        bool m_nee;
        shader::TracePushConstants m_push{};
    };

    /// Records `count` camera samples per pixel of `extent` (a band of rows: positions from `firstRow` on in the
    /// row order of `rowInterleave`, Shared/BandOrder.h), sample
    /// indices from `firstSample` on, as waves of at most waves.capacity() paths (planWaves), each traced to
    /// the render's depth: each sample of a pixel after the one before, added to the accumulation images in
    /// sample order. `sets` (set 0 naming `waves`)
    /// are bound for both bind points; `uniforms` are those of its uniform buffer. Everything recorded is
    /// ordered before what comes next.
    void recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                      const shader::RenderUniforms& uniforms, const PipelineScene& scene, std::uint32_t firstSample,
                      std::uint32_t count, VkExtent2D extent, std::uint32_t firstRow, std::uint32_t rowInterleave,
                      const WaveBuffers& waves) const;

private:
    std::unique_ptr<Compiled> make(const PipelineSpecialization& key) const;
    const Compiled& compiled(const PipelineSpecialization& key) const;
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
