// The interface every engine offers the render driver (Render/RenderDriver.h): take a scene, then trace
// ranges of camera samples into an accumulator the engine keeps, and hand back the estimate. The driver owns
// everything around that (batches, progress, cancellation, previews, timing, stats), once for every engine.
// Virtual at this level only (a few calls per batch); nothing per ray goes through it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "Error.h"
#include "Image/Image.h"
#include "Render/CostMap.h"
#include "Render/LightSampleCounts.h"
#include "Render/RayCounts.h"
#include "Render/RenderControl.h"
#include "Render/RenderSettings.h"
#include "Scene/Scene.h"

namespace rt
{
/// What an engine counted while tracing since beginFrame.
struct SampleTally
{
    RayCounts rays; // rays traced, by kind
    LightSampleCounts lightSamples; // NEE's light samples by outcome, counted with the rays
    bool raysCounted = false; // false: the engine did not count them (the GPU engine without --count-rays)
    std::uint64_t nanSamples = 0; // camera samples whose radiance had a NaN (dropped from the accumulator)
    std::uint64_t infSamples = 0; // ... or an infinity
    int threadsUsed = 1; // host threads that traced
};

/// What one call of traceSamples did.
struct BatchResult
{
    bool complete = true; // false: cancelled part way, the accumulator as it was before the call
    double deviceSeconds = -1.0; // the device's own time for the batch; < 0 when it has no such clock
};

/// The samples of every pixel seed block `block` holds once a frame in seed blocks of `seedBlock` samples (0: one
/// block) has traced `samples` of them (RenderEngine::setSeedBlock).
inline std::uint32_t samplesInSeedBlock(std::uint32_t samples, std::uint32_t seedBlock, std::uint32_t block)
{
    if (seedBlock == 0)
        return block == 0 ? samples : 0u;
    const std::uint64_t before = std::uint64_t(block) * seedBlock;
    return samples <= before ? 0u : static_cast<std::uint32_t>(std::min<std::uint64_t>(samples - before, seedBlock));
}

/// What a frame of `settings` needs to be cut into seed blocks (RenderEngine::setSeedBlock) whatever the block, in
/// words; nullptr where it can be: not with stratified sampling (its strata are the spp's square) nor restir-di (its
/// reservoirs carry from sample to sample).
inline const char* seedBlocksRefusal(const RenderSettings& settings)
{
    return settings.sampling == PixelSampling::Stratified ? "random, accumulate or Sobol pixel sampling"
           : settings.estimator == Estimator::RestirDi   ? "an estimator other than restir-di"
                                                          : nullptr;
}

class RenderEngine
{
public:
    virtual ~RenderEngine() = default;

    virtual EngineKind kind() const = 0;
    /// CPU model and thread count, or the Vulkan device's name.
    virtual std::string deviceName() const = 0;

    /// Builds the engine's acceleration structures for `scene` (validated). The scene must outlive every
    /// frame that follows. Returns the build time in seconds. Throws rt::Error on failure.
    virtual double setScene(const Scene& scene) = 0;
    /// The scene last given to setScene; nullptr before the first.
    virtual const Scene* scene() const = 0;
    /// Seconds the last setScene took.
    virtual double buildSeconds() const = 0;

