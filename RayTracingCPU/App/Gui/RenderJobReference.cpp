// RenderJob's references for the error column (ReferenceTask.h): the queue the UI fills and the render thread
// empties while no render of the person's waits or runs.
#include <algorithm>

#include <spdlog/spdlog.h>

#include "App/Gui/RenderJob.h"
#include "Compare/ReferenceCache.h"
#include "Compare/ReferenceRequest.h"
#include "Image/Metrics.h"

namespace rt::gui
{
void RenderJob::requestReference(const ReferenceTask& task)
{
    {
        std::lock_guard lock(m_mutex);
        const bool queued = std::any_of(m_references.begin(), m_references.end(),
                                        [&](const QueuedReference& q) { return q.task == task; });
        if (queued)
            return;
        m_references.push_back({.task = task});
    }
    m_wake.notify_all();
}

void RenderJob::dropReferences()
{
    std::lock_guard lock(m_mutex);
    m_references.clear();
    if (m_referenceRendering && m_control)
        m_control->requestCancel();
}

std::vector<FinishedReference> RenderJob::takeReferences()
{
    std::lock_guard lock(m_mutex);
    return std::exchange(m_finishedReferences, {});
}

bool RenderJob::referencesPending() const
{
    std::lock_guard lock(m_mutex);
    return m_referenceRendering || nextReference() < m_references.size();
}

std::size_t RenderJob::nextReference() const
{
    // The fewest samples first (the table's rows before a long loop's means at 4x its total spp), the newest
    // among equals: the person looks at the latest render's row.
    std::size_t best = m_references.size();
    for (std::size_t i = m_references.size(); i-- > 0;)
        if (m_references[i].task.base.scene == m_currentScene &&
            (best == m_references.size() || m_references[i].task.spp < m_references[best].task.spp))
            best = i;
    return best;
}

void RenderJob::renderReference(QueuedReference queued, std::shared_ptr<RenderControl> control)
{
    const ReferenceTask task = queued.task;
    FinishedReference finished{.task = task};
    try
    {
        RenderEngine* engine = engineFor(task.engine, *control);
        if (!engine)
            return; // cancelled while the GPU engine started: it stays queued
        const std::shared_ptr<const Scene> scene = sceneFor(task.base.scene);
        bindScene(task.engine, *engine, scene);
        const compare::ReferenceCache cache(m_referenceCache);
        const RenderRequest key = compare::referenceRequest(task.base, task.spp);
        if (std::optional<TwoHalfReference> found = cache.find(*scene, key, task.engine))
        {
            finished.image = std::make_shared<const Image>(std::move(found->mean));
            finished.ownRelMse = found->ownRelMse;
            finished.fromCache = true;
        }
        else
        {
            engine->setCostRecording(false);
            for (int half = queued.firstHalf ? 1 : 0; half < 2; ++half)
            {
                const RenderResult result =
                    render(*engine, compare::referenceHalfRequest(task.base, task.spp, half), *control);
                if (!result.stats.cancelled)
                    queued.seconds += result.stats.renderSeconds;
                if (!result.stats.cancelled && half == 0)
                    queued.firstHalf = result.image;
                if (result.stats.cancelled || half == 0)
                {
                    std::lock_guard lock(m_mutex); // the lock submit() cancels m_control under
                    if (result.stats.cancelled || control->cancelRequested())
                    {
                        // A render of the person's (or Clear) cancelled it: the half done waits in the queue for
                        // the next idle time.
                        for (QueuedReference& q : m_references)
                            if (q.task == task)
                                q = std::move(queued);
                        return;
                    }
                    m_referenceHalvesDone = 1;
                    m_control = std::make_shared<RenderControl>(); // the second half's progress from 0
                    control = m_control;
                    continue;
                }
                TwoHalfReference combined = combineReferenceHalves(*queued.firstHalf, result.image);
                cache.store(*scene, key, task.engine, combined);
                finished.image = std::make_shared<const Image>(std::move(combined.mean));
                finished.ownRelMse = combined.ownRelMse;
                finished.seconds = queued.seconds;
            }
        }
    }
    catch (const std::exception& e)
    {
        spdlog::error("the reference of {} spp on the {} engine failed: {}", task.spp, toString(task.engine), e.what());
        finished.error = e.what();
    }
    std::lock_guard lock(m_mutex);
    std::erase_if(m_references, [&](const QueuedReference& q) { return q.task == task; });
    m_finishedReferences.push_back(std::move(finished));
}
} // namespace rt::gui
