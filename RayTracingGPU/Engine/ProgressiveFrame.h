// The GPU engine's progressive rendering, for a caller that shows the image as it converges (the window): a
// few camera samples per pixel per frame, added to an accumulation image of the render's size and recorded
// into the caller's own command buffer (no readback, no wait). The samples are the engine's: the same uniforms,
// pipeline and launches (SceneTracer::recordLaunch) as GpuEngine::traceSamples, with the integrator the
// render's spp decides, so that N samples here are the image of a headless render of N spp. Each frame in
// flight has its own uniforms and descriptor sets, so the camera and settings written for frame n + 1 never
// change what frame n is still reading. With the cost on, the timed ray-generation shader also sums each
// pixel's shader-clock ticks into a cost image (the window's heatmap). A display pass reads both images where
// they are (GENERAL layout). restir-di runs its three passes per sample (RestirPipeline) over buffers of the image's
// size, made when a frame first asks for it; the history starts again at every clear (a new image, a moved
// camera). It has no heatmap: a frame that asks for the cost with restir-di traces without it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "Image/Image.h"
#include "Render/RenderSettings.h"
#include "Scene/Camera.h"
#include "Shared/HostDevice.h"
#include "Engine/GpuIntegrator.h"
#include "Engine/RestirBuffers.h"
#include "Engine/SceneTracer.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/DescriptorPool.h"
#include "Vulkan/Image.h"
#include "Vulkan/QueryPool.h"

namespace rt::gpu
{
class GpuEngine;

/// What one frame traces.
struct FrameRequest
{
    // The render's settings: spp decides the integrator (as a headless render of spp); sampling is made
    // progressive (progressiveSampling).
    RenderSettings settings;
    CameraDesc camera; // the window's camera, not necessarily the scene's
    bool cost = false; // time the samples (heatmap); needs costAvailable()
};

/// What a window frame's samples aim at on the device's clock when their count is automatic: long enough that
/// each launch's tail (the wait for its slowest paths: about 2 ms on an H200 at 600x600) costs a few percent
/// against a headless render of the same samples, which batches them (rt_gpu_bench, cornell-box-lights 600x600,
/// 64 spp: 1 sample a frame took 3.9x the headless device time, 16 took 1.07x, 64 0.96x; docs/notebook/
/// PERFORMANCE.md §33), and short enough for 20 frames a second.
inline constexpr double kFrameTargetSeconds = 0.05;

/// The samples per pixel of the next frame whose count is automatic, after one of `samples` took `seconds` of the
/// device's time (<= 0: unmeasured): kFrameTargetSeconds' worth, at most 4x `samples` (a first frame measured in
/// microseconds is not trusted with a second's samples), at least 1 and at most `most`.
std::uint32_t autoFrameSamples(std::uint32_t samples, double seconds, std::uint32_t most);

/// One frame's timed samples, summarised: the heatmap's legend and automatic scale.
struct CostSummary
{
    float max = 0.0f; // largest ticks per sample of any pixel (0: the frame timed nothing)
    float high = 0.0f; // 95th percentile of the pixels (interpolated in log2 within its power-of-two bucket)
};

CostSummary summarizeCost(const shader::CostStats& stats);

class ProgressiveFrame final
{
public:
    /// `frameSlots`: frames in flight, each with its own uniforms and descriptor sets.
    ProgressiveFrame(const GpuEngine& engine, std::uint32_t frameSlots);
    ProgressiveFrame(const ProgressiveFrame&) = delete;
    ProgressiveFrame& operator=(const ProgressiveFrame&) = delete;
    ~ProgressiveFrame();

    /// The device has the shader clock, so the heatmap can be shown.
    bool costAvailable() const;
    VkExtent2D extent() const { return m_accumulation.extent(); }
    /// The images were cleared (or written) since they were made: the display pass may read them.
    bool hasImage() const { return !m_imagesUndefined; }

    /// Images of `extent` (kept when it is unchanged) and descriptor sets for the engine's current scene. Call
    /// with the device idle, after every setScene and resize; the next frame must begin with recordClear.
    void prepare(VkExtent2D extent);

    /// The integrator the samples of `request` run on: the one a headless render of its settings (spp and all)
    /// on the current scene would run (SceneTracer::integratorFor).
    GpuIntegrator integratorFor(const FrameRequest& request) const;

    /// Compiles the pipeline the samples of `request` run on when it was not compiled before (SceneTracer::prepare),
    /// so that a caller can time the compilation apart from the samples; recordSamples compiles it at its first
    /// use otherwise. True at the first call for that pipeline (SceneTracer::prepare); false for a request with the
    /// cost (the heatmap's own pipeline).
    bool preparePipeline(const FrameRequest& request) const;

