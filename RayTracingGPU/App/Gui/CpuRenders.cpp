#include "App/Gui/CpuRenders.h"

#include <spdlog/spdlog.h>

#include "Render/EngineRegistry.h"

namespace rt::gpu::gui
{
CpuRenders::CpuRenders() : m_thread([this] { loop(); }) {}

CpuRenders::~CpuRenders()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
        m_waiting.reset();
        if (m_control)
            m_control->requestCancel();
    }
    m_wake.notify_all();
    m_thread.join();
}

void CpuRenders::submit(CpuRender render)
{
    {
        std::lock_guard lock(m_mutex);
        m_waiting = std::move(render);
        if (m_control)
            m_control->requestCancel();
    }
    m_wake.notify_all();
}

void CpuRenders::cancel()
{
    std::lock_guard lock(m_mutex);
    m_waiting.reset();
    if (m_control)
        m_control->requestCancel();
}

bool CpuRenders::busy() const
{
    std::lock_guard lock(m_mutex);
    return m_running || m_waiting.has_value();
}

double CpuRenders::fraction() const
{
    std::lock_guard lock(m_mutex);
    return m_control ? m_control->fraction() : 0.0;
}

std::optional<CpuOutcome> CpuRenders::take()
{
    std::lock_guard lock(m_mutex);
    return std::exchange(m_outcome, std::nullopt);
}

void CpuRenders::loop()
{
    for (;;)
    {
        CpuRender render;
        std::shared_ptr<RenderControl> control;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || m_waiting.has_value(); });
            if (m_stop)
                return;
            render = std::move(*m_waiting);
            m_waiting.reset();
            m_control = control = std::make_shared<RenderControl>();
            m_running = true;
        }
        CpuOutcome outcome{.render = render};
        try
        {
            std::unique_ptr<RenderEngine>& engine = m_engines[render.engine];
            if (!engine)
                engine = engines::make(render.engine);
            if (m_scenes[render.engine] != render.scene)
            {
                engine->setScene(*render.scene);
                m_scenes[render.engine] = render.scene;
            }
            outcome.costUnavailable = render.cost ? engine->costUnavailable(render.request.settings) : std::string();
            engine->setCostRecording(render.cost && outcome.costUnavailable.empty());
            RenderResult result = rt::render(*engine, render.request, *control);
            if (!result.stats.cancelled)
            {
                outcome.result = std::move(result);
                outcome.cost = engine->costMap();
            }
        }
        catch (const std::exception& e)
        {
            spdlog::error("the render on the {} engine failed: {}", toString(render.engine), e.what());
            outcome.error = e.what();
        }
        std::lock_guard lock(m_mutex);
        m_running = false;
        m_control.reset();
        if (outcome.result || !outcome.error.empty())
            m_outcome = std::move(outcome);
    }
}
} // namespace rt::gpu::gui
