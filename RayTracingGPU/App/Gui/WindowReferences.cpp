#include "App/Gui/WindowReferences.h"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "Compare/ReferenceCache.h"
#include "Compare/ReferenceRequest.h"
#include "Engine/GpuEngine.h"
#include "Image/Metrics.h"

namespace rt::gpu::gui
{
using rt::gui::FinishedReference;
using rt::gui::ReferenceTask;

WindowReferences::WindowReferences(const GpuEngine& engine, std::uint32_t frameSlots, std::filesystem::path cacheDir)
    : m_engine(&engine), m_frame(engine, frameSlots), m_cacheDir(std::move(cacheDir)), m_slotHalf(frameSlots, 0)
{
}

void WindowReferences::request(const ReferenceTask& task, const Scene& scene)
{
    if (std::find(m_queue.begin(), m_queue.end(), task) != m_queue.end())
        return;
    if (std::optional<FinishedReference> found = m_memory.find(task))
    {
        m_finished.push_back(std::move(*found));
        return;
    }
    try
    {
        const compare::ReferenceCache cache(m_cacheDir);
        if (std::optional<TwoHalfReference> found =
                cache.find(scene, compare::referenceRequest(task.base, task.spp), task.engine))
        {
            m_finished.push_back({.task = task,
                                  .image = std::make_shared<const Image>(std::move(found->mean)),
                                  .ownRelMse = found->ownRelMse,
                                  .fromCache = true});
            m_memory.remember(m_finished.back());
            return;
        }
    }
    catch (const std::exception& e)
    {
        spdlog::warn("the reference cache could not be read: {}", e.what());
    }
    m_queue.push_back(task);
}

void WindowReferences::sceneChanged()
{
    m_active.reset();
    ++m_half; // samples of the dropped half still in flight are not counted into the next one
}

void WindowReferences::clear()
{
    m_queue.clear();
    sceneChanged();
}

bool WindowReferences::pending(const SceneRef& current) const { return next(current) < m_queue.size(); }

std::size_t WindowReferences::next(const SceneRef& current) const
{
    std::size_t best = m_queue.size();
    for (std::size_t i = m_queue.size(); i-- > 0;)
        if (m_queue[i].base.scene == current && (best == m_queue.size() || m_queue[i].spp < m_queue[best].spp))
            best = i;
    return best;
}

void WindowReferences::takeSeconds(std::uint32_t slot)
{
    const std::optional<double> seconds = m_frame.takeTraceSeconds(slot);
    if (seconds && m_active && m_slotHalf.at(slot) == m_half)
        m_active->seconds += *seconds;
}

std::uint64_t WindowReferences::recordSamples(VkCommandBuffer cmd, std::uint32_t slot, std::uint32_t samples,
                                              const Scene& scene, const SceneRef& current)
{
    takeSeconds(slot);
    if (samples == 0 || (m_active && !(m_active->task.base.scene == current)))
        return 0;
    if (!m_active)
    {
        const std::size_t index = next(current);
        if (index == m_queue.size())
            return 0;
        std::rotate(m_queue.begin(), m_queue.begin() + std::ptrdiff_t(index), m_queue.begin() + std::ptrdiff_t(index) + 1);
        m_active = Active{.task = m_queue.front()};
        ++m_half;
        const RenderSettings& settings = m_active->task.base.settings;
        try
        {
            // The frames in flight read the sets made again here.
            vkDeviceWaitIdle(m_engine->context().device().Handle());
            m_frame.prepare({std::uint32_t(settings.width), std::uint32_t(settings.height())});
        }
        catch (const std::exception& e)
        {
            fail(e.what());
            return 0;
        }
    }
    Active& a = *m_active;
    const RenderRequest half = compare::referenceHalfRequest(a.task.base, a.task.spp, a.half);
    const auto halfSpp = static_cast<std::uint32_t>(half.settings.trueSpp());
    if (a.traced == 0)
        m_frame.recordClear(cmd);
    const std::uint32_t count = std::min(samples, halfSpp - a.traced);
    FrameRequest request{.settings = half.settings, .camera = half.camera.value_or(scene.camera)};
    m_frame.recordSamples(cmd, slot, request, a.traced, count);
    m_slotHalf.at(slot) = m_half;
    a.traced += count;
    return std::uint64_t(count) * std::uint64_t(half.settings.width) * std::uint64_t(half.settings.height());
}

bool WindowReferences::halfRecorded() const
{
    if (!m_active)
        return false;
    const RenderRequest half = compare::referenceHalfRequest(m_active->task.base, m_active->task.spp, m_active->half);
    return m_active->traced >= std::uint32_t(half.settings.trueSpp());
}

void WindowReferences::finishHalf(const Scene& scene)
{
    if (!halfRecorded())
        return;
    for (std::uint32_t slot = 0; slot < m_slotHalf.size(); ++slot)
        takeSeconds(slot);
    Active& a = *m_active;
    try
    {
        Image image = m_frame.readImage();
        if (a.half == 0)
        {
            a.firstHalf = std::move(image);
            a.half = 1;
            a.traced = 0;
            ++m_half;
            return;
        }
        TwoHalfReference combined = combineReferenceHalves(*a.firstHalf, image);
        compare::ReferenceCache(m_cacheDir)
            .store(scene, compare::referenceRequest(a.task.base, a.task.spp), a.task.engine, combined);
        m_finished.push_back({.task = a.task,
                              .image = std::make_shared<const Image>(std::move(combined.mean)),
                              .ownRelMse = combined.ownRelMse,
                              .seconds = a.seconds});
        m_memory.remember(m_finished.back());
        m_queue.erase(m_queue.begin());
        m_active.reset();
        ++m_half;
    }
    catch (const std::exception& e)
    {
        fail(e.what());
    }
}

void WindowReferences::fail(const std::string& why)
{
    spdlog::error("the reference of {} spp failed: {}", m_active->task.spp, why);
    m_finished.push_back({.task = m_active->task, .error = why});
    m_queue.erase(m_queue.begin());
    m_active.reset();
    ++m_half;
}

rt::gui::ReferenceProgress WindowReferences::progress(const SceneRef& current) const
{
    rt::gui::ReferenceProgress progress;
    progress.waiting = int(std::count_if(m_queue.begin(), m_queue.end(),
                                         [&](const ReferenceTask& t) { return t.base.scene == current; })) -
                       (m_active ? 1 : 0);
    if (m_active)
    {
        const int halfSpp = compare::referenceHalfSpp(m_active->task.spp);
        progress.rendering = true;
        progress.task = m_active->task;
        progress.fraction = double(m_active->half * halfSpp + int(m_active->traced)) / double(2 * halfSpp);
    }
    return progress;
}
} // namespace rt::gpu::gui
