#include "Engine/RenderTarget.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "Engine/RenderLimits.h"
#include "Render/RenderEngine.h"
#include "Vulkan/Barriers.h"

namespace rt::gpu
{
RenderTarget::RenderTarget(const vk::Device& device, std::uint32_t width, std::uint32_t height, std::uint32_t blocks)
    : m_image(device, {width, height * blocks}, VK_FORMAT_R32G32B32A32_SFLOAT,
              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT),
      m_view(device, m_image),
      m_compensation(device, {width, height * blocks}, VK_FORMAT_R32G32B32A32_SFLOAT,
                     VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT),
      m_compensationView(device, m_compensation),
      m_readback(device, VkDeviceSize(kAccumulationBytesPerPixel) * width * height * blocks,
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 vk::MemoryUse::Readback),
      m_compensationSnapshot(device, VkDeviceSize(kAccumulationBytesPerPixel) * width * height * blocks,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             vk::MemoryUse::Readback),
      m_uniforms(device, sizeof(shader::RenderUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload),
      m_counters(device, sizeof(shader::SampleCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback),
      m_traceCounters(device, sizeof(shader::TraceCounters),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    vk::MemoryUse::DeviceLocal),
      m_traceCountersSnapshot(device, sizeof(shader::TraceCounters),
                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            vk::MemoryUse::DeviceLocal),
      m_traceCountersReadback(device, sizeof(shader::TraceCounters), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            vk::MemoryUse::Readback),
      m_height(height),
      m_blocks(blocks)
{
}

namespace
{
/// Records the copy of buffer `from` into `to` (same size) after the ray-tracing shaders' writes, and makes the
/// shaders that follow wait for it (they may write either).
void copyAfterTracing(VkCommandBuffer cmd, VkBuffer from, VkBuffer to)
{
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferCopy region{0, 0, sizeof(shader::TraceCounters)};
    vkCmdCopyBuffer(cmd, from, to, 1, &region);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}
} // namespace

void RenderTarget::reset(const shader::RenderUniforms& uniforms)
{
    std::memcpy(m_uniforms.mapped(), &uniforms, sizeof(uniforms));
    std::memset(m_counters.mapped(), 0, sizeof(shader::SampleCounters));
}

shader::SampleCounters RenderTarget::readCounters() const
{
    shader::SampleCounters counters;
    std::memcpy(&counters, m_counters.mapped(), sizeof(counters));
    return counters;
}

void RenderTarget::recordClear(VkCommandBuffer cmd) const
{
    const VkClearColorValue zero{};
    for (const VkImage image : {m_image.Handle(), m_compensation.Handle()})
    {
        vk::imageBarrier(cmd, image,
                         {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &vk::kColorRange);
    }
    vkCmdFillBuffer(cmd, m_traceCounters.Handle(), 0, VK_WHOLE_SIZE, 0u);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void RenderTarget::recordReadback(VkCommandBuffer cmd) const
{
    // Back to GENERAL afterwards for the next dispatch's storage-image writes. The compensation goes along:
    // a restore must put back the pair, or the sums after it would differ from an uncancelled render's.
    for (const auto& [image, buffer] : {std::pair{m_image.Handle(), m_readback.Handle()},
                                        std::pair{m_compensation.Handle(), m_compensationSnapshot.Handle()}})
        vk::recordImageReadback(cmd, image, m_image.extent(), buffer, VK_IMAGE_LAYOUT_GENERAL,
                                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    copyAfterTracing(cmd, m_traceCounters.Handle(), m_traceCountersSnapshot.Handle());
}

void RenderTarget::recordTraceCountersReadback(VkCommandBuffer cmd) const
{
    copyAfterTracing(cmd, m_traceCounters.Handle(), m_traceCountersReadback.Handle());
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_HOST_READ_BIT);
}

std::pair<RayCounts, LightSampleCounts> RenderTarget::readTraceCounts() const
{
    shader::TraceCounters c;
    std::memcpy(&c, m_traceCountersReadback.mapped(), sizeof(c));
    std::uint64_t kinds[shader::kCountKinds] = {};
    for (std::uint32_t slot = 0; slot < shader::kTraceCounterSlots; ++slot)
        for (std::uint32_t kind = 0; kind < shader::kCountKinds; ++kind)
        {
            const std::uint32_t word = (slot * shader::kCountKinds + kind) * 2u;
            kinds[kind] += std::uint64_t(c.words[word]) | std::uint64_t(c.words[word + 1]) << 32;
        }
    return {{kinds[shader::kRayCamera], kinds[shader::kRayExtension], kinds[shader::kRayShadow]},
            {kinds[shader::kCountLightDrawn], kinds[shader::kCountLightFallback], kinds[shader::kCountLightDeclined]}};
}

void RenderTarget::recordRestore(VkCommandBuffer cmd) const
{
    copyAfterTracing(cmd, m_traceCountersSnapshot.Handle(), m_traceCounters.Handle());
    // The launches' contents are discarded (UNDEFINED) once they finished writing; back to GENERAL after.
    for (const auto& [image, buffer] : {std::pair{m_image.Handle(), m_readback.Handle()},
                                        std::pair{m_compensation.Handle(), m_compensationSnapshot.Handle()}})
    {
        vk::imageBarrier(cmd, image,
                         {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {m_image.extent().width, m_image.extent().height, 1};
        vkCmdCopyBufferToImage(cmd, buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        vk::imageBarrier(cmd, image,
                         {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT});
    }
}

void RenderTarget::writeCounters(const shader::SampleCounters& counters)
{
    std::memcpy(m_counters.mapped(), &counters, sizeof(counters));
}

Image RenderTarget::readEstimate(std::uint32_t samples, std::uint32_t seedBlock, std::uint32_t blocks) const
{
    blocks = std::clamp(blocks, 1u, m_blocks);
    Image image(static_cast<int>(width()), static_cast<int>(height() * blocks));
    const auto* texels = static_cast<const float*>(m_readback.mapped());
    const std::size_t blockPixels = std::size_t(width()) * height();
    for (std::uint32_t b = 0; b < blocks; ++b)
    {
        const float count = static_cast<float>(std::max<std::uint32_t>(samplesInSeedBlock(samples, seedBlock, b), 1));
        for (std::size_t i = b * blockPixels; i < (b + 1) * blockPixels; ++i)
            image.data()[i] = vec3(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]) / count;
    }
    return image;
}

std::vector<double> RenderTarget::readSums(std::uint32_t blocks) const
{
    const auto* texels = static_cast<const float*>(m_readback.mapped());
    const std::size_t pixels = std::size_t(width()) * height() * std::clamp(blocks, 1u, m_blocks);
    std::vector<double> sums(3 * pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            sums[3 * i + c] = texels[4 * i + c];
    return sums;
}
} // namespace rt::gpu
