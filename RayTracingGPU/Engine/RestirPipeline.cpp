#include "Engine/RestirPipeline.h"

#include <algorithm>
#include <array>
#include <utility>

#include <spdlog/spdlog.h>

#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"

namespace rt::gpu
{
namespace
{
using namespace shader;

/// The megakernel's constants, kSpecIdWavefront = 0 and kSpecIdRestir = 1.
std::array<std::uint32_t, kSpecIdRestir + 1> restirConstants(const PipelineSpecialization& key)
{
    static_assert(kSpecIdWavefront == kSpecIdCount && kSpecIdRestir == kSpecIdWavefront + 1);
    std::array<std::uint32_t, kSpecIdRestir + 1> constants{};
    std::copy(key.constants.begin(), key.constants.end(), constants.begin());
    constants[kSpecIdRestir] = 1u;
    return constants;
}
} // namespace

struct RestirPipeline::Compiled
{
    vk::Pipeline pipeline;
    HitGroupLayout hitGroups; // the pipeline's own
    using Tables = std::array<ShaderBindingTable, std::size(kRestirPasses)>; // per pass
    mutable std::map<HitGroupLayout, Tables> tables; // per scene layout
    mutable bool prepared = false; // prepare() has returned true for it

    const Tables& tablesFor(const vk::Device& device, const HitGroupLayout& scene) const
    {
        auto it = tables.find(scene);
        if (it == tables.end())
        {
            const std::vector<std::uint32_t> hitRecords = hitRecordGroups(scene, hitGroups, kMissGroupCount);
            const std::uint32_t groups = extraRayGenGroup(hitGroups, 2); // the last raygen is group (.., 1)
            const VkPipeline p = pipeline.Handle();
            it = tables
                     .emplace(scene,
                              Tables{ShaderBindingTable(device, p, groups, kMissGroupCount, hitRecords),
                                     ShaderBindingTable(device, p, groups, kMissGroupCount, hitRecords,
                                                        extraRayGenGroup(hitGroups, 0)),
                                     ShaderBindingTable(device, p, groups, kMissGroupCount, hitRecords,
                                                        extraRayGenGroup(hitGroups, 1))})
                     .first;
        }
        return it->second;
    }
};

RestirPipeline::RestirPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                               const PathTracingPipeline& layout)
    : m_device(&device), m_layout(&layout),
      m_shaders(device, shaderDir, "Restir/Candidates.rgen.spv", {"Restir/Spatial.rgen.spv", "Restir/Shade.rgen.spv"})
{
}

RestirPipeline::~RestirPipeline() = default;

const RestirPipeline::Compiled& RestirPipeline::compiled(const PipelineSpecialization& key) const
{
    auto it = m_compiled.find(key);
    if (it == m_compiled.end())
    {
        const auto constants = restirConstants(key);
        auto c = std::make_unique<Compiled>();
        c->hitGroups = key.hitGroups();
        c->pipeline = createPathTracingPipeline(*m_device, m_layout->layout(), m_shaders, constants, c->hitGroups);
        spdlog::debug("compiled the restir-di pipeline {}", key.describe());
        it = m_compiled.emplace(key, std::move(c)).first;
    }
    return *it->second;
}

bool RestirPipeline::prepare(const RenderUniforms& uniforms, const PipelineScene& scene) const
{
    const Compiled& c = compiled(m_layout->specializationFor(uniforms, scene));
    c.tablesFor(*m_device, scene.hitGroups);
    return !std::exchange(c.prepared, true);
}

void RestirPipeline::recordPass(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                                const RenderUniforms& uniforms, const PipelineScene& scene, RestirPass pass,
                                std::uint32_t sampleIndex, VkExtent2D extent, std::uint32_t firstRow,
                                std::uint32_t rowInterleave, bool history) const
{
    const Compiled& c = compiled(m_layout->specializationFor(uniforms, scene));
    const Compiled::Tables& tables = c.tablesFor(*m_device, scene.hitGroups);
    const ShaderBindingTable& sbt = tables[static_cast<std::size_t>(pass)];
    const VkPipelineLayout layout = m_layout->layout().Handle();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, c.pipeline.Handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout, 0,
                            static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
    TracePushConstants push{};
    push.firstSample = sampleIndex;
    push.sampleCount = 1;
    push.firstRow = firstRow;
    push.rowInterleave = rowInterleave;
    push.restirHistory = history ? 1u : 0u;
    vkCmdPushConstants(cmd, layout, kPathTracerStages, 0, sizeof(push), &push);
    vkCmdTraceRaysKHR(cmd, &sbt.raygen(), &sbt.miss(), &sbt.hit(), &sbt.callable(), extent.width, extent.height, 1);
    // The spatial pass reads the candidates pass's buffers at other pixels; each pass reads the one before.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}
} // namespace rt::gpu
