// What the window shows and what its panel edits, split the way accumulation needs it (style pattern 20):
// ImageSettings holds everything the ray-traced image depends on, compared with a defaulted operator== so
// that a field added later cannot be forgotten: any change restarts accumulation. DisplaySettings only change
// how fast the image converges or how the window looks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "Render/RenderRequest.h"
#include "Scene/Camera.h"

namespace rt::gpu::gui
{
struct Extent
{
    int width = 0; // pixels: of the window's framebuffer, or of the ray-traced image
    int height = 0;

    bool operator==(const Extent&) const = default;
};

struct ImageSettings
{
    /// The scene on the device (id and options) and the settings of its samples: size, spp, depth, estimator,
    /// emitter sidedness, seed. The window traces progressively (sampling: accumulate) and stops at the
    /// settings' spp when DisplaySettings::stopAtSpp says so; the spp also decides the integrator, as it does
    /// for a headless render. The image keeps its size whatever the window's: the window letterboxes it
    /// (WindowLayout.h).
    RenderRequest request;
    CameraDesc camera; // the interactive camera: the scene's, moved, turned and zoomed
    bool rayTracing = true; // off: the rasterised preview
    bool accumulate = true; // off: every frame starts a new image of samplesPerFrame samples
    bool heatmap = false; // cost per pixel instead of radiance (needs the shader clock)

    bool operator==(const ImageSettings&) const = default;

    /// The image's size in pixels: the request's width and height.
    Extent extent() const { return {request.settings.width, request.settings.height()}; }
};

/// Pixel height of the panel's fonts at fontScale 1: WindowState::fonts[0] is ImGui's own, the others are
/// loaded at kPanelFontPixels.
inline constexpr float kImGuiFontPixels = 13.0f;
inline constexpr float kPanelFontPixels = 15.0f;

struct DisplaySettings
{
    int samplesPerFrame = 0; // 0: automatic, about kFrameTargetSeconds of the device's time (ProgressiveFrame.h)
    bool stopAtSpp = false; // tracing stops at the settings' spp (ImageSettings::request); false: never
    bool autoCostScale = true; // the heatmap's top follows the image: 95 % of the pixels are below it
    float costScale = 1.0e5f; // otherwise: ticks per sample at the top of the palette
    bool darkStyle = true;
    int font = 0; // index into WindowState::fonts
    float fontScale = 1.0f; // font pixels / kPanelFontPixels
};

/// The settings plus what the panel or an action asked the frame loop to do.
struct WindowState
{
    ImageSettings image;
    DisplaySettings display;
    /// What renders the ray-traced image: the GPU, progressively in the frames, or a CPU engine (single, multi
    /// core: CpuRenders.h), a whole render of the settings' spp at a time, shown when it ends.
    EngineKind engine = EngineKind::Gpu;
    CameraDesc sceneCamera; // the scene's own camera: "Reset camera"
    float cameraSpeed = 1.0f; // world units per second of WASD (movementSpeed of sceneCamera)
    bool costAvailable = false; // the device has the shader clock: the heatmap can be turned on
    std::uint64_t sceneObjects = 0; // primitives and lights of the scene shown: the memory estimate's
    std::vector<std::string> fonts{"ImGui default"}; // the panel's fonts (ImGuiLayer: those installed)
    std::optional<std::string> sceneRequest; // to be built, then shown
    std::optional<std::filesystem::path> saveRequest; // PNG path; the PFM goes beside it
    std::optional<std::filesystem::path> savePlotRequest; // the convergence plot's PNG; its CSV goes beside it
    std::optional<Extent> resizeRequest; // 0 x 0: minimised
    bool pilotRequest = false; // --strategy auto's pilot on the GPU engine, then the panel takes its choice
    /// The panel's last line for the user: an error, a saved file, a value held to its limit. Empty: none.
    std::string message;
};
} // namespace rt::gpu::gui
