// ray-tracing-gpu without --headless: the window, its frame loop and everything it draws with. One Vulkan
// device for everything (the engine's), presenting to the window's surface.
//
// A frame: wait for its slot, acquire a swapchain image; with ray tracing on, clear the accumulation image if
// the image settings changed (or every frame without accumulation) and trace a few samples per pixel into it;
// then one render pass: the display pass (radiance or heatmap) or the rasterised preview, letterboxed beside
// the panel's column (WindowLayout.h), and the panel; present. The image has the settings' size, whatever the
// window's. Scenes are built on a worker thread while the old one stays on screen; only the upload and the
// acceleration-structure build wait for the device.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "App/Gui/Actions.h"
#include "App/Gui/WindowState.h"
#include "Cli/WindowSize.h"
#include "Compare/AutoStrategy.h"
#include "Engine/GpuEngine.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::gui
{
struct WindowOptions
{
    WindowState initial; // settings from the command line; image.request names `scene` and the image's size
    std::optional<WindowSize> windowSize; // --window-size; none: the panel and the image side by side, 1:1
    std::optional<int> deviceIndex;
    bool validation = false;
    GpuIntegrator integrator = GpuIntegrator::Auto; // --integrator
    std::filesystem::path shaderDir; // --shader-dir; empty: the shaders beside the app
    std::optional<int> frames; // run this many frames after the actions, then stop
    std::filesystem::path screenshot; // with frames: what the window shows in the last frame, as PNG
    std::filesystem::path stateJson; // at exit: the window's and the image's sizes, the layout drawn, the message
    std::vector<Action> actions;
    std::string savePath; // the panel's initial file name for Save image
    compare::PilotBudget pilotBudget; // the strategy pilot's (--pilot-budget, --pilot-max-seconds)
    std::vector<std::string> fixedSettings; // the strategy settings given as flags, which the pilot does not vary
};

/// Opens the window on `scene` and runs until it is closed or `options.frames` have run. Returns the exit
/// status: 0, or 1 when validation was on and reported anything, device destruction (leaked objects)
/// included. Throws rt::Error (no display, no device that presents, a failing action or save with --frames).
int runWindow(const WindowOptions& options, Scene scene);
} // namespace rt::gpu::gui
