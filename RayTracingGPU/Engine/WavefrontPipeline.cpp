#include "Engine/WavefrontPipeline.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include <spdlog/spdlog.h>

#include "Engine/CompileTogether.h"
#include "Engine/WaveBuffers.h"
#include "Engine/WaveStageTimer.h"
#include "Shared/Estimator.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/ComputePipeline.h"

namespace rt::gpu
{
namespace
{
using namespace shader;

/// The megakernel's constants and kSpecIdWavefront = 1.
std::array<std::uint32_t, kSpecIdWavefront + 1> wavefrontConstants(const PipelineSpecialization& key)
{
    static_assert(kSpecIdWavefront == kSpecIdCount);
    std::array<std::uint32_t, kSpecIdWavefront + 1> constants{};
    std::copy(key.constants.begin(), key.constants.end(), constants.begin());
    constants[kSpecIdWavefront] = 1u;
    return constants;
}

/// Orders a kernel's writes before the later kernels' reads and writes and the indirect launches' reads of
/// their sizes.
void waveBarrier(VkCommandBuffer cmd)
{
    constexpr VkPipelineStageFlags kKernels =
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
    vk::memoryBarrier(cmd, kKernels, VK_ACCESS_SHADER_WRITE_BIT, kKernels | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
}

std::uint32_t groupsFor(std::uint64_t invocations)
{
    return static_cast<std::uint32_t>((invocations + kWaveGroupSize - 1) / kWaveGroupSize);
}
} // namespace

struct WavefrontPipeline::Tables
{
    ShaderBindingTable extend;
    ShaderBindingTable shadow;
};

struct WavefrontPipeline::Compiled
{
    vk::Pipeline rayTracing;
    HitGroupLayout hitGroups; // the pipeline's own
    vk::Pipeline generate;
    vk::Pipeline shade;
    vk::Pipeline prepare;
    vk::Pipeline accumulate;
    mutable std::map<HitGroupLayout, Tables> tables; // per scene layout
    mutable bool prepared = false; // prepare() has returned true for it
};

WavefrontPipeline::WavefrontPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                                     const PathTracingPipeline& layout)
    : m_device(&device), m_layout(&layout),
      m_rayTracingShaders(device, shaderDir, "Wavefront/Extend.rgen.spv", {"Wavefront/Shadow.rgen.spv"}),
      m_generate(device, shaderDir / "Wavefront/Generate.comp.spv"),
      m_shade(device, shaderDir / "Wavefront/Shade.comp.spv"),
      m_prepare(device, shaderDir / "Wavefront/Prepare.comp.spv"),
      m_accumulate(device, shaderDir / "Wavefront/Accumulate.comp.spv")
{
}

WavefrontPipeline::~WavefrontPipeline() = default;

std::unique_ptr<WavefrontPipeline::Compiled> WavefrontPipeline::make(const PipelineSpecialization& key) const
{
    const auto constants = wavefrontConstants(key);
    const vk::Specialization specialization(constants);
    const vk::PipelineLayout& layout = m_layout->layout();
    auto c = std::make_unique<Compiled>();
    c->hitGroups = key.hitGroups();
    c->rayTracing = createPathTracingPipeline(*m_device, layout, m_rayTracingShaders, constants, c->hitGroups);
    c->generate = vk::createComputePipeline(*m_device, layout, m_generate, specialization);
    c->shade = vk::createComputePipeline(*m_device, layout, m_shade, specialization);
    c->prepare = vk::createComputePipeline(*m_device, layout, m_prepare, specialization);
    c->accumulate = vk::createComputePipeline(*m_device, layout, m_accumulate, specialization);
    spdlog::debug("compiled the wavefront pipelines {}", key.describe());
    return c;
}

const WavefrontPipeline::Compiled& WavefrontPipeline::compiled(const PipelineSpecialization& key) const
{
    auto it = m_compiled.find(key);
    if (it == m_compiled.end())
        it = m_compiled.emplace(key, make(key)).first;
    return *it->second;
}

void WavefrontPipeline::compileTogether(std::span<const PipelineSpecialization> keys) const
{
    gpu::compileTogether(m_compiled, keys, [this](const PipelineSpecialization& key) { return make(key); });
}

const WavefrontPipeline::Tables& WavefrontPipeline::tablesFor(const Compiled& c, const HitGroupLayout& scene) const
{
    auto it = c.tables.find(scene);
    if (it == c.tables.end())
    {
        const std::vector<std::uint32_t> hitGroups = hitRecordGroups(scene, c.hitGroups, kMissGroupCount);
        const std::uint32_t shadowGroup = extraRayGenGroup(c.hitGroups, 0);
        const std::uint32_t groupCount = shadowGroup + 1;
        const VkPipeline pipeline = c.rayTracing.Handle();
        it = c.tables
                 .emplace(scene, Tables{ShaderBindingTable(*m_device, pipeline, groupCount, kMissGroupCount, hitGroups),
                                        ShaderBindingTable(*m_device, pipeline, groupCount, kMissGroupCount, hitGroups,
                                                           shadowGroup)})
                 .first;
    }
    return it->second;
}

bool WavefrontPipeline::prepare(const RenderUniforms& uniforms, const PipelineScene& scene) const
{
    const Compiled& c = compiled(m_layout->specializationFor(uniforms, scene));
    tablesFor(c, scene.hitGroups);
    return !std::exchange(c.prepared, true);
}

std::vector<Wave> planWaves(std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent,
                            std::uint32_t firstRow, std::uint32_t capacity)
{
    std::vector<Wave> waves;
    const std::uint64_t pixels = std::uint64_t(extent.width) * extent.height;
    const std::uint64_t firstPixel = std::uint64_t(firstRow) * extent.width;
    const std::uint32_t samplesPerWave = std::min(count, std::max(capacity, 1u));
    // Samples outside, pixels inside: every wave of a pixel's earlier samples comes before a later one.
    for (std::uint32_t done = 0; done < count;)
    {
        const std::uint32_t samples = std::min(samplesPerWave, count - done);
        // The pixels spread evenly over the waves they need (sizes within one pixel), as batches and bands are:
        // a short last wave pays a wave's launches per segment for a few paths (many-lights at 600x600, 96
        // samples per batch, had waves of 175 K, 175 K and 10 K pixels; the same time on an H200, §8.9).
        const std::uint64_t most = std::max(capacity, 1u) / samples;
        const std::uint64_t parts = (pixels + most - 1) / most;
        for (std::uint64_t part = 0; part < parts; ++part)
        {
            const std::uint64_t begin = pixels * part / parts, end = pixels * (part + 1) / parts;
            waves.push_back({firstSample + done, samples, static_cast<std::uint32_t>(firstPixel + begin),
                             static_cast<std::uint32_t>(end - begin)});
        }
        done += samples;
    }
    return waves;
}

WavefrontPipeline::Recorder::Recorder(const WavefrontPipeline& pipeline, VkCommandBuffer cmd,
                                      std::span<const VkDescriptorSet> sets, const RenderUniforms& uniforms,
                                      const PipelineScene& scene, std::uint32_t firstRow,
                                      std::uint32_t rowInterleave, const WaveBuffers& waves,
                                      WaveStageTimer* timer)
    : m_cmd(cmd), m_compiled(&pipeline.compiled(pipeline.m_layout->specializationFor(uniforms, scene))),
      m_tables(&pipeline.tablesFor(*m_compiled, scene.hitGroups)),
      m_layout(pipeline.m_layout->layout().Handle()), m_waves(&waves), m_timer(timer),
      m_nee(shader::usesNee(uniforms.estimator) &&
            uniforms.emitterCount > 0)
{
    const auto setCount = static_cast<std::uint32_t>(sets.size());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, setCount, sets.data(), 0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, m_layout, 0, setCount, sets.data(), 0,
                            nullptr);
    m_push.firstRow = firstRow;
    m_push.rowInterleave = rowInterleave;
    m_push.waveCapacity = waves.capacity();
}

