// Random-number benchmarks: what one draw of a camera sample's stream costs on the CPU, PCG's against
// Owen-scrambled Sobol's (Common/Random/Pcg.h, Shared/Sobol.h).
//   rt_bench --benchmark_filter=Draws
#include <benchmark/benchmark.h>

#include "Random/Pcg.h"

namespace
{
using namespace rt;

/// 64 2D draws per camera sample, over consecutive samples of one pixel; arg 0: PCG, 1: Sobol.
void Draws2D(benchmark::State& state)
{
    const bool sobol = state.range(0) != 0;
    std::uint32_t sample = 0;
    float sum = 0.0f;
    for (auto _ : state)
    {
        Rng rng = sobol ? Rng::forSobolSample(7, 1234, sample) : Rng::forSample(7, 1234, sample);
        ++sample;
        for (int i = 0; i < 64; ++i)
        {
            const vec2 u = rng.next2D();
            sum += u.x + u.y;
        }
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations() * 64);
    state.SetLabel(sobol ? "sobol" : "pcg");
}
} // namespace

BENCHMARK(Draws2D)->Arg(0)->Arg(1);
