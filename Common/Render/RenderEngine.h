// The one interface every engine offers the apps: take a scene, render it with settings, report.
// Virtual at this level only (once per render); nothing per ray goes through it.
#pragma once

#include <functional>
#include <string>

#include "Image/Image.h"
#include "Render/RenderControl.h"
#include "Render/RenderSettings.h"
#include "Render/RenderStats.h"
#include "Scene/Scene.h"

namespace rt
{
struct RenderResult
{
    Image image; // linear radiance, settings.width x settings.height; the estimate so far if cancelled
    RenderStats stats;
};

/// Called by an engine with the current estimate and the samples per pixel it holds, after every pass of an
/// accumulating render and at the end of any render. Runs on the rendering thread: copy what you need.
using PreviewCallback = std::function<void(const Image& estimate, int samplesSoFar)>;

class RenderEngine
{
public:
    virtual ~RenderEngine() = default;

    virtual EngineKind kind() const = 0;
    /// CPU model and thread count, or the Vulkan device's name.
    virtual std::string deviceName() const = 0;

    /// Builds the engine's acceleration structures for `scene` (validated). The scene must outlive every
    /// render() that follows. Returns the build time in seconds. Throws rt::Error on failure.
    virtual double setScene(const Scene& scene) = 0;

    /// Renders the scene last given to setScene. Blocks; returns early with stats.cancelled set when
    /// control.requestCancel() is called. Throws UsageError for settings the engine cannot honour
    /// (DeviceError when they exceed a device limit).
    virtual RenderResult render(const RenderSettings& settings, RenderControl& control,
                                const PreviewCallback& preview = {}) = 0;
};
} // namespace rt
