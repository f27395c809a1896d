// The window's state and the commands that change it. The panel's widgets and the --actions script call the
// same functions, so a test drives exactly what a person's clicks do. Image settings start a new render as
// soon as they differ from the last request's (no stale camera, no setting that waits for a scene rebuild);
// the engine and loop rendering apply to the next render.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "Gui/ConvergencePlot.h"
#include "Gui/ReferenceMemory.h"
#include "App/Gui/PanelSettings.h"
#include "App/Gui/RenderJob.h"
#include "Gui/TimingsTable.h"
#include "Cli/ActionGrammar.h"
#include "Render/SettingsTable.h"
#include "SceneFile/SceneFileWatch.h"

namespace rt::gui
{
/// How the latest render that is not running any more ended.
enum class RenderEnd
{
    None, // none has ended yet
    Finished,
    Cancelled, // by Cancel (a newer request's cancellation is followed by that request's end)
    Failed
};

class Session
{
public:
    /// Starts rendering `image` with `engine` at once, after the strategy pilot with `chooseStrategy`
    /// (--strategy auto).
    Session(RenderJob& job, const RenderRequest& image, EngineKind engine, bool loop, bool chooseStrategy = false,
            bool heatmap = false);

    // Image settings. Each returns false, with message(), for a value the engines would refuse.
    /// A catalogue id or an existing scene file (.json, .gltf, .glb), which update() then reloads whenever
    /// it changes on disk; the image on screen stays when the new version fails to load.
    bool setScene(const std::string& idOrPath);
    /// A render setting (Render/SettingsTable.h) from its word or number, as the command line takes it.
    bool setSetting(const Setting& setting, std::string_view value);
    /// white-spheres' sphere count; negative: the scene's default.
    bool setCount(int count);
    /// Every dielectric's Fresnel model; empty: each material's own (--fresnel).
    void setFresnel(std::optional<shader::FresnelModel> fresnel);
    /// Every microfacet material's GGX alpha times `scale` (--roughness-scale), clamped to its range.
    void setRoughnessScale(float scale);
    /// Whether the selected scene, once built, has a microfacet material (the roughness slider applies).
    bool hasMicrofacetMaterial() const;
    /// The books' name for two estimators: on = mixture, off = bsdf (--pdf).
    void setPdf(bool on);
    /// The selected scene's own spp, depth, width, aspect and light mode; false until the scene was built once.
    bool applySceneDefaults();

    // The camera (Scene/CameraMoves.h): a moved camera is part of the image settings (RenderRequest::camera), so
    // every move renders again; a new scene starts from its own camera.
    /// The camera the panel's image is seen from: the moved one, else the selected scene's own (once built).
    std::optional<CameraDesc> viewCamera() const;
    /// Moves, turns or resets the view from viewCamera(); false, with message(), before the scene is built.
    bool applyCamera(const CameraAction& action);
    /// The vertical field of view, held to [kMinFov, kMaxFov]; false before the scene is built.
    bool setFov(float degrees);
    /// The host memory the panel's render needs, as the command line estimates it (Render/MemoryBudget.h); none
    /// before the scene is built. A setting whose render would not fit is refused, naming the figures.
    std::optional<std::uint64_t> memoryEstimate() const;
    /// WASD's speed in world units per second (movementSpeed of the scene's camera); 0 before it is built.
    float cameraSpeed() const;

    /// False, with message(), when the GPU engine is unavailable.
    bool selectEngine(EngineKind engine);
    void setLoop(bool on);
    /// Shows each pixel's cost per sample (Image/Heatmap.h) in place of the image; on, renders are timed per
    /// pixel, and turning it on renders again when the image on screen was not.
    void setHeatmap(bool on);
    bool heatmap() const { return m_heatmap; }
    void render();
    /// Renders after --strategy auto's pilot on the selected engine (RenderJob's chooseStrategy): once it has
    /// chosen, the panel shows the chosen strategy (which the user may change like any setting) and
    /// strategyChoice() the pilot's table.
    void chooseStrategy();
    void cancel();
    /// The last pilot's choice; nullptr before the first.
    const compare::AutoChoice* strategyChoice() const { return m_choice ? &m_choice->choice : nullptr; }

