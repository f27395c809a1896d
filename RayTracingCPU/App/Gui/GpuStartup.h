// The CPU app's GPU engine, created off the UI thread: creating it opens the Vulkan device (0.2 s on lavapipe; its
// pipelines compile at a render's first use of them). A process may hold one Vulkan device at a time (the loader's
// device-level function pointers are process-wide), so this is the only one, kept for the app's lifetime;
// that is also why the window itself draws with OpenGL, not Vulkan. A deferred start waits for begin(): the window
// starts the engine once its launch render has ended, so that the start (0.2 s of a core on lavapipe, more on a
// driver of a real GPU) does not share the CPU with the render it times.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "Render/RenderEngine.h"

namespace rt::gui
{
class GpuStartup
{
public:
    enum class State
    {
        Starting,
        Ready,
        Unavailable
    };
    struct Status
    {
        State state = State::Starting;
        std::string detail; // Ready: the device's name; Unavailable: why (the DeviceError's text)
    };
    struct Options
    {
        bool enabled = true; // false: Unavailable at once ("--no-gpu")
        bool validation = false; // Khronos validation layer on the engine's device
        bool deferred = false; // start at begin(), not at once
    };

    explicit GpuStartup(const Options& options);
    /// Waits for a start in progress, then destroys the engine (and its device) on this thread.
    ~GpuStartup();
    GpuStartup(const GpuStartup&) = delete;
    GpuStartup& operator=(const GpuStartup&) = delete;

    /// Starts a deferred start; nothing when it has started (or cannot). Any thread.
    void begin();
    Status status() const;
    /// A start has begun and not ended: the GPU engine is being made on its own thread now.
    bool starting() const;
    /// Blocks until the engine is ready (returns it) or unavailable (nullptr), or until `giveUp()` is true
    /// (nullptr; polled every 50 ms).
    RenderEngine* wait(const std::function<bool()>& giveUp);
    /// Validation warnings and errors so far (0 without validation or without an engine).
    std::uint64_t validationMessages() const;

private:
    void start(const Options& options);

    Options m_options;

    mutable std::mutex m_mutex;
    std::condition_variable m_resolved;
    Status m_status;
    std::unique_ptr<RenderEngine> m_engine;
    std::thread m_thread;
};
} // namespace rt::gui
