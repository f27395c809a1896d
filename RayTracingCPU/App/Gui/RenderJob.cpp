#include "App/Gui/RenderJob.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include <spdlog/spdlog.h>

#include "App/Gui/DisplayEncoding.h"
#include "Error.h"
#include "Image/Heatmap.h"
#include "Scenes/Catalogue.h"

namespace rt::gui
{
namespace
{
// Previews faster than the window redraws (FramePacer) are wasted work on the render thread, and that time
// is inside the render time the timings table reports: the engines build none more often
// (RenderControl::previewDue).
constexpr auto kPreviewInterval =
    std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(FramePacer::kRenderingInterval));

/// The mean of two independent estimates, weighted by their samples per pixel (loop rendering).
Image combine(const Image& mean, int meanSamples, const Image& estimate, int samples)
{
    if (meanSamples == 0)
        return estimate;
    Image out(estimate.width(), estimate.height());
    const float keep = float(meanSamples) / float(meanSamples + samples);
    for (std::size_t i = 0; i < out.pixelCount(); ++i)
        out.data()[i] = mean.data()[i] * keep + estimate.data()[i] * (1.0f - keep);
    return out;
}
} // namespace

RenderJob::RenderJob(const GpuStartup::Options& gpu, const RenderRequest& initial,
                     std::shared_ptr<const Scene> initialScene, std::function<void()> wakeUi,
                     std::filesystem::path referenceCache, bool held, PilotOptions pilot)
    : m_gpu(gpu), m_scene(std::move(initialScene)), m_sceneKey(initial.scene), m_held(held),
      m_wakeUi(std::move(wakeUi)), m_referenceCache(std::move(referenceCache)), m_pilot(std::move(pilot)),
      m_currentScene(initial.scene)
{
    m_slots[std::size_t(EngineKind::Single)].engine = &m_single;
    m_slots[std::size_t(EngineKind::Multi)].engine = &m_multi;
    m_sceneSummaries[initial.scene.id] = {m_scene->defaults, m_scene->hasMicrofacetMaterial(), m_scene->camera,
                                          m_scene->primitiveCount() + m_scene->lights.size()};
    m_worker = std::thread([this] { workerLoop(); });
}

RenderJob::~RenderJob()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
        m_pending.reset();
        if (m_control)
            m_control->requestCancel();
    }
    m_wake.notify_all();
    m_worker.join();
}

void RenderJob::submit(const JobRequest& request)
{
    {
        std::lock_guard lock(m_mutex);
        m_pending = request;
        m_loop = request.loop;
        if (m_control)
            m_control->requestCancel();
    }
    m_wake.notify_all();
}

void RenderJob::release()
{
    {
        std::lock_guard lock(m_mutex);
        m_held = false;
    }
    m_wake.notify_all();
}

void RenderJob::cancel()
{
    std::lock_guard lock(m_mutex);
    m_pending.reset();
    if (m_control && !m_referenceRendering) // Cancel is for the person's render; a reference goes on
        m_control->requestCancel();
}

bool RenderJob::setLoop(bool loop)
{
    std::lock_guard lock(m_mutex);
    m_loop = loop;
    return m_pending.has_value() || m_phase != JobPhase::Idle;
}

JobProgress RenderJob::progress() const
{
    std::lock_guard lock(m_mutex);
    JobProgress p;
    p.phase = m_phase;
    p.busy = m_pending.has_value() || m_phase != JobPhase::Idle;
    p.loopIteration = m_loopIteration;
    if (m_control && m_phase == JobPhase::Rendering)
    {
        p.fraction = m_control->fraction();
        p.elapsedSeconds = m_control->elapsedSeconds();
        p.etaSeconds = m_control->etaSeconds();
    }
    for (const QueuedReference& queued : m_references)
        p.reference.waiting += queued.task.base.scene == m_currentScene ? 1 : 0;
    if (m_referenceRendering && m_control)
    {
        p.reference.rendering = true;
        p.reference.fraction = (m_referenceHalvesDone + m_control->fraction()) / 2.0;
        p.reference.waiting = std::max(0, p.reference.waiting - 1);
        p.reference.task = m_referenceInProgress;
    }
    return p;
}

std::shared_ptr<const StrategyChoice> RenderJob::latestChoice() const
{
    std::lock_guard lock(m_mutex);
    return m_choice;
}

std::shared_ptr<const Preview> RenderJob::latestPreview() const
{
    std::lock_guard lock(m_mutex);
    return m_preview;
}

std::vector<RenderOutcome> RenderJob::takeOutcomes()
{
    std::lock_guard lock(m_mutex);
    return std::exchange(m_outcomes, {});
}

