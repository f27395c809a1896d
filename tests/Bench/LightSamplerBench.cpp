// Light sampler benchmarks: what one NEE sample of a light costs on the CPU by each --light-sampler
// (Shared/LightSampling.h), at points spread over the floor and back wall of rtrol-cornell-box (one rectangle
// light) and sphere-light-closeup (one sphere). The spherical samplers' setup at every shading point is what
// separates them from area sampling.
//   rt_bench --benchmark_filter=SampleLight
#include <benchmark/benchmark.h>

#include "Random/Pcg.h"
#include "Render/RenderSettings.h"
#include "Scenes/Catalogue.h"
#include "Shared/LightSampling.h"

namespace
{
using namespace rt;

/// arg 0: the scene (0 rtrol-cornell-box, 1 sphere-light-closeup); arg 1: the sampler (LightSampler's value).
void SampleLight(benchmark::State& state)
{
    const Scene scene = makeScene(state.range(0) == 0 ? "rtrol-cornell-box" : "sphere-light-closeup");
    const auto sampler = static_cast<shader::LightSampler>(state.range(1));
    const LightData& light = scene.lights.front();
    // Receivers on the scene's bounding box's floor and back wall, facing in.
    const Aabb box = scene.bounds();
    const vec3 size = box.max - box.min;
    struct Receiver
    {
        vec3 p;
        vec3 n;
    };
    std::vector<Receiver> receivers;
    Rng rng(1);
    for (int i = 0; i < 4096; ++i)
    {
        const float a = 0.02f + 0.96f * rng.nextFloat();
        const float b = 0.02f + 0.96f * rng.nextFloat();
        receivers.push_back(i % 2 ? Receiver{box.min + vec3(a * size.x, 0.0f, b * size.z), {0.0f, 1.0f, 0.0f}}
                                  : Receiver{box.min + vec3(a * size.x, b * size.y, size.z), {0.0f, 0.0f, -1.0f}});
    }
    std::size_t i = 0;
    float sum = 0.0f;
    for (auto _ : state)
    {
        const Receiver& r = receivers[i++ & 4095u];
        shader::LightSample ls;
        if (shader::sampleLight(light, sampler, r.p, r.n, vec2(rng.nextFloat(), rng.nextFloat()), ls))
            sum += ls.pdf;
    }
    benchmark::DoNotOptimize(sum);
    state.SetLabel(std::string(state.range(0) == 0 ? "rtrol-cornell-box " : "sphere-light-closeup ") +
                   toString(sampler));
}
} // namespace

BENCHMARK(SampleLight)->ArgsProduct({{0, 1}, {0, 1, 2, 3}});
