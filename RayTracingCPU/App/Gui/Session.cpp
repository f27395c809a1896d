#include "App/Gui/Session.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ActionGrammar.h"
#include "Cli/HeadlessRun.h"
#include "IO/AtomicFile.h"
#include "Error.h"
#include "Gui/PlotFiles.h"
#include "Image/Heatmap.h"
#include "Image/ImageIO.h"
#include "Render/MemoryBudget.h"
#include "Scene/CameraMoves.h"
#include "SceneFile/SceneFile.h"

namespace rt::gui
{
namespace
{
nlohmann::json toJson(const RenderRequest& request)
{
    const RenderSettings& r = request.settings;
    return {{"scene", request.scene.id},
            {"count", request.scene.options.count},
            {"mesh", request.scene.options.meshPath},
            {"fresnel", fresnelOptionName(request.scene.options.fresnel)},
            {"roughness_scale", request.scene.options.roughnessScale},
            {"spp", r.spp},
            {"true_spp", r.trueSpp()},
            {"depth", r.depth},
            {"width", r.width},
            {"height", r.height()},
            {"aspect", r.aspect},
            {"sampling", toString(r.sampling)},
            {"estimator", toString(r.estimator)},
            {"light_sampler", toString(r.lightSampler)},
            {"light_selection", toString(r.lightSelection)},
            {"russian_roulette", toString(r.russianRoulette)},
            {"unidirectional_light", r.unidirectionalLight},
            {"seed", r.seed},
            {"camera", cameraJson(request.camera)}};
}

std::string duration(double seconds)
{
    if (seconds < 0.0)
        return "?";
    if (seconds < 60.0)
        return fmt::format("{:.1f} s", seconds);
    return fmt::format("{}:{:02}", int(seconds) / 60, int(seconds) % 60);
}

const char* toString(GpuStartup::State state)
{
    switch (state)
    {
    case GpuStartup::State::Starting: return "starting";
    case GpuStartup::State::Ready: return "ready";
    case GpuStartup::State::Unavailable: return "unavailable";
    }
    return "?";
}
} // namespace

Session::Session(RenderJob& job, const RenderRequest& image, EngineKind engine, bool loop, bool chooseStrategy,
                 bool heatmap)
    : m_job(job), m_image(image), m_engine(engine), m_loop(loop), m_heatmap(heatmap), m_gpu(job.gpuStatus())
{
    m_watch.watch(m_image.scene.id, m_image.scene.fileVersion);
    if (chooseStrategy)
        this->chooseStrategy();
    else
        render(); // the window opens on the command line's render
}

bool Session::tryImage(const RenderRequest& candidate)
{
    try
    {
        candidate.settings.validate();
        // The command line's memory check, where the scene is known (a new scene is checked by its build).
        const RenderSettings& s = candidate.settings;
        if (const std::optional<SceneSummary> summary = m_job.sceneSummary(candidate.scene.id))
            checkMemory(renderBytes(s, summary->objects),
                        fmt::format("a {}x{} render of {}", s.width, s.height(), candidate.scene.id),
                        availableMemoryBytesReplacing(memoryEstimate().value_or(0)));
    }
    catch (const Error& e)
    {
        note(e.what(), true);
        return false;
    }
    m_image = candidate;
    return true;
}

std::optional<std::uint64_t> Session::memoryEstimate() const
{
    const std::optional<SceneSummary> summary = m_job.sceneSummary(m_image.scene.id);
    return summary ? std::optional(renderBytes(m_image.settings, summary->objects)) : std::nullopt;
}

bool Session::setScene(const std::string& idOrPath)
{
    if (const std::string problem = sceneProblem(idOrPath); !problem.empty())
    {
        note(problem, true);
        return false;
    }
    RenderRequest s = m_image;
    s.scene.id = idOrPath;
    s.scene.fileVersion = sceneFileVersion(idOrPath);
    s.camera.reset(); // another scene, its own view
    if (!tryImage(s))
        return false;
    m_watch.watch(idOrPath, s.scene.fileVersion);
    return true;
}

void Session::setFresnel(std::optional<shader::FresnelModel> fresnel) { m_image.scene.options.fresnel = fresnel; }

void Session::setRoughnessScale(float scale)
{
    m_image.scene.options.roughnessScale = std::clamp(scale, kMinRoughnessScale, kMaxRoughnessScale);
}

bool Session::hasMicrofacetMaterial() const
{
    const std::optional<SceneSummary> summary = m_job.sceneSummary(m_image.scene.id);
    return summary && summary->microfacet;
}

std::optional<CameraDesc> Session::viewCamera() const
{
    if (m_image.camera)
        return m_image.camera;
    const std::optional<SceneSummary> summary = m_job.sceneSummary(m_image.scene.id);
    return summary ? std::optional(summary->camera) : std::nullopt;
}

bool Session::applyCamera(const CameraAction& action)
{
    if (action.reset)
    {
        m_image.camera.reset();
        return true;
    }
    const std::optional<CameraDesc> view = viewCamera();
    if (!view)
    {
        note("the camera moves once the scene is built", true);
        return false;
    }
    CameraDesc moved = *view;
    if (action.move != vec3(0.0f))
        moved = moveCamera(moved, action.move);
    if (action.yawDegrees != 0.0f || action.pitchDegrees != 0.0f)
        moved = turnCamera(moved, action.yawDegrees, action.pitchDegrees);
    m_image.camera = moved;
    return true;
}

bool Session::setFov(float degrees)
{
    const std::optional<CameraDesc> view = viewCamera();
    if (!view)
    {
        note("the camera moves once the scene is built", true);
        return false;
    }
    m_image.camera = withFov(*view, degrees);
    return true;
}

float Session::cameraSpeed() const
{
    const std::optional<SceneSummary> summary = m_job.sceneSummary(m_image.scene.id);
    return summary ? movementSpeed(summary->camera) : 0.0f;
}

bool Session::setSetting(const Setting& setting, std::string_view value)
{
    RenderRequest s = m_image;
    if (!setting.assign(setting, s.settings, value))
    {
        note(setting.refusal(value), true);
        return false;
    }
    return tryImage(s);
}

bool Session::setCount(int count)
{
    // As --count: at least 1 (-1 for the scene's own), and refused up front where the scene would not fit.
    if (count == 0)
    {
        note("count must be at least 1 (-1: the scene's own)", true);
        return false;
    }
    if (count > 0)
    {
        try
        {
            checkMemory(renderBytes(0, std::uint64_t(count)), fmt::format("count={}", count), availableMemoryBytes());
        }
        catch (const Error& e)
        {
            note(e.what(), true);
            return false;
        }
    }
    RenderRequest s = m_image;
    s.scene.options.count = count < 0 ? -1 : count;
    return tryImage(s);
}

void Session::setPdf(bool on) { m_image.settings.estimator = on ? Estimator::Mixture : Estimator::BsdfOnly; }

bool Session::applySceneDefaults()
{
    const std::optional<SceneSummary> d = m_job.sceneSummary(m_image.scene.id);
    if (!d)
    {
        note("the scene's defaults are known once it has been built: render it first", true);
        return false;
    }
    RenderRequest s = m_image;
    rt::applySceneDefaults(s.settings, d->defaults);
    return tryImage(s);
}

bool Session::selectEngine(EngineKind engine)
{
    if (engine == EngineKind::Gpu && m_gpu.state == GpuStartup::State::Unavailable)
    {
        note("the GPU engine is unavailable: " + m_gpu.detail, true);
        return false;
    }
    m_engine = engine;
    return true;
}

void Session::setLoop(bool on)
{
    m_loop = on;
    if (!m_job.setLoop(on) && on)
        render(); // loop rendering of an idle window starts rendering, as the thesis' checkbox did
}

void Session::setHeatmap(bool on)
{
    m_heatmap = on;
    if (on && (!m_preview || (m_preview->cost.empty() && m_preview->costUnavailable.empty())))
        render();
}

void Session::render()
{
    m_requested = m_image;
    m_message.clear();
    m_job.submit({.image = m_image, .engine = m_engine, .loop = m_loop, .heatmap = m_heatmap});
    m_progress = m_job.progress();
}

void Session::chooseStrategy()
{
    m_requested = m_image;
    m_message.clear();
    m_job.submit({.image = m_image, .engine = m_engine, .loop = m_loop, .heatmap = m_heatmap, .chooseStrategy = true});
    m_progress = m_job.progress();
}

void Session::cancel()
{
    m_job.cancel();
    note("cancelled", false);
}

bool Session::saveImage(const std::filesystem::path& png)
{
    if (!m_preview)
    {
        note("nothing rendered yet", true);
        return false;
    }
    try
    {
        if (const std::string problem = saveImagePathProblem(png.string()); !problem.empty())
            throw UsageError(problem);
        const Preview& p = *m_preview;
        const std::vector<std::filesystem::path> linear = writePngWithLinear(png, p.linear);
        // The image is written as it is on screen; what it is, the message says.
        std::string what;
        if (!p.complete && !p.request.loop)
            what = fmt::format(": a partial image, {} of {} spp ({})", p.samples, p.request.image.settings.trueSpp(),
                               m_progress.busy && !imageIsStale() ? "still rendering" : "the render was cancelled");
        else if (!p.complete)
            what = fmt::format(": {} spp of loop rendering, the last pass partial", p.samples);
        if (imageIsStale())
            what += " (rendered with other settings than the panel's)";
        note(fmt::format("saved {}, {} and {}{}", png.string(), linear[0].filename().string(),
                         linear[1].filename().string(), what),
             false);
        spdlog::info("{}", message());
        return true;
    }
    catch (const Error& e)
    {
        note(e.what(), true);
        return false;
    }
}

std::string Session::suggestedImageName() const
{
    const RenderRequest& s = m_preview ? m_preview->request.image : m_image;
    const RenderSettings& r = s.settings;
    return fmt::format("{}_{}x{}_{}spp_{}.png", sceneShortName(s.scene.id), r.width, r.height(), m_preview ? m_preview->samples : r.trueSpp(),
                       toString(m_preview ? m_preview->request.engine : m_engine));
}

std::string Session::suggestedPlotName() const
{
    const RenderSettings& r = m_image.settings;
    return fmt::format("{}_{}x{}_depth{}_convergence.png", sceneShortName(m_image.scene.id), r.width, r.height(),
                       r.depth);
}

void Session::setFontSize(float pixels)
{
    const float kept = std::clamp(pixels, float(kMinFontPixels), float(kMaxFontPixels));
    if (kept != pixels)
    {
        note(fmt::format("font size {:g} px: {} than the {} allowed, {:g} px; using {:g} px", pixels,
                         pixels > kept ? "more" : "less", pixels > kept ? "largest" : "smallest", kept, kept),
             false);
        spdlog::warn("{}", message());
    }
    m_display.fontSize = kept;
}

std::string Session::progressText() const
{
    const JobProgress& p = m_progress;
    switch (p.phase)
    {
    case JobPhase::WaitingForGpu: return "waiting for the GPU engine to start...";
    case JobPhase::BuildingScene: return "building the scene...";
    case JobPhase::ChoosingStrategy: return "choosing the strategy (a pilot of 5 % of the render, 2 s at most)...";
    case JobPhase::Rendering:
    {
        std::string text = fmt::format("{:.0f}%  {} elapsed, ETA {}", p.fraction * 100.0, duration(p.elapsedSeconds),
                                       duration(p.etaSeconds));
        if (m_loop)
            text += fmt::format("  (loop {})", p.loopIteration + 1);
        return text;
    }
    case JobPhase::Idle: break;
    }
    if (p.busy)
        return "starting...";
    switch (m_lastEnd)
    {
    case RenderEnd::None: return "idle";
    case RenderEnd::Finished: return "done";
    case RenderEnd::Failed: return "failed";
    case RenderEnd::Cancelled:
        if (m_preview && !m_preview->complete && !imageIsStale())
            return fmt::format("cancelled: {} of {} spp on screen", m_preview->samples,
                               m_preview->request.image.settings.trueSpp());
        return "cancelled";
    }
    return "?";
}

float Session::progressFraction() const
{
    if (m_progress.phase == JobPhase::Rendering)
        return float(m_progress.fraction);
    if (m_progress.busy)
        return 0.0f;
    if (m_lastEnd == RenderEnd::Finished)
        return 1.0f;
    if (m_lastEnd == RenderEnd::Cancelled && m_preview && !m_preview->complete && !imageIsStale())
        return std::min(1.0f, float(m_preview->samples) / float(m_preview->request.image.settings.trueSpp()));
    return 0.0f;
}

void Session::update()
{
    m_gpu = m_job.gpuStatus();
    if (m_engine == EngineKind::Gpu && m_gpu.state == GpuStartup::State::Unavailable)
    {
        m_engine = EngineKind::Multi;
        note("the GPU engine is unavailable (" + m_gpu.detail + "): switched to multi core", true);
    }
    if (const auto version = m_watch.poll(SceneFileWatch::Clock::now()); version && m_watch.path() == m_image.scene.id)
    {
        spdlog::info("{} changed on disk: reloading it", m_image.scene.id);
        m_image.scene.fileVersion = *version;
        ++m_sceneReloads;
    }
    if (auto choice = m_job.latestChoice(); choice && choice != m_choice)
    {
        m_choice = choice;
        // The job renders the chosen strategy: the panel shows it, unless the user has changed the image settings
        // since asking (their newer request wins).
        if (m_requested == choice->asked && m_image == choice->asked)
        {
            m_image.settings = choice->choice.chosen.applyTo(m_image.settings);
            m_requested = m_image;
        }
        note(fmt::format("strategy chosen by a pilot of {:.2f} s: {}", choice->choice.pilotWallSeconds,
                         choice->choice.chosen.name()),
             false);
        spdlog::info("{}:\n{}", message(), choice->choice.table());
    }
    if (m_requested != m_image)
        render();
    // Progress first: once it says idle, the outcomes taken next are all there are.
    m_progress = m_job.progress();
    for (RenderOutcome& outcome : m_job.takeOutcomes())
    {
        if (outcome.stats)
        {
            recordFinished(outcome);
            ++m_finished;
            m_lastEnd = RenderEnd::Finished;
            m_lastFinished = std::move(outcome);
        }
        else if (!outcome.error.empty())
        {
            ++m_failed;
            m_lastEnd = RenderEnd::Failed;
            spdlog::error("render failed: {}", outcome.error);
            note("render failed: " + outcome.error, true);
        }
        else
            m_lastEnd = RenderEnd::Cancelled; // the user's (cancel() said so) or a newer request's, which ends later
    }
    for (const FinishedReference& reference : m_job.takeReferences())
    {
        m_references.remember(reference);
        m_timings.attach(reference);
        m_plot.attach(reference);
    }
    m_preview = m_job.latestPreview();
}

void Session::recordFinished(const RenderOutcome& outcome)
{
    const RenderStats& stats = *outcome.stats;
    m_timings.record(stats, outcome.redraws, outcome.image);
    if (const std::optional<ReferenceTask> wanted = m_timings.referenceWanted())
        requestReference(*wanted);
    const EngineKind referenceEngine = m_timings.rows()[m_timings.latestRow()].reference->task.engine;
    if (outcome.loopIteration == 0)
    {
        m_loopBase = stats.request;
        m_loopSeconds = 0.0;
    }
    m_loopSeconds += stats.renderSeconds;
    // A loop's mean after 1, 2, 4, ... iterations: a line's points spread evenly on the log axis.
    const int iterations = outcome.loopIteration + 1;
    if ((iterations & (iterations - 1)) != 0)
        return;
    if (const std::optional<ReferenceTask> task =
            m_plot.add(m_loopBase, stats.engine, stats.device, m_loopSeconds, outcome.meanSamples, outcome.mean,
                       referenceEngine, iterations > 1))
        requestReference(*task); // the row's own for a render: the job holds it once
}

void Session::requestReference(const ReferenceTask& task)
{
    if (const std::optional<FinishedReference> found = m_references.find(task))
    {
        m_timings.attach(*found);
        m_plot.attach(*found);
    }
    else
        m_job.requestReference(task);
}

bool Session::savePlot(const std::filesystem::path& png)
{
    try
    {
        const std::size_t points = savePlotFiles(m_plot, m_image, png);
        if (points == 0)
        {
            note("no plot to save: no point of this work has its relMSE yet", true);
            return false;
        }
        std::filesystem::path csv = png;
        note(fmt::format("saved the plot {} and its {} points {}", png.string(), points,
                         csv.replace_extension(".csv").string()),
             false);
        return true;
    }
    catch (const std::exception& e)
    {
        note(std::string("the plot was not saved: ") + e.what(), true);
        return false;
    }
}

std::string Session::referenceText() const
{
    const ReferenceProgress& r = m_progress.reference;
    const std::string more = r.waiting > 0 ? fmt::format(" ({} more waiting)", r.waiting) : "";
    if (r.rendering)
        return fmt::format("reference for relMSE: {:.0f}% of {} spp on {}{}", r.fraction * 100.0, r.task.spp,
                           engineLabel(r.task.engine), more);
    if (r.waiting > 0)
        return fmt::format("references for relMSE: {} waiting for the render to end", r.waiting);
    return {};
}

void Session::note(std::string text, bool error)
{
    m_message = std::move(text);
    m_messageIsError = error;
}

nlohmann::json Session::stateJson() const
{
    nlohmann::json panel = toJson(m_image);
    panel["engine"] = rt::toString(m_engine);
    panel["loop"] = m_loop;
    panel["heatmap"] = m_heatmap;
    const std::optional<std::uint64_t> memory = memoryEstimate();
    panel["memory_bytes"] = memory ? nlohmann::json(*memory) : nlohmann::json();
    nlohmann::json image = nullptr;
    if (m_preview)
        image = {{"settings", toJson(m_preview->request.image)},
                 {"engine", rt::toString(m_preview->request.engine)},
                 {"samples", m_preview->samples},
                 {"complete", m_preview->complete},
                 {"heatmap", m_preview->cost.empty() ? nlohmann::json()
                                                     : toJson(m_preview->cost, summarize(m_preview->cost))},
                 {"heatmap_unavailable", m_preview->costUnavailable}};
    return {{"panel", panel},
            {"image", image},
            {"image_matches_panel", !imageIsStale()},
            {"timings", m_timings.toJson()},
            {"plot", m_plot.toJson()},
            {"gpu", {{"state", toString(m_gpu.state)}, {"detail", m_gpu.detail}}},
            {"progress", progressText()},
            {"reference_progress", referenceText()},
            {"finished_renders", m_finished},
            {"failed_renders", m_failed},
            {"scene_reloads", m_sceneReloads},
            {"strategy_choice", m_choice ? m_choice->choice.toJson() : nlohmann::json()},
            {"message", m_message}};
}
} // namespace rt::gui
