#include "Engine/WavefrontPipeline.h"

#include <algorithm>
#include <array>
#include <cstddef>

#include <spdlog/spdlog.h>

#include "Engine/WaveBuffers.h"
#include "Engine/WaveStageTimer.h"
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
};

WavefrontPipeline::WavefrontPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                                     const PathTracingPipeline& layout)
    : m_device(&device), m_layout(&layout),
      m_rayTracingShaders(device, shaderDir, "Wavefront/Extend.rgen.spv", "Wavefront/Shadow.rgen.spv"),
      m_generate(device, shaderDir / "Wavefront/Generate.comp.spv"),
      m_shade(device, shaderDir / "Wavefront/Shade.comp.spv"),
      m_prepare(device, shaderDir / "Wavefront/Prepare.comp.spv"),
      m_accumulate(device, shaderDir / "Wavefront/Accumulate.comp.spv")
{
}

WavefrontPipeline::~WavefrontPipeline() = default;

const WavefrontPipeline::Compiled& WavefrontPipeline::compiled(const PipelineSpecialization& key) const
{
    auto it = m_compiled.find(key);
    if (it == m_compiled.end())
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
        it = m_compiled.emplace(key, std::move(c)).first;
    }
    return *it->second;
}

const WavefrontPipeline::Tables& WavefrontPipeline::tablesFor(const Compiled& c, const HitGroupLayout& scene) const
{
    auto it = c.tables.find(scene);
    if (it == c.tables.end())
    {
        const std::vector<std::uint32_t> hitGroups = hitRecordGroups(scene, c.hitGroups, kMissGroupCount);
        const std::uint32_t shadowGroup = secondRayGenGroup(c.hitGroups);
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
    const std::size_t before = m_compiled.size();
    tablesFor(compiled(m_layout->specializationFor(uniforms, scene)), scene.hitGroups);
    return m_compiled.size() > before;
}

void WavefrontPipeline::recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                                     const RenderUniforms& uniforms, const PipelineScene& scene,
                                     std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent,
                                     std::uint32_t firstRow, const WaveBuffers& waves, WaveStageTimer* timer) const
{
    const Compiled& c = compiled(m_layout->specializationFor(uniforms, scene));
    const Tables& tables = tablesFor(c, scene.hitGroups);
    const VkPipelineLayout layout = m_layout->layout().Handle();
    const auto setCount = static_cast<std::uint32_t>(sets.size());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, setCount, sets.data(), 0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout, 0, setCount, sets.data(), 0,
                            nullptr);
    const VkBuffer counters = waves.counters().Handle();
    const VkDeviceAddress countersAddress = waves.counters().address();
    const bool nee = (uniforms.estimator == Estimator::Nee || uniforms.estimator == Estimator::NeeMis) &&
                     uniforms.emitterCount > 0;
    const std::uint32_t capacity = waves.capacity();
    const std::uint64_t pixels = std::uint64_t(extent.width) * extent.height;
    const std::uint64_t firstPixel = std::uint64_t(firstRow) * extent.width;

    TracePushConstants push{};
    push.firstRow = firstRow;
    push.waveCapacity = capacity;
    const auto pushConstants = [&] {
        vkCmdPushConstants(cmd, layout, kPathTracerStages, 0, sizeof(push), &push);
    };
    const auto ordered = [&](WaveStage stage) {
        waveBarrier(cmd);
        if (timer)
            timer->mark(cmd, stage);
    };
    const auto dispatch = [&](WaveStage stage, const vk::Pipeline& pipeline, std::uint32_t groups) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.Handle());
        pushConstants();
        vkCmdDispatch(cmd, groups, 1, 1);
        ordered(stage);
    };
    const auto trace = [&](WaveStage stage, const ShaderBindingTable& sbt, std::size_t sizeOffset) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, c.rayTracing.Handle());
        pushConstants();
        vkCmdTraceRaysIndirectKHR(cmd, &sbt.raygen(), &sbt.miss(), &sbt.hit(), &sbt.callable(),
                                  countersAddress + sizeOffset);
        ordered(stage);
    };

    // Samples outside, pixels inside: every wave of a pixel's earlier samples is summed before a later one.
    const std::uint32_t samplesPerWave = std::min(count, capacity);
    for (std::uint32_t done = 0; done < count;)
    {
        const std::uint32_t samples = std::min(samplesPerWave, count - done);
        const std::uint64_t pixelsPerWave = capacity / samples;
        for (std::uint64_t pixel = 0; pixel < pixels; pixel += pixelsPerWave)
        {
            push.firstSample = firstSample + done;
            push.sampleCount = samples;
            push.wavePixelBegin = static_cast<std::uint32_t>(firstPixel + pixel);
            push.wavePixelCount = static_cast<std::uint32_t>(std::min(pixelsPerWave, pixels - pixel));
            push.waveSegment = 0;
            push.waveQueue = 0;
            vkCmdFillBuffer(cmd, counters, 0, VK_WHOLE_SIZE, 0);
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                              VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
            dispatch(WaveStage::Generate, c.generate, groupsFor(std::uint64_t(push.wavePixelCount) * samples));
            dispatch(WaveStage::Prepare, c.prepare, 1);
            for (std::uint32_t segment = 0; segment < uniforms.depth; ++segment)
            {
                push.waveSegment = segment;
                push.waveQueue = segment & 1u;
                trace(WaveStage::Extend, tables.extend, offsetof(WaveCounters, extendRays));
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, c.shade.Handle());
                pushConstants();
                vkCmdDispatchIndirect(cmd, counters, offsetof(WaveCounters, shadeGroups));
                ordered(WaveStage::Shade);
                dispatch(WaveStage::Prepare, c.prepare, 1);
                if (nee)
                {
                    push.waveQueue = kWaveShadowQueue;
                    trace(WaveStage::Shadow, tables.shadow, offsetof(WaveCounters, shadowRays));
                }
            }
            dispatch(WaveStage::Accumulate, c.accumulate, groupsFor(push.wavePixelCount));
        }
        done += samples;
    }
    // The sums and the NaN/Inf counters, for whatever the caller records next (a readback, the next launch).
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                          VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                          VK_ACCESS_HOST_READ_BIT);
}
} // namespace rt::gpu
