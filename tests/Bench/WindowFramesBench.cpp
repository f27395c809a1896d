// The GPU window's samples against a headless render of the same settings, on the device's own clock (issue 38:
// the window's render no slower than headless beyond 5 %). The window traces `samples per frame` per frame
// (ProgressiveFrame, one submission each, as the window records them) and its timings table adds up the
// timestamps around each frame's samples; the headless render batches its samples into as few launches as
// its batches allow (GpuEngine through the render driver: stats.gpuSeconds). Both after a warm-up, the
// pipeline compiled.
//   rt_gpu_bench --benchmark_filter=. --benchmark_enable_random_interleaving=true --benchmark_repetitions=5
//   args: width (square image), spp, and for WindowFrames the samples per frame (0: automatic, by the device time of
//   the frame before: autoFrameSamples, the window's default)
#include <benchmark/benchmark.h>

#include <algorithm>

#include "Engine/GpuEngine.h"
#include "Engine/ProgressiveFrame.h"
#include "Engine/SceneTracer.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"
#include "Vulkan/CommandBuffer.h"

namespace
{
using namespace rt;
using namespace rt::gpu;

constexpr const char* kScene = "cornell-box-lights";

GpuEngine& engine()
{
    static GpuEngine e;
    static const Scene scene = makeScene(kScene);
    static const bool ready = (e.setScene(scene), true);
    (void)ready;
    return e;
}

RenderSettings settingsOf(const benchmark::State& state)
{
    RenderSettings s;
    s.width = int(state.range(0));
    s.aspect = 1.0f;
    s.spp = int(state.range(1));
    return s;
}

void Headless(benchmark::State& state)
{
    GpuEngine& e = engine();
    const RenderSettings settings = settingsOf(state);
    RenderControl warmUp;
    test::renderWithSettings(e, settings, warmUp);
    std::uint64_t paths = 0;
    for (auto _ : state)
    {
        RenderControl control;
        const RenderResult r = test::renderWithSettings(e, settings, control);
        state.SetIterationTime(r.stats.gpuSeconds);
        paths += r.stats.paths;
    }
    state.counters["Mpaths/s"] = benchmark::Counter(double(paths) * 1e-6, benchmark::Counter::kIsRate);
    state.SetLabel(e.deviceName());
}

void WindowFrames(benchmark::State& state)
{
    GpuEngine& e = engine();
    const RenderSettings settings = settingsOf(state);
    const auto spp = std::uint32_t(settings.spp);
    const auto perFrame = std::uint32_t(state.range(2));
    ProgressiveFrame frame(e, 1);
    frame.prepare({std::uint32_t(settings.width), std::uint32_t(settings.height())});
    const FrameRequest request{.settings = settings, .camera = e.scene()->camera};
    frame.preparePipeline(request);
    frame.warmUp(request);
    std::uint64_t paths = 0;
    std::uint32_t automatic = 1; // carried from image to image, as the window carries it
    for (auto _ : state)
    {
        double seconds = 0.0;
        for (std::uint32_t done = 0; done < spp;)
        {
            const std::uint32_t count = std::min(perFrame > 0 ? perFrame : automatic, spp - done);
            vk::submitAndWait(e.context().device(), e.context().commandPool(), [&](VkCommandBuffer cmd) {
                if (done == 0)
                    frame.recordClear(cmd);
                frame.recordSamples(cmd, 0, request, done, count);
            });
            const double frameSeconds = frame.takeTraceSeconds(0).value_or(0.0);
            seconds += frameSeconds;
            automatic = autoFrameSamples(count, frameSeconds, 256);
            done += count;
        }
        state.SetIterationTime(seconds);
        paths += std::uint64_t(settings.width) * std::uint64_t(settings.height()) * spp;
    }
    state.counters["Mpaths/s"] = benchmark::Counter(double(paths) * 1e-6, benchmark::Counter::kIsRate);
    state.SetLabel(e.deviceName());
}

BENCHMARK(Headless)->Args({600, 64})->Args({64, 64})->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(WindowFrames)
    ->Args({600, 64, 1})
    ->Args({600, 64, 4})
    ->Args({600, 64, 16})
    ->Args({600, 64, 64})
    ->Args({600, 64, 0})
    ->Args({64, 64, 1})
    ->Args({64, 64, 0})
    ->Args({64, 64, 64})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
} // namespace
