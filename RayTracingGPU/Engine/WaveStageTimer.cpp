#include "Engine/WaveStageTimer.h"

namespace rt::gpu
{
namespace
{
const char* stageName(WaveStage stage)
{
    switch (stage)
    {
    case WaveStage::Generate: return "wave_generate_gpu";
    case WaveStage::Extend: return "wave_extend_gpu";
    case WaveStage::Shade: return "wave_shade_gpu";
    case WaveStage::Shadow: return "wave_shadow_gpu";
    case WaveStage::Accumulate: return "wave_accumulate_gpu";
    case WaveStage::Prepare: return "wave_prepare_gpu";
    }
    return "wave_gpu";
}
} // namespace

WaveStageTimer::WaveStageTimer(const vk::Device& device, std::uint32_t timestamps)
    : m_device(&device), m_pool(device, timestamps), m_capacity(timestamps)
{
}

void WaveStageTimer::begin(VkCommandBuffer cmd)
{
    m_stages.clear();
    vkCmdResetQueryPool(cmd, m_pool.Handle(), 0, m_capacity);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_pool.Handle(), 0);
}

void WaveStageTimer::mark(VkCommandBuffer cmd, WaveStage stage)
{
    if (m_stages.size() + 1 >= m_capacity)
        return;
    m_stages.push_back(stage);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_pool.Handle(),
                        static_cast<std::uint32_t>(m_stages.size()));
}

void WaveStageTimer::addTo(std::map<std::string, double>& stages) const
{
    if (m_stages.empty())
        return;
    const double secondsPerTick = double(m_device->properties().limits.timestampPeriod) * 1e-9;
    const std::vector<std::uint64_t> ticks = m_pool.ticks(0, static_cast<std::uint32_t>(m_stages.size() + 1));
    for (std::size_t i = 0; i < m_stages.size(); ++i)
        if (ticks[i + 1] >= ticks[i])
            stages[stageName(m_stages[i])] += double(ticks[i + 1] - ticks[i]) * secondsPerTick;
}
} // namespace rt::gpu