std::optional<SceneSummary> RenderJob::sceneSummary(const std::string& sceneId) const
{
    std::lock_guard lock(m_mutex);
    const auto it = m_sceneSummaries.find(sceneId);
    return it == m_sceneSummaries.end() ? std::nullopt : std::optional(it->second);
}

void RenderJob::workerLoop()
{
    std::unique_lock lock(m_mutex);
    for (;;)
    {
        m_wake.wait(lock, [this] {
            return m_stop || (!m_held && (m_pending.has_value() || nextReference() < m_references.size()));
        });
        if (m_stop)
            return;
        if (!m_pending)
        {
            QueuedReference queued = m_references[nextReference()];
            m_control = std::make_shared<RenderControl>();
            auto control = m_control;
            m_referenceRendering = true;
            m_referenceInProgress = queued.task;
            m_referenceHalvesDone = queued.firstHalf ? 1 : 0;
            lock.unlock();
            renderReference(std::move(queued), std::move(control));
            lock.lock();
            m_control.reset();
            m_referenceRendering = false;
            m_phase = JobPhase::Idle; // a reference on the GPU may have waited for its start (engineFor)
            if (m_wakeUi)
                m_wakeUi();
            continue;
        }
        const JobRequest request = std::move(*m_pending);
        m_pending.reset();
        // Made under the lock that submit() and cancel() take, so a newer request always finds it to cancel.
        m_control = std::make_shared<RenderControl>();
        auto control = m_control;
        lock.unlock();
        run(request, std::move(control));
        m_gpu.begin(); // after the first render (a loop's: after its first iteration, in publish)
        lock.lock();
        m_control.reset();
        m_phase = JobPhase::Idle;
        m_loopIteration = 0;
        if (m_wakeUi)
            m_wakeUi();
    }
}

void RenderJob::countRedraw(bool onInput)
{
    m_redraws.fetch_add(1, std::memory_order_relaxed);
    if (onInput)
        m_redrawsOnInput.fetch_add(1, std::memory_order_relaxed);
}

void RenderJob::run(const JobRequest& request, std::shared_ptr<RenderControl> control)
{
    try
    {
        RenderEngine* engine = engineFor(request.engine, *control);
        // A GPU engine being made on its own thread (a deferred start begins after the first render) would share
        // the CPU with this render and its timing: the render waits for it.
        if (engine && request.engine != EngineKind::Gpu && m_gpu.starting())
        {
            setPhase(JobPhase::WaitingForGpu);
            m_gpu.wait([&] { return control->cancelRequested(); });
            if (control->cancelRequested())
                engine = nullptr;
        }
        if (!engine)
        {
            report({.request = request, .cancelled = true});
            return;
        }
        setPhase(JobPhase::BuildingScene);
        const std::shared_ptr<const Scene> scene = sceneFor(request.image.scene);
        bindScene(request.engine, *engine, scene);
        JobRequest job = request;
        engine->setCostRecording(false); // the pilot's renders are not timed per pixel
        const std::optional<compare::StrategyLists> candidates =
            request.chooseStrategy
                ? compare::pilotCandidates(compare::autoCandidates(*scene, {}, m_pilot.fixed), request.image.settings)
                : std::nullopt;
        if (request.chooseStrategy && !candidates)
            spdlog::info("{}", compare::kNoPilotForRestirDi);
        job.chooseStrategy = job.chooseStrategy && candidates;
        if (job.chooseStrategy)
        {
            setPhase(JobPhase::ChoosingStrategy);
            auto chosen = std::make_shared<StrategyChoice>();
            chosen->asked = request.image;
            chosen->choice = compare::chooseStrategy(*engine, request.image, *candidates, m_pilot.budget);
            job.image.settings = chosen->choice.chosen.applyTo(job.image.settings);
            job.chooseStrategy = false;
            std::lock_guard lock(m_mutex);
            chosen->generation = ++m_generation;
            m_choice = std::move(chosen);
        }

        const std::string costUnavailable = job.heatmap ? engine->costUnavailable(job.image.settings) : std::string();
        engine->setCostRecording(job.heatmap && costUnavailable.empty());
        Image mean;
        int meanSamples = 0;
        for (int iteration = 0; control; ++iteration)
        {
            RenderRequest iterationRequest = job.image;
            iterationRequest.settings.seed += static_cast<std::uint32_t>(iteration); // independent streams, wrapping is fine
            setPhase(JobPhase::Rendering, iteration);
            control->setPreviewInterval(kPreviewInterval);
            m_redraws = 0;
            m_redrawsOnInput = 0;
            const RenderResult result =
                render(*engine, iterationRequest, *control, [&](const Image& estimate, int samples) {
                    if (samples <= 0)
                        return;
                    publish(job, combine(mean, meanSamples, estimate, samples), meanSamples + samples, false);
                });
            const WindowRedraws redraws{m_redraws.load(), m_redrawsOnInput.load()};
            if (result.stats.cancelled)
            {
                report({.request = job, .cancelled = true, .redraws = redraws});
                return;
            }
            mean = combine(mean, meanSamples, result.image, result.stats.trueSpp);
            meanSamples += result.stats.trueSpp;
            auto image = std::make_shared<const Image>(result.image);
            publish(job, mean, meanSamples, true,
                    RenderOutcome{.request = job,
                                  .stats = result.stats,
                                  .image = image,
                                  .loopIteration = iteration,
                                  .mean = iteration == 0 ? image : std::make_shared<const Image>(mean),
                                  .meanSamples = meanSamples,
                                  .redraws = redraws},
                    engine->costMap(), costUnavailable);
            control = nextIteration();
        }
    }
    catch (const std::exception& e)
    {
        report({.request = request, .error = e.what()});
    }
}

