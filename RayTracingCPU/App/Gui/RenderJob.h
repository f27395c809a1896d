// The window's render thread. It owns the engines and renders one request at a time, so the UI thread never
// waits on a render (the thesis' app froze while it rendered). The UI submits requests and reads back
// progress, progressive previews and outcomes; every exchange goes through one mutex, and a preview is an
// immutable snapshot the UI can hold while the next one is being made.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "App/Gui/FramePacer.h"
#include "App/Gui/GpuStartup.h"
#include "App/Gui/PanelSettings.h"
#include "Gui/ReferenceTask.h"
#include "Compare/AutoStrategy.h"
#include "Engine/CpuEngine.h"
#include "Render/RenderControl.h"
#include "Render/RenderDriver.h"
#include "Render/RenderStats.h"
#include "Scene/Scene.h"

namespace rt::gui
{
struct JobRequest
{
    RenderRequest image;
    EngineKind engine = EngineKind::Multi;
    bool loop = false; // loop rendering: when a render finishes, render again with the next seed and average
    bool heatmap = false; // time each pixel (RenderEngine::setCostRecording): each finished render's cost map
    /// --strategy auto's pilot first (Compare/AutoStrategy.h: its default candidates, budget and table), then the
    /// render with the strategy it chose. The pilot runs to its end (its budget, 2 s at most) before a newer
    /// request can start.
    bool chooseStrategy = false;
};

/// What a pilot chose, for the request that asked.
struct StrategyChoice
{
    std::uint64_t generation = 0; // grows with every choice published
    RenderRequest asked; // the image settings the pilot started from
    compare::AutoChoice choice;
};

/// An estimate on its way or finished, with the request it belongs to.
struct Preview
{
    std::uint64_t generation = 0; // grows with every preview published
    JobRequest request;
    int samples = 0; // samples per pixel in the estimate, every loop iteration together
    bool complete = false; // a render (or a loop iteration) finished; false for passes and cancelled renders
    Image linear; // linear radiance, for Save image
    std::vector<unsigned char> rgba; // the same as sRGB RGBA8, for the screen
    // With JobRequest::heatmap, of a finished render (loop rendering: its latest iteration): each pixel's cost,
    // painted (Image/Heatmap.h) for the screen, and its figures; or why the engine could not time the pixels.
    CostMap cost;
    Image costPainted;
    std::vector<unsigned char> costRgba;
    std::string costUnavailable;
};

enum class JobPhase
{
    Idle,
    WaitingForGpu, // the GPU engine is still starting
    BuildingScene, // makeScene and the engine's acceleration structures
    ChoosingStrategy, // the pilot of JobRequest::chooseStrategy
    Rendering
};

struct JobProgress
{
    JobPhase phase = JobPhase::Idle;
    bool busy = false; // a render runs or a request waits to start
    double fraction = 0.0; // of the render (loop iteration) in progress
    double elapsedSeconds = 0.0;
    double etaSeconds = -1.0; // negative while unknown
    int loopIteration = 0;
    ReferenceProgress reference; // while the job is idle: the error column's reference (ReferenceTask.h)
};

/// What became of a request: one per finished render (each loop iteration), or its cancellation or failure.
struct RenderOutcome
{
    JobRequest request;
    std::optional<RenderStats> stats; // set when the render ran to the end
    std::shared_ptr<const Image> image; // and its image (a loop iteration's own, not the loop's mean)
    int loopIteration = 0; // 0 for a render without loop rendering
    std::shared_ptr<const Image> mean; // the loop's estimate so far (image for iteration 0)
    int meanSamples = 0;
    bool cancelled = false;
    std::string error; // set when it failed
    WindowRedraws redraws; // during this render (loop iteration)
};

/// What the window needs of a scene it does not hold: its own render defaults, whether the roughness slider
/// applies, and its camera.
struct SceneSummary
{
    SceneDefaults defaults;
    bool microfacet = false; // Scene::hasMicrofacetMaterial
    CameraDesc camera; // the scene's own: where the window's camera starts and resets to
    std::uint64_t objects = 0; // primitives and lights: the memory estimate's (Render/MemoryBudget.h)
};

/// The strategy pilot's budget (--pilot-budget, --pilot-max-seconds) and the strategy settings given as flags, which
/// it does not vary (Compare/AutoCommand.h).
struct PilotOptions
{
    compare::PilotBudget budget;
    std::vector<std::string> fixed;
};

class RenderJob
{
public:
    /// `initialScene`, already built from `initial` (the command line's scene), is used rather than built again.
    /// `wakeUi` is called from the render thread when an outcome or a reference arrives or the job falls idle,
    /// so that a window pacing its frames hears of it at once. References are looked up in and stored to
    /// `referenceCache` (empty: none).
    /// A `held` job starts no render before release() (a window holds its launch render until it has drawn its
    /// first frame, so that its start-up does not share the CPU with the render it times). A deferred GPU start
    /// (GpuStartup::Options) begins once the first render has ended, or at once for a render on the GPU.
    RenderJob(const GpuStartup::Options& gpu, const RenderRequest& initial, std::shared_ptr<const Scene> initialScene,
              std::function<void()> wakeUi = {}, std::filesystem::path referenceCache = {}, bool held = false,
              PilotOptions pilot = {});
    /// Cancels the render in progress and joins the render thread (and the GPU engine's start).
    ~RenderJob();
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    /// Renders `request` once the render in progress has stopped: that one is cancelled, and a request that
    /// has not started yet is replaced (twenty quick scene switches render the last scene, once).
    void submit(const JobRequest& request);
    /// Cancels the render in progress and drops a waiting request.
    void cancel();
    /// Lets a held job start its renders.
    void release();
    /// Loop rendering of the request in progress; off stops after the current iteration. Returns false when
    /// no request is in progress or waiting (nothing will loop until the next submit).
    bool setLoop(bool loop);

