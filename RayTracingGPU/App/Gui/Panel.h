// The settings panel (appendix B.2 of the thesis: UI style and font, scene, ray tracing, camera, profiler)
// plus what the thesis app lacked: the estimator, statistics and saving the image. Every change goes through
// Controls, the functions the scripted actions call too.
#pragma once

#include <string>

#include "App/Gui/Controls.h"

namespace rt::gpu::gui
{
/// Pixels at font scale 1: the panel sits at the window's top left, 8 pixels in, over the image.
inline constexpr float kPanelWidth = 300.0f;

/// What the panel shows but does not edit.
struct PanelInfo
{
    std::string device;
    bool costAvailable = false; // the device has the shader clock: the profiler section exists
    std::string building; // the scene being built, empty when none
    std::string sceneError; // why the last scene build failed (the scene on screen stayed), empty when none
    std::string message; // the last error or saved file
    double framesPerSecond = 0.0;
    double megaSamplesPerSecond = 0.0; // camera samples (paths) per second, in millions
    int accumulatedSpp = 0;
    float costMax = 0.0f; // largest ticks per sample of the last timed frame
    float costScale = 1.0f; // the palette's top in use (automatic or not)
    Extent size;
};

/// What belongs to the panel alone (text being typed).
struct PanelState
{
    std::string savePath = "ray-tracing-gpu.png";
    std::string sceneFile; // the path typed beside Load
    std::string loadError; // why Load refused the path
};

void drawPanel(Controls& controls, const WindowState& state, const PanelInfo& info, PanelState& panel);
} // namespace rt::gpu::gui
