// CPU engine benchmarks. Each renders a whole image and reports camera paths and rays (every kind) per second.
//   rt_bench --benchmark_filter=BookFinal         book 3's final scene, the books' own settings (16 spp)
//   rt_bench --benchmark_filter=WhiteSpheres      BVH scaling with the number of spheres (thesis §4.3)
//   rt_bench --benchmark_filter=Catalogue         every scene at a small size
#include <benchmark/benchmark.h>

#include <thread>

#include "Engine/CpuEngine.h"
#include "Scenes/Catalogue.h"
#include "Support/SmallSettings.h"
#include "Support/RenderWithSettings.h"

namespace
{
using namespace rt;

void renderBenchmark(benchmark::State& state, const Scene& scene, const RenderSettings& settings, EngineKind engine)
{
    cpu::CpuEngine e(engine);
    e.setScene(scene);
    std::uint64_t paths = 0, segments = 0;
    for (auto _ : state)
    {
        RenderControl control;
        const RenderResult r = test::renderWithSettings(e, settings, control);
        paths += r.stats.paths;
        segments += r.stats.rays.total();
        benchmark::DoNotOptimize(r.image.data());
    }
    state.counters["Mpaths/s"] = benchmark::Counter(double(paths) * 1e-6, benchmark::Counter::kIsRate);
    state.counters["Msegments/s"] = benchmark::Counter(double(segments) * 1e-6, benchmark::Counter::kIsRate);
    state.counters["segments/path"] = paths ? double(segments) / double(paths) : 0.0;
}

/// RTTROYL's final render as the book's code makes it: 600x600, 16 spp stratified, depth 50, mixture of the
/// cosine pdf and the light list (light quad + glass sphere). arg 0: single core, 1: multi core.
void BookFinal(benchmark::State& state)
{
    static const Scene scene = makeScene("rtrol-cornell-glass");
    RenderSettings s;
    s.width = 600;
    s.aspect = 1.0f;
    s.spp = 16;
    s.depth = 50;
    s.sampling = PixelSampling::Stratified;
    s.estimator = Estimator::Mixture;
    s.unidirectionalLight = true;
    renderBenchmark(state, scene, s, state.range(0) ? EngineKind::Multi : EngineKind::Single);
    state.SetLabel(state.range(0) ? "multi" : "single");
}
BENCHMARK(BookFinal)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(5.0);

/// The thesis' BVH scaling scene with N spheres, 200x200, 8 spp, single core.
void WhiteSpheres(benchmark::State& state)
{
    SceneOptions o;
    o.count = static_cast<int>(state.range(0));
    const Scene scene = makeScene("white-spheres", o);
    RenderSettings s;
    s.width = 200;
    s.spp = 8;
    s.depth = 50;
    renderBenchmark(state, scene, s, EngineKind::Single);
}
BENCHMARK(WhiteSpheres)->Arg(100)->Arg(1000)->Arg(5000)->Arg(10000)->Arg(20000)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Every catalogue scene at 100 pixels wide, 8 spp, multi core.
void Catalogue(benchmark::State& state, const std::string& id)
{
    const Scene scene = makeScene(id);
    renderBenchmark(state, scene, test::settingsFor(scene, 100, 8, 50), EngineKind::Multi);
}

const bool registered = [] {
    for (const SceneInfo& info : sceneCatalogue())
        benchmark::RegisterBenchmark(("Catalogue/" + info.id).c_str(), Catalogue, info.id)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    return true;
}();
} // namespace