void WavefrontPipeline::Recorder::pushConstants() const
{
    vkCmdPushConstants(m_cmd, m_layout, kPathTracerStages, 0, sizeof(m_push), &m_push);
}

void WavefrontPipeline::Recorder::ordered(WaveStage stage) const
{
    waveBarrier(m_cmd);
    if (m_timer)
        m_timer->mark(m_cmd, stage);
}

void WavefrontPipeline::Recorder::dispatch(WaveStage stage, const vk::Pipeline& pipeline, std::uint32_t groups) const
{
    vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.Handle());
    pushConstants();
    vkCmdDispatch(m_cmd, groups, 1, 1);
    ordered(stage);
}

void WavefrontPipeline::Recorder::trace(WaveStage stage, const ShaderBindingTable& sbt, std::size_t sizeOffset) const
{
    vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, m_compiled->rayTracing.Handle());
    pushConstants();
    vkCmdTraceRaysIndirectKHR(m_cmd, &sbt.raygen(), &sbt.miss(), &sbt.hit(), &sbt.callable(),
                              m_waves->counters().address() + sizeOffset);
    ordered(stage);
}

void WavefrontPipeline::Recorder::use(const Wave& wave)
{
    m_push.firstSample = wave.firstSample;
    m_push.sampleCount = wave.samples;
    m_push.wavePixelBegin = wave.pixelBegin;
    m_push.wavePixelCount = wave.pixelCount;
}

