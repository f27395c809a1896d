// Where a wavefront launch's GPU time goes: a timestamp after each of its kernels (and the barrier that
// follows it), read back once the submission is done as seconds per kind of kernel. The engine reports them
// in the stats' stage_seconds: wave_generate_gpu, wave_extend_gpu (path rays), wave_shade_gpu,
// wave_shadow_gpu (shadow rays), wave_accumulate_gpu, wave_prepare_gpu (queue sizes and counter resets).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "Vulkan/QueryPool.h"

namespace rt::gpu
{
enum class WaveStage
{
    Generate,
    Extend,
    Shade,
    Shadow,
    Accumulate,
    Prepare,
};

class WaveStageTimer final
{
public:
    /// Room for `timestamps` marks per submission; marks beyond it are dropped (their time goes to the last
    /// kept stage).
    WaveStageTimer(const vk::Device& device, std::uint32_t timestamps = 16384);

    /// Records the reset of the pool and the first timestamp; forgets the marks of the last submission.
    void begin(VkCommandBuffer cmd);
    /// Records a timestamp: the time since the last one was `stage`'s.
    void mark(VkCommandBuffer cmd, WaveStage stage);
    /// Adds each stage's seconds of the submission (done) to `stages`.
    void addTo(std::map<std::string, double>& stages) const;

private:
    const vk::Device* m_device;
    vk::QueryPool m_pool;
    std::uint32_t m_capacity;
    std::vector<WaveStage> m_stages; // the stage of the interval before timestamp i + 1
};
} // namespace rt::gpu
