// --strategy auto's arithmetic on the host (Compare/AutoStrategy.h): the pilot's error of 13 candidates over a GPU
// pilot's 512 x 512 pixels, which runs after every round of the search and counts against its guard of twice the
// budget on the host's clock.
#include <benchmark/benchmark.h>

#include <random>

#include "Compare/AutoStrategy.h"

namespace
{
void PilotRelMse(benchmark::State& state)
{
    const auto side = static_cast<int>(state.range(0));
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.5f, 0.1f);
    std::vector<rt::compare::PilotHalves> candidates(13);
    for (auto& c : candidates)
    {
        c.a = rt::Image(side, side);
        c.b = rt::Image(side, side);
        for (rt::Image* image : {&c.a, &c.b})
            for (auto& pixel : image->pixels())
                pixel = rt::vec3(noise(rng), noise(rng), noise(rng));
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(rt::compare::pilotRelMse(candidates));
    state.SetItemsProcessed(state.iterations() * std::int64_t(side) * side * 13);
}
BENCHMARK(PilotRelMse)->Arg(32)->Arg(512)->Unit(benchmark::kMillisecond);
} // namespace