    /// The camera of the frames that follow: `camera`, or the scene's when empty. The render driver sets it from
    /// RenderRequest::camera before every beginFrame.
    void setCamera(std::optional<CameraDesc> camera) { m_camera = std::move(camera); }
    /// The frames that follow stand for a render of `paths` camera paths (width x height x spp; 0: each frame for
    /// itself): an engine that picks a variant by a render's size (the GPU's integrator: the wavefront from 2^20
    /// NEE paths) picks the render's, so that --strategy auto's small frames time what the render will run. (A
    /// pilot's frames ran the megakernel under a render on the wavefront: on an H200's cornell-box-lights the
    /// megakernel's projected sampling with the BVH took 2.3x the time of solid-angle sampling with uniform
    /// selection, the wavefront's 1.23x, the render's 1.27x; docs/notebook/PERFORMANCE.md §36.)
    void setRepresentedPaths(std::uint64_t paths) { m_representedPaths = paths; }
    /// The frames that follow in seed blocks of `samples` camera samples each (0: one seed, the default): sample s of
    /// a pixel is drawn as sample s mod `samples` of seed + s / `samples` and summed apart, so that one frame of
    /// k x `samples` spp holds k independent renders, each bit for bit the render of its seed alone (on the same
    /// engine variant: the GPU picks its integrator by a block's paths, or by setRepresentedPaths')
    /// (Shared/Shading/Camera.h). estimate() then holds the blocks one below the other (width x height·k), each
    /// block divided by its own samples, and radianceSums() their sums, block after block. --strategy auto's two
    /// halves of a measurement take one frame so on a GPU (AutoStrategy.cpp): its wavefront pays a frame's tail
    /// once, not twice. A frame of seed blocks needs random, accumulate or Sobol sampling, no restir-di, no cost
    /// recording, spp a multiple of `samples` and at most 65536 rows in all: beginFrame throws UsageError otherwise
    /// (seedBlocksOf).
    void setSeedBlock(std::uint32_t samples) { m_seedBlock = samples; }
    std::uint32_t seedBlock() const { return m_seedBlock; }

    /// Camera paths one batch of traceSamples should hold: enough that the per-batch cost vanishes, few
    /// enough that a batch ends well within a second (cancel, progress, no GPU watchdog).
    virtual std::uint64_t pathsPerBatch() const = 0;
    /// Camera paths the engine traces at once: a frame of fewer pixels leaves part of the device idle, and its
    /// time per path says little about a larger frame's (--strategy auto's pilot keeps at least this many pixels, and
    /// times its final round on frames of up to 16x this many paths where its measurements hold fewer).
    virtual std::uint64_t concurrentPaths() const { return 1024; }
    /// The fewest pixels a frame of `settings` (its spp; the paths it stands for: setRepresentedPaths) needs to keep
    /// the device busy: concurrentPaths() where a thread traces its pixel's samples in turn (the default; the GPU's
    /// megakernel), concurrentPaths() / spp where a frame's samples run at once (the GPU's wavefront, whose waves
    /// hold pixels x samples paths). --strategy auto's pilot measures at more spp over fewer pixels where it can: a
    /// candidate's error per path over another's changes with the spp (notebook §44).
    virtual std::uint64_t busyPixels(const RenderSettings& settings) const
    {
        (void)settings;
        return concurrentPaths();
    }

    /// How many frames' preparation compileAhead does at once (1: the engine compiles nothing ahead).
    virtual std::size_t concurrentCompiles() const { return 1; }
    /// Compiles ahead what beginFrame of each of `frames` (validated by the caller) would compile on the current
    /// scene, at once where the engine can, so that their beginFrame finds it done; changes no frame. The GPU
    /// compiles a pipeline per strategy, each on a thread of its own: one after the other, --strategy auto's 13
    /// candidates took 1.1-1.8 s of an H200 host's time (notebook §67). Nothing by default. Throws UsageError
    /// before setScene, DeviceError as beginFrame.
    virtual void compileAhead(std::span<const RenderSettings> frames) { (void)frames; }
    /// Starts a frame of `settings` (validated by the caller) on the current scene: an accumulator of the
    /// settings' size, cleared, and zero tallies. Throws UsageError before setScene, DeviceError naming the
    /// limit when the image does not fit the device.
    virtual void beginFrame(const RenderSettings& settings) = 0;
    /// Adds camera samples firstSample .. firstSample + count - 1 of every pixel to the accumulator, one after
    /// the other in sample order, so the sums do not depend on how the samples are cut into batches.
    /// Advances `control` by the camera paths traced (in parts, where the engine can: progress within a
    /// batch) and may poll control.cancelRequested(): a batch it abandons leaves the accumulator as it was.
    virtual BatchResult traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control) = 0;
    /// The accumulator divided by `samples` (> 0): linear radiance, the frame's width x height.
    virtual Image estimate(std::uint32_t samples) = 0;
    /// The accumulator itself: each pixel's sum of the samples traced since beginFrame, RGB, row by row from the
    /// top (width x height x 3 values, times the frame's seed blocks), the sum estimate() divides. An MPI job adds
    /// its ranks' shares from these (Cluster/SplitRender.h).
    virtual std::vector<double> radianceSums() = 0;
    virtual SampleTally tally() const = 0;
    /// The engine's own times of the stages of its last setScene and frame, in seconds, by name (each engine's
    /// documentation names its stages); empty where the engine has none to tell.
    virtual std::map<std::string, double> stageSeconds() const { return {}; }
    /// Of stageSeconds, the last frame's stages alone: what a sum over frames may add up (the pilot's).
    virtual std::map<std::string, double> frameStageSeconds() const { return {}; }
    /// What the last frame ran on, in words, where an engine has variants (the GPU engine: the specialisation
    /// of its pipeline; the CPU engine: its path loop); empty otherwise.
    virtual std::string frameConfiguration() const { return {}; }
    /// Warnings and errors the device's validation has reported since the engine was made (the GPU engine with
    /// --validation); 0 where there is none.
    virtual std::uint64_t validationMessages() const { return 0; }
    /// Bytes the last frame holds per pixel beyond its image, by buffer ("reservoirs", "surfaces": restir-di's);
    /// empty where the frame holds none.
    virtual std::map<std::string, std::uint64_t> frameBytesPerPixel() const { return {}; }

