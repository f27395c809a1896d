#include "Render/RenderDriver.h"

#include <algorithm>
#include <chrono>

#include <spdlog/fmt/fmt.h>

#include "Check.h"
#include "Error.h"
#include "Render/BatchPlan.h"

namespace rt
{
namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
} // namespace

RenderResult render(RenderEngine& engine, const RenderRequest& request, RenderControl& control,
                    const PreviewCallback& preview, const FramePart& part)
{
    const Clock::time_point wallStart = Clock::now();
    const RenderSettings& settings = request.settings;
    settings.validate();
    const Scene* scene = engine.scene();
    if (!scene)
        throw UsageError(fmt::format("the {} engine was asked to render before it was given a scene",
                                     toString(engine.kind())));
    RT_CHECK_EQ(scene->id, request.scene.id); // the request names the scene the engine holds
    engine.setCamera(request.camera);
    engine.beginFrame(settings);

    const int width = settings.width;
    const int height = settings.height();
    const auto frameSamples = static_cast<std::uint32_t>(settings.trueSpp());
    RT_CHECK_LE(part.firstSample, frameSamples);
    const std::uint32_t totalSamples = part.samples.value_or(frameSamples - part.firstSample);
    RT_CHECK_LE(totalSamples, frameSamples - part.firstSample);
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    // restir-di's iterations are one sample per pixel each, its reservoirs carried from one to the next.
    BatchPlan plan(std::max(totalSamples, 1u), pixels, engine.pathsPerBatch(),
                   settings.sampling == PixelSampling::Accumulate || settings.estimator == Estimator::RestirDi);
    control.begin(pixels * frameSamples); // progress in camera paths of the whole frame, advanced by the engine

    std::uint32_t samplesDone = 0;
    Image previewImage; // the last preview's estimate, the result too when no batch followed it
    std::uint32_t previewSamples = 0;
    double deviceSeconds = 0.0;
    bool deviceTimed = true;
    const Clock::time_point renderStart = Clock::now();
    while (samplesDone < totalSamples && !control.cancelRequested())
    {
        if (part.beforeBatch)
        {
            part.beforeBatch();
            if (control.cancelRequested())
                break;
        }
        const std::uint32_t samples =
            part.oneBatch ? static_cast<std::uint32_t>(evenPart(totalSamples - samplesDone, plan.maxSamples()))
                          : plan.next(samplesDone);
        RT_DCHECK_GT(samples, 0u);
        const Clock::time_point batchStart = Clock::now();
        const BatchResult traced = engine.traceSamples(part.firstSample + samplesDone, samples, control);
        if (!traced.complete)
            break;
        plan.record(samples, secondsSince(batchStart));
        deviceTimed = deviceTimed && traced.deviceSeconds >= 0.0;
        deviceSeconds += traced.deviceSeconds;
        samplesDone += samples;
        if (preview && control.previewDue())
        {
            previewImage = engine.estimate(samplesDone);
            previewSamples = samplesDone;
            preview(previewImage, static_cast<int>(samplesDone));
        }
    }
    const double renderSeconds = secondsSince(renderStart);

    RenderResult result;
    if (samplesDone == 0)
        result.image = Image(width, height);
    else if (previewSamples == samplesDone)
        result.image = std::move(previewImage); // no second readback of the same estimate
    else
        result.image = engine.estimate(samplesDone);
    const SampleTally tally = engine.tally();
    RenderStats& st = result.stats;
    st.request = request;
    st.engine = engine.kind();
    st.device = engine.deviceName();
    st.width = width;
    st.height = height;
    st.trueSpp = static_cast<int>(samplesDone);
    st.buildSeconds = engine.buildSeconds();
    st.renderSeconds = renderSeconds;
    st.gpuSeconds = deviceTimed ? deviceSeconds : -1.0;
    st.paths = pixels * samplesDone;
    st.rays = tally.rays;
    st.lightSamples = tally.lightSamples;
    st.raysCounted = tally.raysCounted;
    st.nanSamples = tally.nanSamples;
    st.infSamples = tally.infSamples;
    st.threadsUsed = tally.threadsUsed;
    st.stageSeconds = engine.stageSeconds();
    st.frameConfiguration = engine.frameConfiguration();
    st.frameBytesPerPixel = engine.frameBytesPerPixel();
    st.cancelled = samplesDone < totalSamples; // a cancel during the last batch came too late to matter
    st.wallSeconds = secondsSince(wallStart) + st.buildSeconds; // the build belongs to the render's cost
    return result;
}
} // namespace rt
