// The settings panel (appendix B.2 of the thesis: UI style and font, scene, ray tracing, camera, profiler)
// plus what the thesis app lacked: the estimator, statistics and saving the image. Every change goes through
// Controls, the functions the scripted actions call too.
#pragma once

#include <string>

#include "App/Gui/Controls.h"
#include "Compare/AutoStrategy.h"
#include "App/Gui/WindowLayout.h"

namespace rt::gpu::gui
{
/// The panel column's width in pixels at font scale 1 (WindowLayout.h gives it at most half the window).
inline constexpr float kPanelWidth = 300.0f;

/// What the panel shows but does not edit.
struct PanelInfo
{
    std::string device;
    bool costAvailable = false; // the device has the shader clock: the profiler section exists
    std::string building; // the scene being built, empty when none
    std::string sceneError; // why the last scene build failed (the scene on screen stayed), empty when none
    bool microfacet = false; // the scene on screen has a microfacet material: the roughness slider applies
    double framesPerSecond = 0.0;
    double megaSamplesPerSecond = 0.0; // camera samples (paths) per second, in millions
    int accumulatedSpp = 0;
    int samplesPerFrame = 1; // of the last frame (the automatic count, or the panel's)
    std::string engineStatus; // a CPU engine's render: its progress, or the last one's spp and time
    float costMax = 0.0f; // largest ticks per sample of the last timed frame
    float costScale = 1.0f; // the palette's top in use (automatic or not)
    std::string costUnit = "ticks per sample"; // of costMax and costScale: the GPU's, or a CPU engine's map's
    Extent window; // the framebuffer
    Extent image; // the image letterboxed in it (Stats)
    const compare::AutoChoice* pilot = nullptr; // the last strategy pilot's, none before the first
};

/// What belongs to the panel alone (text being typed).
struct PanelState
{
    std::string savePath = "ray-tracing-gpu.png";
    std::string sceneFile; // the path typed beside Load
    std::string loadError; // why Load refused the path
};

/// Draws the panel into `column` (framebuffer pixels, WindowLayout::panel); `framebufferScale` is ImGui's
/// framebuffer pixels per window coordinate. Returns the rectangle ImGui drew it in, in framebuffer pixels.
PixelRect drawPanel(Controls& controls, const WindowState& state, const PanelInfo& info, PanelState& panel,
                    const PixelRect& column, float framebufferScale);
} // namespace rt::gpu::gui
