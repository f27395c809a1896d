// The one render driver of every engine: it cuts a frame into batches of samples (Render/BatchPlan.h), asks
// the engine to trace each into its accumulator, and owns what surrounds the tracing — progress and
// cancellation (RenderControl), previews, timing and the stats — so that every engine reports the same
// figures measured the same way.
#pragma once

#include <functional>
#include <optional>

#include "Image/Image.h"
#include "Render/RenderControl.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"
#include "Render/RenderStats.h"

namespace rt
{
struct RenderResult
{
    Image image; // linear radiance, width x height of the settings; the finished batches' estimate if cancelled
    RenderStats stats;
};

/// Called with the current estimate and the samples per pixel it holds, after a batch when
/// control.previewDue() allows (every batch of an accumulating render by default). Runs on the rendering
/// thread: copy what you need.
using PreviewCallback = std::function<void(const Image& estimate, int samplesSoFar)>;

/// The part of the frame one render call traces: camera samples firstSample .. firstSample + samples - 1 of every
/// pixel (an MPI rank's share: Cluster/SplitRender.h; by default all of them). Progress counts the whole frame's
/// camera paths, of which this call advances its own. `beforeBatch`, when given, runs on the rendering thread
/// before each batch (a rank's messages: it may cancel through the control). `oneBatch` traces the part in as few
/// batches as the engine's paths per batch allow instead of a first batch of one sample sized by its time: for
/// renders known to take milliseconds (--strategy auto's pilot), whose second batch would cost a second launch
/// chain (the GPU's wavefront: about 1 ms of an H200's clock each) and a second tail.
struct FramePart
{
    std::uint32_t firstSample = 0;
    std::optional<std::uint32_t> samples; // empty: the frame's trueSpp() - firstSample
    std::function<void()> beforeBatch;
    bool oneBatch = false;
};

/// Renders `request.settings` of the scene last given to engine.setScene, which `request.scene` names (the
/// stats report it). Blocks; stops between batches when control.requestCancel() is called, with
/// stats.cancelled set and the estimate of the finished batches. Throws UsageError for invalid settings or an
/// engine without a scene, DeviceError when the image exceeds a device limit. With a `part`, the result holds that
/// part's samples only (stats.trueSpp is their count; the estimate is their mean).
RenderResult render(RenderEngine& engine, const RenderRequest& request, RenderControl& control,
                    const PreviewCallback& preview = {}, const FramePart& part = {});
} // namespace rt
