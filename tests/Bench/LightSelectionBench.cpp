// Light selection benchmarks: what picking NEE's light costs on the CPU per shading point, by the alias table
// and by the light BVH (Shared/LightSelection.h, Shared/LightBvh.h), on cornell-box-lights (12 emitters) and
// many-lights (1,000), at points spread over the box's floor and back wall.
//   rt_bench --benchmark_filter=SelectLight
#include <benchmark/benchmark.h>

#include "Random/Pcg.h"
#include "Sampling/LightBvh.h"
#include "Sampling/LightPower.h"
#include "Scenes/Catalogue.h"
#include "Shared/LightSelection.h"

namespace
{
using namespace rt;

struct ShadingPoint
{
    vec3 p;
    vec3 n;
};

/// arg 0: the scene (0 cornell-box-lights, 1 many-lights); arg 1: the selection (LightSelection's value).
void SelectLight(benchmark::State& state)
{
    const Scene scene = makeScene(state.range(0) == 0 ? "cornell-box-lights" : "many-lights");
    const auto selection = static_cast<shader::LightSelection>(state.range(1));
    const std::vector<AliasEntry> alias = lightAliasTable(scene);
    const LightBvh bvh = buildLightBvh(scene);
    const auto count = static_cast<std::uint32_t>(scene.emitterCount());
    std::vector<ShadingPoint> points;
    Rng rng(1);
    for (int i = 0; i < 4096; ++i)
    {
        const float x = 555.0f * rng.nextFloat();
        const float y = 555.0f * rng.nextFloat();
        points.push_back(i % 2 ? ShadingPoint{{x, 0.0f, y}, {0.0f, 1.0f, 0.0f}}
                               : ShadingPoint{{x, y, 555.0f}, {0.0f, 0.0f, -1.0f}});
    }
    std::size_t i = 0;
    float sum = 0.0f;
    for (auto _ : state)
    {
        const ShadingPoint& s = points[i++ & 4095u];
        float pmf = 0.0f;
        const std::uint32_t light =
            shader::selectLight(alias.data(), bvh.nodes.data(), selection, rng.nextFloat(), count, s.p, s.n, false, pmf);
        sum += pmf + float(light);
    }
    benchmark::DoNotOptimize(sum);
    state.SetLabel(std::string(state.range(0) == 0 ? "cornell-box-lights " : "many-lights ") +
                   (selection == shader::LightSelection::Bvh ? "bvh" : "power"));
}
} // namespace

BENCHMARK(SelectLight)
    ->Args({0, int(shader::LightSelection::Power)})
    ->Args({0, int(shader::LightSelection::Bvh)})
    ->Args({1, int(shader::LightSelection::Power)})
    ->Args({1, int(shader::LightSelection::Bvh)});
