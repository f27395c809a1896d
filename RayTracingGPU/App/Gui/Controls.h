// Every change the panel's widgets make, and the only way they make it: the scripted actions (Actions.h) call
// the same functions, so `--actions` exercises exactly what a person clicking does. Values are held to their
// limits here, once, and a value held says so (WindowState::message and the log), naming the limit: the
// panel's sliders take any number typed into them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "App/Gui/WindowState.h"
#include "Render/SettingsTable.h"
#include "Math/Math.h"

namespace rt::gpu::gui
{
/// One frame's launches are recorded into one command buffer: more samples make a frame long enough for
/// the window to stop answering (and some drivers to time the submission out).
inline constexpr int kMaxSamplesPerFrame = 256;

class Controls final
{
public:
    explicit Controls(WindowState& state) : m_state(&state) {}

    /// Asks for scene `idOrPath` (built by the frame loop): a catalogue id or a scene file (.json, .gltf,
    /// .glb), which the window then reloads whenever it changes on disk. Throws rt::SceneError for an id not
    /// in the catalogue or a scene file that does not exist.
    void selectScene(const std::string& idOrPath);
    /// Every dielectric's Fresnel model (empty: each material's own); rebuilds the scene when it changes.
    void setFresnel(std::optional<shader::FresnelModel> fresnel);
    /// Every microfacet material's GGX alpha times `scale` (--roughness-scale; clamped to its range); rebuilds the
    /// scene when it changes, keeping the view.
    void setRoughnessScale(float scale);
    void setRayTracing(bool on);
    /// The engine that renders the image (WindowState::engine).
    void setEngine(EngineKind engine);
    /// Asks for --strategy auto's pilot (Compare/AutoStrategy.h) on the GPU engine for the panel's image; the frame
    /// loop runs it and sets the panel's estimator, light sampler and selection to its choice, which any setting
    /// changed afterwards overrides.
    void chooseStrategy();
    void setAccumulate(bool on);
    void setHeatmap(bool on); // stays off without the shader clock (WindowState::costAvailable)
    void setAutoCostScale(bool on);
    void setCostScale(float ticksPerSample);
    void setSamplesPerFrame(int samples);
    /// Tracing stops at `spp` samples per pixel, the render's spp (> 0); 0: never stops (the spp is kept).
    void setStopSpp(int spp);
    void setDepth(int depth);
    /// A render setting (Render/SettingsTable.h) from its word or number, as the command line takes it; false,
    /// with WindowState::message, for a value the table refuses.
    bool setSetting(const Setting& setting, std::string_view value);
    /// The books' name for two estimators: on = mixture, off = bsdf (--pdf).
    void setPdf(bool on);
    /// Owen-scrambled Sobol pixel samples (on) or random jitter per pass (off).
    void setSobol(bool on);
    float fov() const { return m_state->image.camera.vfovDegrees; }
    void setFov(float degrees);
    void setAperture(float diameter);
    void setFocusDistance(float distance);
    /// Moves by `offset` in view axes (x right, y up, z forward), world units.
    void moveCamera(const vec3& offset);
    void turnCamera(float yawDegrees, float pitchDegrees);
    void resetCamera();
    void setDarkStyle(bool dark);
    /// One of WindowState::fonts; throws rt::UsageError naming the others for any other name.
    void setFont(const std::string& name);
    /// The scale at which the current font is `pixels` high, `pixels` held to [kMinFontPixels,
    /// kMaxFontPixels] (the --actions' font-size and the panel's slider, in pixels as in the CPU window).
    void setFontPixels(int pixels);
    /// The current font's height in pixels at the current scale.
    int fontPixels() const;
    /// Asks for the accumulated image as PNG at `png` and PFM beside it (same name, .pfm). Returns false,
    /// with the reason in WindowState::message, for a name that does not end in .png.
    bool save(const std::filesystem::path& png);
    /// Asks the frame loop to save the convergence plot of the image's work as `png` and its CSV (Gui/PlotFiles.h);
    /// false (and the message) for a name that is not a .png.
    bool savePlot(const std::filesystem::path& png);
    /// Asks for a window of `size` (0 x 0: minimised).
    void resize(Extent size);

private:
    /// Sets `request` to `png`, or says in the message why a name not ending in .png is refused.
    bool requestPng(const std::filesystem::path& png, std::optional<std::filesystem::path>& request);

    WindowState* m_state;
};
} // namespace rt::gpu::gui