void WavefrontPipeline::Recorder::start(const Wave& wave)
{
    use(wave);
    m_push.waveSegment = 0; // Prepare: the queue it sizes is segment 0's
    m_push.waveQueue = 0;
    vkCmdFillBuffer(m_cmd, m_waves->counters().Handle(), 0, VK_WHOLE_SIZE, 0);
    vk::memoryBarrier(m_cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    dispatch(WaveStage::Generate, m_compiled->generate, groupsFor(std::uint64_t(wave.pixelCount) * wave.samples));
    dispatch(WaveStage::Prepare, m_compiled->prepare, 1);
}

void WavefrontPipeline::Recorder::segments(const Wave& wave, std::uint32_t first, std::uint32_t last)
{
    use(wave);
    for (std::uint32_t segment = first; segment < last; ++segment)
    {
        m_push.waveSegment = segment;
        m_push.waveQueue = segment & 1u;
        trace(WaveStage::Extend, m_tables->extend, offsetof(WaveCounters, extendRays));
        vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_compiled->shade.Handle());
        pushConstants();
        vkCmdDispatchIndirect(m_cmd, m_waves->counters().Handle(), offsetof(WaveCounters, shadeGroups));
        ordered(WaveStage::Shade);
        m_push.waveSegment = segment + 1; // Prepare: the queue it sizes is the next segment's
        dispatch(WaveStage::Prepare, m_compiled->prepare, 1);
        if (m_nee)
        {
            m_push.waveQueue = kWaveShadowQueue;
            trace(WaveStage::Shadow, m_tables->shadow, offsetof(WaveCounters, shadowRays));
        }
    }
}

void WavefrontPipeline::Recorder::finish(const Wave& wave)
{
    use(wave);
    dispatch(WaveStage::Accumulate, m_compiled->accumulate, groupsFor(wave.pixelCount));
    // The sums and the NaN/Inf counters, for whatever the caller records next (a readback, the next launch).
    vk::memoryBarrier(m_cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                          VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                          VK_ACCESS_HOST_READ_BIT);
}

void WavefrontPipeline::recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                                     const RenderUniforms& uniforms, const PipelineScene& scene,
                                     std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent,
                                     std::uint32_t firstRow, std::uint32_t rowInterleave,
                                     const WaveBuffers& waves) const
{
    Recorder recorder(*this, cmd, sets, uniforms, scene, firstRow, rowInterleave, waves);
    for (const Wave& wave : planWaves(firstSample, count, extent, firstRow, waves.capacity()))
    {
        recorder.start(wave);
        recorder.segments(wave, 0, uniforms.depth);
        recorder.finish(wave);
    }
}
} // namespace rt::gpu
