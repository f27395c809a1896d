// One timed render of a comparison and what it measured, with Ctrl-C routed to whichever render is running
// (Cli/Interrupt.h).
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <string>

#include "Image/Image.h"
#include "Image/Metrics.h"
#include "Render/RenderControl.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"

namespace rt::compare
{
/// Rays traced per second by kind, in millions (RenderStats::mraysPerSecond); < 0: the engine did not count them.
struct RayRates
{
    double camera = -1.0;
    double extension = -1.0;
    double shadow = -1.0;
};

struct Measurement
{
    int spp = 0; // true spp
    double wallMs = 0.0; // host clock around the tracing
    double gpuMs = -1.0; // GPU timestamps around the trace dispatches; < 0 when the engine has none
    double mpathsPerSecond = 0.0;
    RayRates mraysPerSecond;
    bool cancelled = false;
    /// Past measure's time limit: cancelled by it (not by Ctrl-C), or finished past it where the engine could not
    /// stop it (a GPU's one batch: cancelled stays false and the image is whole).
    bool timedOut = false;
    ErrorMetrics error; // against the reference, when one was given
    Image image;
    std::map<std::string, double> stageSeconds; // the frame's own (RenderEngine::frameStageSeconds)

    /// The time a comparison reports: the GPU's own clock where there is one (no host overhead), else the host's.
    double ms() const { return gpuMs >= 0.0 ? gpuMs : wallMs; }
};

/// Renders `request` with `engine`, cancellable by Ctrl-C while an InterruptScope (Cli/Interrupt.h) lives;
/// compares with `reference` unless null. A `timeLimit` > 0 cancels the render once it has run that long (checked
/// between the engine's camera samples on the CPU, between batches on the GPU): then cancelled and timedOut.
/// Warns about NaN and Inf samples (they are left out of the image, and out of the error). `oneBatch`: the render in
/// as few batches as the engine's paths per batch allow (FramePart::oneBatch; a GPU cannot stop a batch, so its
/// render may finish past the limit: then timedOut, not cancelled).
Measurement measure(RenderEngine& engine, const RenderRequest& request, const Image* reference,
                    std::chrono::nanoseconds timeLimit = {}, bool oneBatch = false);

/// While one lives, every measure() calls `keepGoing` before each batch of its render and cancels the render
/// (cancelled, not timedOut) when it returns false: a rank of a distributed comparison serving the job's messages
/// (Cluster/TaskPool.h). On the thread that renders; one at a time.
class BatchHookScope
{
public:
    explicit BatchHookScope(std::function<bool()> keepGoing);
    ~BatchHookScope();
    BatchHookScope(const BatchHookScope&) = delete;
    BatchHookScope& operator=(const BatchHookScope&) = delete;
};

/// Half a second of untimed 4-spp renders: a GPU idle through another engine's turn drops its clocks, and an
/// H100 then ran its first rows 3-10x slower (docs/notebook/PERFORMANCE.md).
void warmUp(RenderEngine& engine, const RenderRequest& request);
} // namespace rt::compare
