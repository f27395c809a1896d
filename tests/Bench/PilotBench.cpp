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

/// The search's scoring between rounds: every candidate's estimate already made (PilotSums keeps them), the relMSE
/// of each against the others' alone.
void PilotRelMseOfEstimates(benchmark::State& state)
{
    const auto side = static_cast<int>(state.range(0));
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.5f, 0.1f);
    std::vector<rt::compare::PilotEstimate> estimates;
    for (int c = 0; c < 13; ++c)
    {
        rt::compare::PilotHalves halves{rt::Image(side, side), rt::Image(side, side)};
        for (rt::Image* image : {&halves.a, &halves.b})
            for (auto& pixel : image->pixels())
                pixel = rt::vec3(noise(rng), noise(rng), noise(rng));
        estimates.push_back(rt::compare::PilotEstimate::of(halves));
    }
    std::vector<const rt::compare::PilotEstimate*> pointers;
    for (const auto& e : estimates)
        pointers.push_back(&e);
    for (auto _ : state)
        benchmark::DoNotOptimize(rt::compare::pilotRelMse(pointers));
    state.SetItemsProcessed(state.iterations() * std::int64_t(side) * side * 13);
}
BENCHMARK(PilotRelMseOfEstimates)->Arg(32)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace
