// The GPU window's renders on the CPU engines (single and multi core), reached through the engine registry
// (Render/EngineRegistry.h), never by including them: one render at a time on a thread of its own, so the window
// keeps drawing while it runs. A newer request cancels the render in progress; the engines are made at their
// first render and kept. The scene is the window's, shared: an engine points at it while it renders, so the
// render keeps it alive when the window moves on to another.
#pragma once

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "Render/RenderControl.h"
#include "Render/RenderDriver.h"
#include "Render/RenderEngine.h"
#include "Scene/Scene.h"

namespace rt::gpu::gui
{
struct CpuRender
{
    RenderRequest request;
    EngineKind engine = EngineKind::Multi;
    std::shared_ptr<const Scene> scene; // the scene `request` names, built
    bool cost = false; // time each pixel (RenderEngine::setCostRecording): the heatmap
};

struct CpuOutcome
{
    CpuRender render;
    std::optional<RenderResult> result; // a render that ran to its end
    CostMap cost; // with CpuRender::cost: each pixel's cost, or empty and why in costUnavailable
    std::string costUnavailable;
    std::string error; // why it failed
};

class CpuRenders
{
public:
    CpuRenders();
    /// Cancels the render in progress and joins the thread.
    ~CpuRenders();
    CpuRenders(const CpuRenders&) = delete;
    CpuRenders& operator=(const CpuRenders&) = delete;

    /// Renders `render` once the render in progress has stopped (cancelled); a request not started yet is
    /// replaced.
    void submit(CpuRender render);
    /// Cancels the render in progress and drops a waiting one.
    void cancel();
    /// A render runs or waits.
    bool busy() const;
    /// The running render's fraction done (0 when none runs).
    double fraction() const;
    /// The latest render that ended (finished or failed; a cancelled one is not reported), once.
    std::optional<CpuOutcome> take();

private:
    void loop();

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<CpuRender> m_waiting;
    bool m_running = false;
    bool m_stop = false;
    std::shared_ptr<RenderControl> m_control; // of the running render
    std::optional<CpuOutcome> m_outcome;
    std::map<EngineKind, std::unique_ptr<RenderEngine>> m_engines; // the render thread's alone
    std::map<EngineKind, std::shared_ptr<const Scene>> m_scenes; // what each engine was given
    std::thread m_thread; // last: starts after the members above exist
};
} // namespace rt::gpu::gui
