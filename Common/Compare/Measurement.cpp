#include "Compare/Measurement.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "Cli/Interrupt.h"
#include "Render/RenderDriver.h"

namespace rt::compare
{
namespace
{
std::function<bool()> g_keepGoing; // BatchHookScope's
} // namespace

BatchHookScope::BatchHookScope(std::function<bool()> keepGoing)
{
    g_keepGoing = std::move(keepGoing);
}

BatchHookScope::~BatchHookScope()
{
    g_keepGoing = nullptr;
}

Measurement measure(RenderEngine& engine, const RenderRequest& request, const Image* reference,
                    std::chrono::nanoseconds timeLimit, bool oneBatch)
{
    RenderControl control;
    control.setTimeLimit(timeLimit);
    if (InterruptScope::interrupted())
        return {.cancelled = true};
    InterruptScope::route(&control);
    FramePart frame{.oneBatch = oneBatch};
    bool stopped = false; // by the hook
    if (g_keepGoing)
        frame.beforeBatch = [&] {
            if (!stopped && !g_keepGoing())
            {
                stopped = true;
                control.requestCancel();
            }
        };
    RenderResult r = render(engine, request, control, {}, frame);
    InterruptScope::route(nullptr);
    Measurement m;
    m.stageSeconds = engine.frameStageSeconds();
    m.cancelled = r.stats.cancelled || InterruptScope::interrupted() || stopped;
    m.timedOut = m.cancelled && !InterruptScope::interrupted() && !stopped && control.timeLimitPassed();
    m.wallMs = r.stats.renderSeconds * 1e3;
    if (m.cancelled)
        return m;
    // A render the limit could not stop (one batch on the GPU) that ran past it is reported too, image and all.
    m.timedOut = timeLimit.count() > 0 && control.timeLimitPassed();
    if (r.stats.nanSamples + r.stats.infSamples > 0)
        spdlog::warn("{} engine: {} NaN and {} Inf samples", toString(engine.kind()), r.stats.nanSamples,
                     r.stats.infSamples);
    m.spp = request.settings.trueSpp();
    m.wallMs = r.stats.renderSeconds * 1e3;
    m.gpuMs = r.stats.gpuSeconds >= 0.0 ? r.stats.gpuSeconds * 1e3 : -1.0;
    m.mpathsPerSecond = r.stats.mpathsPerSecond();
    if (r.stats.raysCounted)
        m.mraysPerSecond = {r.stats.mraysPerSecond(r.stats.rays.camera), r.stats.mraysPerSecond(r.stats.rays.extension),
                            r.stats.mraysPerSecond(r.stats.rays.shadow)};
    if (reference)
        m.error = compareImages(r.image, *reference);
    m.image = std::move(r.image);
    return m;
}

void warmUp(RenderEngine& engine, const RenderRequest& request)
{
    RenderRequest small = request;
    small.settings.spp = 4;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 1000 && std::chrono::steady_clock::now() - start < std::chrono::milliseconds(500); ++i)
        if (measure(engine, small, nullptr).cancelled)
            return;
}
} // namespace rt::compare
