#include "Engine/ProgressiveFrame.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "Engine/CostTarget.h"
#include "Render/BatchPlan.h"
#include "Engine/GpuEngine.h"
#include "Engine/GpuScene.h"
#include "Engine/RenderLimits.h"
#include "Engine/RestirPipeline.h"
#include "Error.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"

namespace rt::gpu
{
namespace
{
// The stages that touch the images between frames: the ray tracer writes, the display pass reads, clears write.
constexpr VkPipelineStageFlags kImageStages = VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;

} // namespace

ProgressiveFrame::ProgressiveFrame(const GpuEngine& engine, std::uint32_t frameSlots)
    : m_engine(&engine),
      m_counters(engine.context().device(), sizeof(shader::SampleCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                 vk::MemoryUse::Readback),
      m_traceCounters(engine.context().device(), sizeof(shader::TraceCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    vk::MemoryUse::DeviceLocal)
{
    const vk::Device& device = engine.context().device();
    for (std::uint32_t slot = 0; slot < frameSlots; ++slot)
        m_uniforms.emplace_back(device, sizeof(shader::RenderUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                vk::MemoryUse::Upload);
    if (device.properties().timestampValidBits > 0)
        m_timestamps = vk::QueryPool(device, 2 * frameSlots);
    m_slotTimed.assign(frameSlots, false);
    std::memset(m_counters.mapped(), 0, sizeof(shader::SampleCounters));
}

ProgressiveFrame::~ProgressiveFrame() = default;

bool ProgressiveFrame::costAvailable() const { return m_engine->context().device().shaderClock(); }

void ProgressiveFrame::prepare(VkExtent2D extent)
{
    const vk::Device& device = m_engine->context().device();
    const VkExtent2D current = m_accumulation.extent();
    if (current.width != extent.width || current.height != extent.height)
    {
        m_accumulationView = vk::ImageView();
        m_compensationView = vk::ImageView();
        m_costView = vk::ImageView();
        m_accumulation = vk::Image(device, extent, VK_FORMAT_R32G32B32A32_SFLOAT,
                                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        m_accumulationView = vk::ImageView(device, m_accumulation);
        m_compensation = vk::Image(device, extent, VK_FORMAT_R32G32B32A32_SFLOAT,
                                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        m_compensationView = vk::ImageView(device, m_compensation);
        m_cost = vk::Image(device, extent, VK_FORMAT_R32_SFLOAT,
                           VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        m_costView = vk::ImageView(device, m_cost);
        m_imagesUndefined = true;
        m_restir.reset(); // made again at this size when a frame asks for it
    }
    makeSets();
    if (m_costPipeline)
        writeCostDescriptors();
}

void ProgressiveFrame::makeSets()
{
    // Set 0 follows the scene (its image count is the set's variable count) and the images.
    m_sets.clear();
    for (const vk::Buffer& uniforms : m_uniforms)
        m_sets.push_back(m_engine->tracer().makeDescriptors({m_accumulationView.Handle(), m_compensationView.Handle(),
                                                             uniforms.Handle(), m_counters.Handle(), m_traceCounters.Handle(),
                                                             m_restir.get()}));
}

void ProgressiveFrame::ensureRestir()
{
    if (m_restir)
        return;
    const VkExtent2D size = extent();
    const vk::Device& device = m_engine->context().device();
    if (const auto problem = RestirBuffers::tooLargeFor(device, std::uint64_t(size.width) * size.height))
        throw DeviceError(*problem);
    vkDeviceWaitIdle(device.Handle()); // the frames in flight use the sets made again below
    m_restir = std::make_unique<RestirBuffers>(device, std::uint64_t(size.width) * size.height);
    m_restirHistory = false;
    makeSets();
}

void ProgressiveFrame::createCostResources()
{
    const vk::Device& device = m_engine->context().device();
    m_costPipeline = std::make_unique<PathTracingPipeline>(device, m_engine->tracer().shaderDir(), RayGenVariant::Cost,
                                                           m_engine->tracer().pipeline().specializes());
    for (std::size_t slot = 0; slot < m_uniforms.size(); ++slot)
    {
        m_costStats.emplace_back(device, sizeof(shader::CostStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 vk::MemoryUse::Readback);
        std::memset(m_costStats.back().mapped(), 0, sizeof(shader::CostStats));
        m_costPools.emplace_back(device, m_costPipeline->costBindings(), 0);
        m_costSets.push_back(m_costPools.back().allocate(m_costPipeline->costSetLayout(), 0));
    }
    writeCostDescriptors();
}

void ProgressiveFrame::writeCostDescriptors() const
{
    for (std::size_t slot = 0; slot < m_costSets.size(); ++slot)
        writeCostSet(m_engine->context().device(), m_costSets[slot], m_costView.Handle(), m_costStats[slot].Handle());
}

void ProgressiveFrame::recordClear(VkCommandBuffer cmd)
{
    VkImageMemoryBarrier toClear[3]{};
    const VkImage images[3] = {m_accumulation.Handle(), m_compensation.Handle(), m_cost.Handle()};
    for (int i = 0; i < 3; ++i)
    {
        VkImageMemoryBarrier& b = toClear[i];
        b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        // Earlier frames' shader writes (and their reads, by the execution dependency) come first.
        b.srcAccessMask = m_imagesUndefined ? 0 : VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
        b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.oldLayout = m_imagesUndefined ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_GENERAL;
        b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = images[i];
        b.subresourceRange = vk::kColorRange;
    }
    const VkPipelineStageFlags before = m_imagesUndefined ? VkPipelineStageFlags(VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT)
                                                          : kImageStages;
    vkCmdPipelineBarrier(cmd, before,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 3, toClear);
    const VkClearColorValue zero{};
    for (VkImage image : images)
        vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &vk::kColorRange);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    m_imagesUndefined = false;
    m_restirHistory = false;
}

shader::RenderUniforms ProgressiveFrame::uniformsOf(const FrameRequest& request) const
{
    RenderSettings settings = request.settings;
    // A stratified request stops at its spp (the window asks for it only then: WindowApp's requestOf).
    settings.sampling = progressiveSampling(settings.sampling, true);
    return m_engine->tracer().uniforms(request.camera, settings, extent());
}

GpuIntegrator ProgressiveFrame::integratorOf(const shader::RenderUniforms& uniforms, int spp) const
{
    // Decided by the render's spp, as the headless render of that spp decides (the two integrators' images
    // differ by noise on a GPU): a window image of N spp stays that render's.
    const VkExtent2D size = extent();
    return m_engine->tracer().integratorFor(uniforms, std::uint64_t(size.width) * size.height *
                                                          static_cast<std::uint64_t>(std::max(spp, 1)));
}

GpuIntegrator ProgressiveFrame::integratorFor(const FrameRequest& request) const
{
    return integratorOf(uniformsOf(request), request.settings.spp);
}

bool ProgressiveFrame::preparePipeline(const FrameRequest& request) const
{
    if (request.cost)
        return false;
    const shader::RenderUniforms uniforms = uniformsOf(request);
    const GpuIntegrator integrator = integratorOf(uniforms, request.settings.spp);
    if (integrator == GpuIntegrator::Wavefront && !m_engine->tracer().wavefront())
        return false; // made, and compiled, at its first launch
    return m_engine->tracer().prepare(uniforms, integrator);
}

void ProgressiveFrame::warmUp(const FrameRequest& request)
{
    if (request.cost)
        return;
    const bool restir = request.settings.estimator == Estimator::RestirDi;
    if (restir)
        ensureRestir();
    const vk::Device& device = m_engine->context().device();
    vkDeviceWaitIdle(device.Handle()); // slot 0's uniforms and the images are rewritten below
    const shader::RenderUniforms uniforms = uniformsOf(request);
    std::memcpy(m_uniforms.at(0).mapped(), &uniforms, sizeof(uniforms));
    const VkExtent2D pixel{1, 1};
    vk::submitAndWait(device, m_engine->context().commandPool(), [&](VkCommandBuffer cmd) {
        recordClear(cmd); // the images' first layout, when they have none yet; no restir history after it
        if (restir)
            for (const RestirPass pass : kRestirPasses)
                m_engine->tracer().restir().recordPass(cmd, {&m_sets.at(0).set, 1}, uniforms,
                                                       m_engine->tracer().gpuScene().pipelineScene(), pass, 0, pixel, 0,
                                                       1, false);
        else
            m_engine->tracer().recordLaunch(cmd, {&m_sets.at(0).set, 1}, uniforms,
                                            integratorOf(uniforms, request.settings.spp), 0, 1, pixel);
    });
}

void ProgressiveFrame::recordSamples(VkCommandBuffer cmd, std::uint32_t slot, const FrameRequest& request,
                                     std::uint32_t firstSample, std::uint32_t count)
{
    if (count == 0)
        return;
    const VkExtent2D size = extent();
    const shader::RenderUniforms uniforms = uniformsOf(request);
    std::memcpy(m_uniforms.at(slot).mapped(), &uniforms, sizeof(uniforms));

    // After the previous frame's display reads (write-after-read) and its samples or clears.
    vk::memoryBarrier(cmd, kImageStages, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    // Both at the bottom of the pipe: the first is written once the work before (the previous frame's display
    // pass included) has finished, so the interval holds these samples alone.
    const bool timed = m_timestamps.Handle() != VK_NULL_HANDLE;
    if (timed)
    {
        vkCmdResetQueryPool(cmd, m_timestamps.Handle(), 2 * slot, 2);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_timestamps.Handle(), 2 * slot);
    }
    if (request.settings.estimator == Estimator::RestirDi)
    {
        ensureRestir();
        const RestirPipeline& restir = m_engine->tracer().restir();
        const PipelineScene& scene = m_engine->tracer().gpuScene().pipelineScene();
        for (std::uint32_t s = 0; s < count; ++s)
        {
            for (const RestirPass pass : kRestirPasses)
                restir.recordPass(cmd, {&m_sets.at(slot).set, 1}, uniforms, scene, pass, firstSample + s, size, 0, 1,
                                  m_restirHistory);
            m_restirHistory = true;
        }
    }
    else if (request.cost)
    {
        if (!m_costPipeline)
            createCostResources();
        const VkDescriptorSet sets[] = {m_sets.at(slot).set, m_costSets.at(slot)};
        m_engine->tracer().recordLaunch(cmd, sets, uniforms, GpuIntegrator::Megakernel, firstSample, count, size,
                                        m_costPipeline.get());
    }
    else
        m_engine->tracer().recordLaunch(cmd, {&m_sets.at(slot).set, 1}, uniforms,
                                        integratorOf(uniforms, request.settings.spp), firstSample, count, size);
    if (timed)
    {
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_timestamps.Handle(), 2 * slot + 1);
        m_slotTimed.at(slot) = true;
    }
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_HOST_READ_BIT);
}

std::uint32_t autoFrameSamples(std::uint32_t samples, double seconds, std::uint32_t most)
{
    const double last = std::max(samples, 1u);
    const double next = workForTarget(last, seconds, 4.0 * last, kFrameTargetSeconds);
    return static_cast<std::uint32_t>(std::clamp(std::floor(next), 1.0, double(std::max(most, 1u))));
}

CostSummary summarizeCost(const shader::CostStats& stats)
{
    CostSummary summary;
    std::memcpy(&summary.max, &stats.maxBits, sizeof(summary.max));
    std::uint64_t pixels = 0;
    for (std::uint32_t count : stats.buckets)
        pixels += count;
    // The 95th percentile, placed inside its bucket as if the bucket's pixels were spread evenly in log2.
    const double target = 0.95 * static_cast<double>(pixels);
    double below = 0.0;
    for (std::uint32_t b = 0; b < shader::kCostBuckets && pixels > 0; ++b)
    {
        const double count = stats.buckets[b];
        if (below + count >= target && count > 0.0)
        {
            summary.high = static_cast<float>(std::exp2(double(b) + (target - below) / count));
            break;
        }
        below += count;
    }
    return summary;
}

CostSummary ProgressiveFrame::takeCostSummary(std::uint32_t slot)
{
    if (slot >= m_costStats.size())
        return {};
    auto* stats = static_cast<shader::CostStats*>(m_costStats[slot].mapped());
    const CostSummary summary = summarizeCost(*stats);
    std::memset(stats, 0, sizeof(*stats));
    return summary;
}

std::optional<double> ProgressiveFrame::takeTraceSeconds(std::uint32_t slot)
{
    if (slot >= m_slotTimed.size() || !m_slotTimed[slot])
        return std::nullopt;
    m_slotTimed[slot] = false;
    return m_timestamps.secondsBetween(2 * slot, m_engine->context().device().properties().limits.timestampPeriod);
}

void ProgressiveFrame::showImage(const Image& image, std::span<const float> costPerSample)
{
    const vk::Device& device = m_engine->context().device();
    const VkExtent2D size = extent();
    if (image.width() != int(size.width) || image.height() != int(size.height) ||
        (!costPerSample.empty() && costPerSample.size() != image.pixelCount()))
        throw UsageError("ProgressiveFrame::showImage: the image or its cost is not of the accumulation's size");
    std::optional<vk::Buffer> costUpload;
    if (!costPerSample.empty())
    {
        costUpload.emplace(device, VkDeviceSize(sizeof(float)) * costPerSample.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                           vk::MemoryUse::Upload);
        std::memcpy(costUpload->mapped(), costPerSample.data(), sizeof(float) * costPerSample.size());
    }
    const vk::Buffer upload(device, VkDeviceSize(kAccumulationBytesPerPixel) * size.width * size.height,
                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::Upload);
    auto* texels = static_cast<float*>(upload.mapped());
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
    {
        const vec3 c = image.data()[i];
        texels[4 * i] = c.x;
        texels[4 * i + 1] = c.y;
        texels[4 * i + 2] = c.z;
        texels[4 * i + 3] = 1.0f; // one sample
    }
    vkDeviceWaitIdle(device.Handle()); // the frames in flight read the image
    vk::submitAndWait(device, m_engine->context().commandPool(), [&](VkCommandBuffer cmd) {
        recordClear(cmd);
        vk::imageBarrier(cmd, m_accumulation.Handle(),
                         {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {size.width, size.height, 1};
        vkCmdCopyBufferToImage(cmd, upload.Handle(), m_accumulation.Handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
        vk::imageBarrier(cmd, m_accumulation.Handle(),
                         {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT, kImageStages,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT});
        if (costUpload)
        {
            vk::imageBarrier(cmd, m_cost.Handle(),
                             {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
            vkCmdCopyBufferToImage(cmd, costUpload->Handle(), m_cost.Handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                                   &region);
            vk::imageBarrier(cmd, m_cost.Handle(),
                             {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_TRANSFER_WRITE_BIT, kImageStages,
                              VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT});
        }
    });
}

Image ProgressiveFrame::readImage() const
{
    const vk::Device& device = m_engine->context().device();
    const VkExtent2D size = extent();
    if (m_imagesUndefined)
        return Image(static_cast<int>(size.width), static_cast<int>(size.height)); // nothing traced yet
    const vk::Buffer readback(device, VkDeviceSize(kAccumulationBytesPerPixel) * size.width * size.height, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUse::Readback);
    vk::submitAndWait(device, m_engine->context().commandPool(), [&](VkCommandBuffer cmd) {
        vk::recordImageReadback(cmd, m_accumulation.Handle(), size, readback.Handle(), VK_IMAGE_LAYOUT_GENERAL,
                                kImageStages, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, kImageStages,
                                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    });
    Image image(static_cast<int>(size.width), static_cast<int>(size.height));
    const auto* texels = static_cast<const float*>(readback.mapped());
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        image.data()[i] = vec3(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]) / std::max(texels[4 * i + 3], 1.0f);
    return image;
}
} // namespace rt::gpu
