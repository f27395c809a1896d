#include "App/Gui/GpuStartup.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "Error.h"
#include "Render/EngineRegistry.h"

namespace rt::gui
{
GpuStartup::GpuStartup(const Options& options) : m_options(options)
{
    if (!engines::has(EngineKind::Gpu))
        m_status = {State::Unavailable, "built without the GPU engine (RT_BUILD_GPU=OFF)"};
    else if (!options.enabled)
        m_status = {State::Unavailable, "disabled by --no-gpu"};
    else if (!options.deferred)
        begin();
}

void GpuStartup::begin()
{
    std::lock_guard lock(m_mutex);
    if (m_status.state != State::Starting || m_thread.joinable())
        return;
    m_thread = std::thread([this] { start(m_options); });
}

GpuStartup::~GpuStartup()
{
    if (m_thread.joinable())
        m_thread.join();
}

void GpuStartup::start(const Options& options)
{
    Status status;
    std::unique_ptr<RenderEngine> engine;
    const auto begin = std::chrono::steady_clock::now();
    try
    {
        engine = engines::make(EngineKind::Gpu, EngineOptions{.validation = options.validation});
        status = {State::Ready, engine->deviceName()};
        spdlog::info("GPU engine ready in {:.1f} s: {}",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), status.detail);
    }
    catch (const std::exception& e)
    {
        status = {State::Unavailable, e.what()};
        spdlog::info("GPU engine unavailable: {}", status.detail);
    }
    {
        std::lock_guard lock(m_mutex);
        m_engine = std::move(engine);
        m_status = std::move(status);
    }
    m_resolved.notify_all();
}

bool GpuStartup::starting() const
{
    std::lock_guard lock(m_mutex);
    return m_thread.joinable() && m_status.state == State::Starting;
}

GpuStartup::Status GpuStartup::status() const
{
    std::lock_guard lock(m_mutex);
    return m_status;
}

RenderEngine* GpuStartup::wait(const std::function<bool()>& giveUp)
{
    std::unique_lock lock(m_mutex);
    while (m_status.state == State::Starting)
    {
        if (giveUp())
            return nullptr;
        m_resolved.wait_for(lock, std::chrono::milliseconds(50));
    }
    return m_engine.get();
}

std::uint64_t GpuStartup::validationMessages() const
{
    std::lock_guard lock(m_mutex);
    return m_engine ? m_engine->validationMessages() : 0;
}
} // namespace rt::gui
