// Every change the panel's widgets make, and the only way they make it: the scripted actions (Actions.h) call
// the same functions, so `--actions` exercises exactly what a person clicking does. Values are clamped here,
// once.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "App/Gui/WindowState.h"
#include "Math/Math.h"

namespace rt::gpu::gui
{
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
    void setRayTracing(bool on);
    void setAccumulate(bool on);
    void setHeatmap(bool on); // stays off without the shader clock (WindowState::costAvailable)
    void setAutoCostScale(bool on);
    void setCostScale(float ticksPerSample);
    void setSamplesPerFrame(int samples);
    void setTargetSpp(int spp); // 0: never stop
    void setDepth(int depth);
    void setEstimator(Estimator estimator);
    void setRussianRoulette(bool on);
    void setLightSampler(LightSampler sampler);
    void setLightSelection(LightSelection selection);
    /// Owen-scrambled Sobol pixel samples (on) or random jitter per pass (off).
    void setSobol(bool on);
    void setUnidirectionalLight(bool on);
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
    void setFontScale(float scale);
    /// The scale at which the current font is `pixels` high (the --actions' font-size, as in the CPU window).
    void setFontPixels(int pixels);
    /// Asks for the accumulated image as PNG at `png` and PFM beside it (same name, .pfm).
    void save(const std::filesystem::path& png);
    /// Asks for a window of `size` (0 x 0: minimised).
    void resize(Extent size);

private:
    WindowState* m_state;
};
} // namespace rt::gpu::gui
