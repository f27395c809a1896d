#include "App/Gui/GpuStartup.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "Error.h"

#ifdef RT_WITH_GPU_ENGINE
#include "Engine/GpuContext.h"
#include "Engine/GpuEngine.h"
#endif

namespace rt::gui
{
GpuStartup::GpuStartup(const Options& options)
{
#ifdef RT_WITH_GPU_ENGINE
    if (options.enabled)
    {
        m_thread = std::thread([this, options] { start(options); });
        return;
    }
    m_status = {State::Unavailable, "disabled by --no-gpu"};
#else
    (void)options;
    m_status = {State::Unavailable, "built without the GPU engine (RT_BUILD_GPU=OFF)"};
#endif
}

GpuStartup::~GpuStartup()
{
    if (m_thread.joinable())
        m_thread.join();
}

void GpuStartup::start([[maybe_unused]] const Options& options)
{
#ifdef RT_WITH_GPU_ENGINE
    Status status;
    std::unique_ptr<gpu::GpuEngine> engine;
    const auto begin = std::chrono::steady_clock::now();
    try
    {
        engine = std::make_unique<gpu::GpuEngine>(
            gpu::GpuEngineOptions{.validation = options.validation || gpu::validationWanted()});
        status = {State::Ready, engine->deviceName()};
        spdlog::info("GPU engine ready in {:.1f} s: {}{}",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), status.detail,
                     engine->validationEnabled() ? " (validation layer on)" : "");
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
#endif
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
#ifdef RT_WITH_GPU_ENGINE
    std::lock_guard lock(m_mutex);
    // Only start() puts an engine here, and it only makes GpuEngines.
    return m_engine ? static_cast<const gpu::GpuEngine&>(*m_engine).validationMessages() : 0;
#else
    return 0;
#endif
}
} // namespace rt::gui