void RenderJob::bindScene(EngineKind kind, RenderEngine& engine, const std::shared_ptr<const Scene>& scene)
{
    EngineSlot& slot = m_slots[std::size_t(kind)];
    if (slot.scene == scene)
        return;
    // The old scene lives until setScene has replaced what points into it; if setScene throws, the slot stays
    // empty and the next request sets the scene again.
    const auto previous = std::exchange(slot.scene, nullptr);
    engine.setScene(*scene);
    slot.scene = scene;
}

RenderEngine* RenderJob::engineFor(EngineKind kind, const RenderControl& control)
{
    EngineSlot& slot = m_slots[std::size_t(kind)];
    if (slot.engine)
        return slot.engine;
    setPhase(JobPhase::WaitingForGpu);
    m_gpu.begin();
    slot.engine = m_gpu.wait([&] { return control.cancelRequested(); });
    if (slot.engine)
        return slot.engine;
    const GpuStartup::Status status = m_gpu.status();
    if (status.state == GpuStartup::State::Unavailable)
        throw DeviceError("the GPU engine is unavailable: " + status.detail);
    return nullptr;
}

std::shared_ptr<const Scene> RenderJob::sceneFor(const SceneRef& ref)
{
    if (m_scene && m_sceneKey == ref)
        return m_scene;
    auto scene = std::make_shared<const Scene>(buildScene(ref));
    {
        std::lock_guard lock(m_mutex);
        m_sceneSummaries[ref.id] = {scene->defaults, scene->hasMicrofacetMaterial(), scene->camera,
                                    scene->primitiveCount() + scene->lights.size()};
        m_currentScene = ref;
    }
    m_scene = scene;
    m_sceneKey = ref;
    return scene;
}

void RenderJob::setPhase(JobPhase phase, int loopIteration)
{
    std::lock_guard lock(m_mutex);
    m_phase = phase;
    m_loopIteration = loopIteration;
}

void RenderJob::publish(const JobRequest& request, Image estimate, int samples, bool complete,
                        std::optional<RenderOutcome> outcome, CostMap cost, std::string costUnavailable)
{
    auto preview = std::make_shared<Preview>();
    preview->request = request;
    preview->samples = samples;
    preview->complete = complete;
    preview->rgba = toDisplayRgba(estimate); // before the lock: the UI never waits for this
    preview->linear = std::move(estimate);
    if (!cost.empty())
    {
        preview->costPainted = paintHeatmap(cost);
        preview->costRgba = toDisplayRgba(preview->costPainted);
        preview->cost = std::move(cost);
    }
    preview->costUnavailable = std::move(costUnavailable);
    std::lock_guard lock(m_mutex);
    preview->generation = ++m_generation;
    m_preview = std::move(preview);
    if (outcome)
    {
        m_gpu.begin();
        m_outcomes.push_back(std::move(*outcome));
        if (m_wakeUi)
            m_wakeUi(); // a loop iteration's timing: the job stays busy
    }
}

void RenderJob::report(RenderOutcome outcome)
{
    std::lock_guard lock(m_mutex);
    m_outcomes.push_back(std::move(outcome));
}

std::shared_ptr<RenderControl> RenderJob::nextIteration()
{
    std::lock_guard lock(m_mutex);
    if (!m_loop || m_stop || m_pending || m_control->cancelRequested())
    {
        // Idle under the lock that decided it: a setLoop(true) from now on learns that it must submit.
        m_phase = JobPhase::Idle;
        return nullptr;
    }
    m_control = std::make_shared<RenderControl>();
    return m_control;
}
} // namespace rt::gui