    /// Traces one sample of `request` at one pixel and waits, the device idle before: a driver that finishes a
    /// pipeline's compilation at its first launch (lavapipe: seconds) does it here rather than in the first timed
    /// frame, as GpuEngine's beginFrame does (restir-di: its three passes at that pixel). The accumulation image is
    /// left cleared but for that pixel: the caller records a clear before its samples. The heatmap's pipeline is
    /// not warmed up (its frames are not timed renders).
    void warmUp(const FrameRequest& request);

    /// Records the clearing of the accumulation and cost images: the next sample starts a new image.
    void recordClear(VkCommandBuffer cmd);
    /// Records `count` samples of `request` (indices from `firstSample` on) for frame `slot`, whose previous
    /// frame must have completed (its uniforms are rewritten now), and makes them visible to the display pass.
    void recordSamples(VkCommandBuffer cmd, std::uint32_t slot, const FrameRequest& request, std::uint32_t firstSample,
                       std::uint32_t count);

    VkImageView accumulationView() const { return m_accumulationView.Handle(); }
    VkImageView costView() const { return m_costView.Handle(); }

    /// The cost of `slot`'s last timed frame (zeros if it timed nothing), and zero counts for its next one.
    /// Call once `slot`'s previous frame has completed.
    CostSummary takeCostSummary(std::uint32_t slot);

    /// The device seconds of `slot`'s last frame's samples (from the end of the work before them to the end of
    /// theirs: GPU timestamps, as GpuEngine times a headless render's launches), once; nullopt when that frame
    /// traced nothing or the queue has no timestamps. Call once `slot`'s previous frame has completed.
    std::optional<double> takeTraceSeconds(std::uint32_t slot);

    /// Replaces the accumulation with `image` (extent()'s size) as one sample per pixel, its compensation cleared
    /// and its cost `costPerSample` (a value per pixel, row by row; empty: cleared): another engine's render (the
    /// window's CPU engines), shown by the display pass, radiance or heatmap, and read back by readImage as it
    /// is. Waits for the device, uploads and waits.
    void showImage(const Image& image, std::span<const float> costPerSample = {});

    /// The accumulated estimate (radiance sum / sample count per pixel), read back: submits and waits.
    Image readImage() const;

private:
    /// The uniforms of `request` for images of extent(), its sampling made progressive.
    shader::RenderUniforms uniformsOf(const FrameRequest& request) const;
    GpuIntegrator integratorOf(const shader::RenderUniforms& uniforms, int spp) const;
    void createCostResources();
    void writeCostDescriptors() const;
    /// Set 0 of every slot for the images, the slot's uniforms and restir-di's buffers if made.
    void makeSets();
    /// restir-di's buffers of extent(), made (and the sets with them) the first time a frame needs them: waits for
    /// the device, so that no frame in flight still uses the old sets.
    void ensureRestir();

    const GpuEngine* m_engine;
    std::vector<vk::Buffer> m_uniforms; // per slot
    vk::QueryPool m_timestamps; // two per slot: before and after its samples; none without timestamps
    std::vector<bool> m_slotTimed; // the slot's timestamps were written and not taken yet
    vk::Buffer m_counters; // NaN / Inf samples, shared: only atomics touch it
    vk::Buffer m_traceCounters; // TraceCounters, bound but never counted in: the window's uniforms leave countRays 0
    vk::Image m_accumulation;
    vk::ImageView m_accumulationView;
    vk::Image m_compensation; // the Kahan compensation of m_accumulation's sums
    vk::ImageView m_compensationView;
    vk::Image m_cost;
    vk::ImageView m_costView;
    bool m_imagesUndefined = true; // not cleared since they were created
    std::vector<TracingDescriptors> m_sets; // per slot
    std::unique_ptr<RestirBuffers> m_restir; // restir-di's, of extent(), once a frame has asked for it
    bool m_restirHistory = false; // its final reservoirs hold an iteration of the current image
    // The heatmap's pipeline and set kSetCost per slot, made when first asked for (lavapipe compiles a
    // ray-tracing pipeline for seconds at its first launch).
    std::unique_ptr<PathTracingPipeline> m_costPipeline;
    std::vector<vk::Buffer> m_costStats; // per slot: CostStats
    std::vector<vk::DescriptorPool> m_costPools;
    std::vector<VkDescriptorSet> m_costSets;
};
} // namespace rt::gpu