    /// Writes the image on screen: `png` (sRGB) and the same name with .pfm (linear radiance). A partial
    /// image (cancelled, or still rendering) is written as it is, and the message says how many samples it
    /// holds of how many.
    bool saveImage(const std::filesystem::path& png);
    /// scene_WxH_Nspp_engine.png, from the image on screen.
    std::string suggestedImageName() const;
    /// Empties the timings table and the convergence plot, and drops the references they still wait for.
    void clearTimings()
    {
        m_timings.clear();
        m_plot.clear();
        m_job.dropReferences();
    }
    /// Writes the convergence plot's lines of the panel's work: its measured points as --compare's CSV (`png` with
    /// .csv) and their figure by plot_convergence.py (`png`). False, with message(), when there is no point or the
    /// script fails.
    bool savePlot(const std::filesystem::path& png);
    /// scene_WxH_depthN_convergence.png, from the panel's work.
    std::string suggestedPlotName() const;

    void setDark(bool dark) { m_display.dark = dark; }
    void setFont(const std::string& font) { m_display.font = font; }
    /// Held to [kMinFontPixels, kMaxFontPixels]; a size outside says so, naming the limit.
    void setFontSize(float pixels);

    /// Once per frame: notices a new version of the scene file, starts a render when the image settings
    /// differ from the last request's, collects the render thread's outcomes and newest preview.
    void update();

    const RenderRequest& image() const { return m_image; }
    EngineKind engine() const { return m_engine; }
    bool loop() const { return m_loop; }
    const DisplaySettings& display() const { return m_display; }
    const JobProgress& progress() const { return m_progress; }
    RenderEnd lastEnd() const { return m_lastEnd; }
    /// The progress bar's line ("37%  1.2 s elapsed, ETA 2.0 s", "done", "cancelled: 12 of 1000 spp on
    /// screen", ...) and how full it is.
    std::string progressText() const;
    /// The error column's reference in progress ("reference for relMSE: 40% of 256 spp on multi (1 more
    /// waiting)"); empty when none is rendering or waiting.
    std::string referenceText() const;
    /// A reference of the current scene is queued or rendering (RenderJob::referencesPending).
    bool referencesPending() const { return m_job.referencesPending(); }
    float progressFraction() const;
    const GpuStartup::Status& gpu() const { return m_gpu; }
    const std::shared_ptr<const Preview>& preview() const { return m_preview; }
    /// True when the image on screen was rendered with other image settings than the panel shows.
    bool imageIsStale() const { return !m_preview || m_preview->request.image != m_image; }
    /// The latest render that ran to the end.
    const std::optional<RenderOutcome>& lastFinished() const { return m_lastFinished; }
    /// The latest error or note for the status line; empty when there is none.
    const std::string& message() const { return m_message; }
    bool messageIsError() const { return m_messageIsError; }
    const TimingsTable& timings() const { return m_timings; }
    const ConvergencePlot& plot() const { return m_plot; }
    int finishedRenders() const { return m_finished; }
    int failedRenders() const { return m_failed; }
    /// The panel, the image on screen, the timings and the GPU engine's status (--state-json).
    nlohmann::json stateJson() const;

private:
    bool tryImage(const RenderRequest& candidate);
    /// The timings table's and the plot's share of a finished render, and the references they ask for.
    void recordFinished(const RenderOutcome& outcome);
    /// Measures against `task`'s reference at once when this session finished it before, else asks the job.
    void requestReference(const ReferenceTask& task);
    void note(std::string text, bool error);

    RenderJob& m_job;
    RenderRequest m_image;
    SceneFileWatch m_watch;
    EngineKind m_engine;
    bool m_loop;
    bool m_heatmap = false;
    DisplaySettings m_display;
    std::optional<RenderRequest> m_requested; // the image settings of the last request
    JobProgress m_progress;
    GpuStartup::Status m_gpu;
    std::shared_ptr<const Preview> m_preview;
    std::optional<RenderOutcome> m_lastFinished;
    std::string m_message;
    bool m_messageIsError = false;
    TimingsTable m_timings;
    ConvergencePlot m_plot;
    ReferenceMemory m_references; // the references finished so far
    RenderRequest m_loopBase; // the first iteration's request of the loop in progress
    double m_loopSeconds = 0.0; // its iterations' tracing so far
    int m_finished = 0;
    int m_failed = 0;
    int m_sceneReloads = 0; // new versions of the scene file noticed
    RenderEnd m_lastEnd = RenderEnd::None;
    std::shared_ptr<const StrategyChoice> m_choice; // the last pilot's, applied to the panel once
};
} // namespace rt::gui
