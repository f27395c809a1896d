// What a render of one size writes: the RGBA32F accumulation image (rgb: sum of sample radiances, a: sample
// count) and its Kahan compensation image, a host-visible copy of the sum for readback, the per-render
// uniforms, the NaN/Inf counters and the trace counters (--count-rays, rays and light samples: device-local, with
// a snapshot for a cancelled batch and a host-visible copy to read).
#pragma once

#include <cstdint>
#include <utility>

#include "Engine/PathTracingPipeline.h"
#include "Image/Image.h"
#include "Render/LightSampleCounts.h"
#include "Render/RayCounts.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/Image.h"

namespace rt::gpu
{
class RenderTarget final
{
public:
    /// Allocates for width x height (checkTargetLimits passed) in up to `blocks` seed blocks
    /// (RenderEngine::setSeedBlock), their images one below the other. The image is left in GENERAL layout by the
    /// first clear() recorded.
    RenderTarget(const vk::Device& device, std::uint32_t width, std::uint32_t height, std::uint32_t blocks = 1);
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;
    ~RenderTarget() = default;

    std::uint32_t width() const { return m_image.extent().width; }
    std::uint32_t height() const { return m_height; } // a block's: the frame's
    std::uint32_t blocks() const { return m_blocks; } // the most a frame may use
    VkImageView view() const { return m_view.Handle(); }
    const vk::Buffer& uniforms() const { return m_uniforms; }
    const vk::Buffer& counters() const { return m_counters; }
    TargetBindings bindings() const
    {
        return {m_view.Handle(), m_compensationView.Handle(), m_uniforms.Handle(), m_counters.Handle(),
                m_traceCounters.Handle()};
    }

    /// Writes the uniforms and zeroes the counters (host-visible memory; call while the device is idle).
    void reset(const shader::RenderUniforms& uniforms);
    shader::SampleCounters readCounters() const;

    /// Records: UNDEFINED -> GENERAL and clear to zero, both images, and zeroes the trace counters.
    void recordClear(VkCommandBuffer cmd) const;
    /// Records the copy of the accumulation image into the readback buffer (and of the compensation image and the
    /// trace counters into their snapshots), after the ray-tracing writes.
    void recordReadback(VkCommandBuffer cmd) const;
    /// Records the copy of the readback buffer (and the snapshots) back into the two images and the trace counters:
    /// with recordReadback before a batch, this puts back the frame as the batch found it (a batch cancelled
    /// between its bands).
    void recordRestore(VkCommandBuffer cmd) const;
    /// Records the copy of the trace counters into their host-visible buffer, after the ray-tracing writes (the
    /// wavefront's compute writes are ordered before the transfer by its own barriers, WaveBuffers and Recorder).
    void recordTraceCountersReadback(VkCommandBuffer cmd) const;
    /// The rays by kind and NEE's light samples by outcome, summed over their slots (call after
    /// recordTraceCountersReadback completed).
    std::pair<RayCounts, LightSampleCounts> readTraceCounts() const;
    /// Overwrites the NaN/Inf counters (host-visible; call while the device is idle).
    void writeCounters(const shader::SampleCounters& counters);
    /// The estimate from the readback buffer of a frame of `blocks` seed blocks (at most blocks()): sum / the samples
    /// each block holds of `samples` traced in blocks of `seedBlock` (0: one block), RGB, the blocks one below the
    /// other (call after recordReadback completed).
    Image readEstimate(std::uint32_t samples, std::uint32_t seedBlock, std::uint32_t blocks) const;
    /// The sums of the readback buffer, RGB per pixel, of the frame's `blocks` blocks, as readEstimate divides them
    /// (the Kahan compensation, which the estimate leaves out too, is not added).
    std::vector<double> readSums(std::uint32_t blocks) const;

private:
    vk::Image m_image;
    vk::ImageView m_view;
    vk::Image m_compensation;
    vk::ImageView m_compensationView;
    vk::Buffer m_readback;
    vk::Buffer m_compensationSnapshot; // the compensation image at the last readback, for recordRestore
    vk::Buffer m_uniforms;
    vk::Buffer m_counters;
    vk::Buffer m_traceCounters; // TraceCounters, device-local: the shaders' atomics stay on the device
    vk::Buffer m_traceCountersSnapshot; // the trace counters at the last recordReadback, for recordRestore
    vk::Buffer m_traceCountersReadback; // host-visible, for readTraceCounts
    std::uint32_t m_height; // a block's
    std::uint32_t m_blocks;
};
} // namespace rt::gpu