    /// Why the engine cannot record each pixel's cost for the settings' frame, in words naming what is missing;
    /// empty when it can.
    virtual std::string costUnavailable(const RenderSettings& settings) const
    {
        (void)settings;
        return "this engine records no per-pixel cost";
    }
    /// Records each pixel's cost in the frames begun from now on (off by default: the recording costs time).
    /// Throws UsageError when turned on where costUnavailable says why not, at the next beginFrame.
    virtual void setCostRecording(bool on) { (void)on; }
    /// The cost of the samples the frame has traced in the batches that completed; empty when not recorded.
    virtual CostMap costMap() { return {}; }

protected:
    /// What beginFrame renders from: setCamera's camera, else `scene`'s.
    const CameraDesc& frameCamera(const Scene& scene) const { return m_camera ? *m_camera : scene.camera; }
    /// The seed blocks a frame of `settings` holds (1 without setSeedBlock). Throws UsageError, naming what stands
    /// in the way, where the frame cannot be cut into them (setSeedBlock's conditions; `costRecording`: the
    /// engine records each pixel's cost).
    std::uint32_t seedBlocksOf(const RenderSettings& settings, bool costRecording) const
    {
        if (m_seedBlock == 0)
            return 1;
        const char* why = seedBlocksRefusal(settings);
        if (!why && costRecording)
            why = "no per-pixel cost recording";
        else if (!why && settings.trueSpp() % int(m_seedBlock) != 0)
            why = "spp a multiple of the block";
        if (why)
            throw UsageError("seed blocks of " + std::to_string(m_seedBlock) + " samples need " + why + " (spp " +
                             std::to_string(settings.trueSpp()) + ")");
        const std::uint32_t blocks = static_cast<std::uint32_t>(settings.trueSpp()) / m_seedBlock;
        if (std::uint64_t(blocks) * std::uint64_t(settings.height()) > std::uint64_t(kMaxImageSide))
            throw UsageError("seed blocks of " + std::to_string(m_seedBlock) + " samples: " + std::to_string(blocks) +
                             " blocks of " + std::to_string(settings.height()) + " rows pass " +
                             std::to_string(kMaxImageSide) + " rows");
        return blocks;
    }

    /// The paths the frame of `framePaths` stands for (setRepresentedPaths).
    std::uint64_t representedPaths(std::uint64_t framePaths) const
    {
        return m_representedPaths > 0 ? m_representedPaths : framePaths;
    }

private:
    std::optional<CameraDesc> m_camera;
    std::uint64_t m_representedPaths = 0;
    std::uint32_t m_seedBlock = 0;
};
} // namespace rt