    /// Queues a reference (ReferenceTask.h), rendered when no render waits or runs. References of the scene of
    /// the latest render go first, the fewest spp first (newest among equals); those of other scenes wait until that scene is rendered again
    /// (no scene is built again for a reference).
    void requestReference(const ReferenceTask& task);
    /// Drops the references not started yet.
    void dropReferences();
    /// References finished (or failed) since the last call, oldest first.
    std::vector<FinishedReference> takeReferences();
    /// A reference of the current scene is queued or rendering.
    bool referencesPending() const;

    JobProgress progress() const;
    /// The newest preview; nullptr before the first.
    std::shared_ptr<const Preview> latestPreview() const;
    /// The newest pilot's choice; nullptr before the first.
    std::shared_ptr<const StrategyChoice> latestChoice() const;
    /// Outcomes since the last call, oldest first.
    std::vector<RenderOutcome> takeOutcomes();
    /// What the window shows of a scene the job has built; empty for one it has not.
    std::optional<SceneSummary> sceneSummary(const std::string& sceneId) const;
    GpuStartup::Status gpuStatus() const { return m_gpu.status(); }
    std::uint64_t gpuValidationMessages() const { return m_gpu.validationMessages(); }
    /// The window drew a frame (`onInput`: for a person's input); counted into the outcome of the render
    /// in progress. Any thread.
    void countRedraw(bool onInput);

private:
    struct EngineSlot
    {
        RenderEngine* engine = nullptr;
        std::shared_ptr<const Scene> scene; // the scene the engine was last given: it must outlive its renders
    };

    struct QueuedReference
    {
        ReferenceTask task;
        std::optional<Image> firstHalf; // kept when a render cancelled the second
        double seconds = 0.0; // tracing the halves so far
    };

    void workerLoop();
    void run(const JobRequest& request, std::shared_ptr<RenderControl> control);
    /// The engine `kind` holding `scene` (RenderEngine::setScene when it held another).
    void bindScene(EngineKind kind, RenderEngine& engine, const std::shared_ptr<const Scene>& scene);
    /// The index in m_references of the next reference to render, or m_references.size(). Under m_mutex.
    std::size_t nextReference() const;
    /// Renders m_references[index]'s halves (from the one it lacks) or finds it in the cache; finished or
    /// failed, it leaves the queue; cancelled, it stays with the halves done.
    void renderReference(QueuedReference queued, std::shared_ptr<RenderControl> control);
    /// The engine for `kind`, waiting for the GPU engine to start; nullptr when the wait was cancelled.
    RenderEngine* engineFor(EngineKind kind, const RenderControl& control);
    std::shared_ptr<const Scene> sceneFor(const SceneRef& ref);
    void setPhase(JobPhase phase, int loopIteration = 0);
    /// Publishes an estimate (and, when given, the outcome that goes with it, and the render's cost map or why
    /// there is none) in one step.
    void publish(const JobRequest& request, Image estimate, int samples, bool complete,
                 std::optional<RenderOutcome> outcome = {}, CostMap cost = {}, std::string costUnavailable = {});
    void report(RenderOutcome outcome);
    /// After a finished loop iteration: the control of the next one, or nullptr when the loop must stop.
    std::shared_ptr<RenderControl> nextIteration();

    GpuStartup m_gpu; // declared first: destroyed last, after the render thread has stopped using its engine
    cpu::CpuEngine m_single{EngineKind::Single};
    cpu::CpuEngine m_multi{EngineKind::Multi};
    // Touched by the render thread only.
    std::array<EngineSlot, 3> m_slots; // by EngineKind
    std::shared_ptr<const Scene> m_scene; // the last scene built, for the next request of the same scene
    SceneRef m_sceneKey;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    bool m_held = false;
    bool m_loop = false;
    std::optional<JobRequest> m_pending;
    std::shared_ptr<RenderControl> m_control; // of the render in progress
    JobPhase m_phase = JobPhase::Idle;
    int m_loopIteration = 0;
    std::shared_ptr<const Preview> m_preview;
    std::uint64_t m_generation = 0;
    std::shared_ptr<const StrategyChoice> m_choice;
    std::vector<RenderOutcome> m_outcomes;
    std::unordered_map<std::string, SceneSummary> m_sceneSummaries;
    std::function<void()> m_wakeUi;
    std::atomic<int> m_redraws{0}; // of the render in progress
    std::atomic<int> m_redrawsOnInput{0};
    std::filesystem::path m_referenceCache;
    PilotOptions m_pilot;
    SceneRef m_currentScene; // m_sceneKey, for the UI thread's questions
    std::deque<QueuedReference> m_references; // queued, oldest first; the one rendering stays in it
    bool m_referenceRendering = false;
    ReferenceTask m_referenceInProgress;
    int m_referenceHalvesDone = 0; // of the one rendering
    std::vector<FinishedReference> m_finishedReferences;

    std::thread m_worker; // last: starts after everything above exists
};
} // namespace rt::gui
