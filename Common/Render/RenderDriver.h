// The one render driver of every engine: it cuts a frame into batches of samples (Render/BatchPlan.h), asks
// the engine to trace each into its accumulator, and owns what surrounds the tracing — progress and
// cancellation (RenderControl), previews, timing and the stats — so that every engine reports the same
// figures measured the same way.
#pragma once

#include <functional>

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

/// Renders `request.settings` of the scene last given to engine.setScene, which `request.scene` names (the
/// stats report it). Blocks; stops between batches when control.requestCancel() is called, with
/// stats.cancelled set and the estimate of the finished batches. Throws UsageError for invalid settings or an
/// engine without a scene, DeviceError when the image exceeds a device limit.
RenderResult render(RenderEngine& engine, const RenderRequest& request, RenderControl& control,
                    const PreviewCallback& preview = {});
} // namespace rt
