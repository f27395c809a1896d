// --strategy auto's arithmetic on the host (Compare/AutoStrategy.h): a candidate's error from its measurements
// (measuredRelMse), which the search computes for every candidate after every round, on the host's clock and
// within its guard of twice the budget: 13 candidates of a GPU pilot's 512 x 512 pixels (a megakernel's halves) in
// the first round, three measurements in the final one.
#include <benchmark/benchmark.h>

#include <random>

#include "Compare/AutoStrategy.h"

namespace
{
void MeasuredRelMse(benchmark::State& state)
{
    const auto side = static_cast<int>(state.range(0));
    const auto measurements = static_cast<std::size_t>(state.range(1));
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.5f, 0.1f);
    std::vector<rt::compare::PilotHalves> halves(measurements);
    for (auto& h : halves)
    {
        h.a = rt::Image(side, side);
        h.b = rt::Image(side, side);
        for (rt::Image* image : {&h.a, &h.b})
            for (auto& pixel : image->pixels())
                pixel = rt::vec3(noise(rng), noise(rng), noise(rng));
    }
    const std::vector<float> denominator(std::size_t(side) * side * 3, 0.5f);
    std::vector<rt::compare::PilotMeasurement> list;
    for (const auto& h : halves)
        list.push_back({&h, &denominator});
    for (auto _ : state)
        benchmark::DoNotOptimize(rt::compare::measuredRelMse(list));
    state.SetItemsProcessed(state.iterations() * std::int64_t(side) * side * std::int64_t(measurements));
}
BENCHMARK(MeasuredRelMse)->Args({32, 1})->Args({512, 1})->Args({512, 3})->Unit(benchmark::kMillisecond);
} // namespace
