// One row of a comparison's table (engine x strategy x spp, or a strategy of the equal-time comparison): its
// renders over seeds and rounds, and the figures the tables print from them (Compare.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "Compare/Confidence.h"
#include "Compare/Measurement.h"
#include "Image/Metrics.h"

namespace rt::compare
{
/// One row of a comparison: its render with each of options.seeds seeds (the request's seed + k), timed in
/// each of options.rounds interleaved rounds. A seed renders the same image in every round (the same streams);
/// the rounds measure its time again. The first seed's first round keeps its image (the CPU/GPU comparison, the
/// equal-time figure); the others' images are dropped once measured.
struct SeededRow
{
    std::vector<std::vector<Measurement>> runs; // [seed][round]

    const Measurement& first() const { return runs.front().front(); }
    /// Round 0's value of each seed.
    std::vector<double> values(double (*of)(const Measurement&)) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
            out.push_back(of(seed.front()));
        return out;
    }
    static double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
    /// Every seed's and round's value.
    std::vector<double> all(double (*of)(const Measurement&)) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
            for (const Measurement& m : seed)
                out.push_back(of(m));
        return out;
    }
    double ms() const { return median(all([](const Measurement& m) { return m.ms(); })); }
    double wallMs() const { return median(all([](const Measurement& m) { return m.wallMs; })); }
    double gpuMs() const { return median(all([](const Measurement& m) { return m.gpuMs; })); }
    /// (max - min) / median of every time: the rounds' (and seeds') spread.
    double spread() const
    {
        const std::vector<double> t = all([](const Measurement& m) { return m.ms(); });
        return (*std::max_element(t.begin(), t.end()) - *std::min_element(t.begin(), t.end())) / median(t);
    }
    Interval relMse() const { return metric(ErrorMetric::RelMse); }
    /// The metric's mean over the seeds (round 0's value: every round renders the same image).
    Interval metric(ErrorMetric which) const
    {
        std::vector<double> v;
        for (const auto& seed : runs)
            v.push_back(metricValue(seed.front().error, which));
        return meanInterval(v);
    }
    /// metric^k x seconds per seed (k = efficiencyPower), at the median of its rounds' times: the inverse of
    /// the efficiency 1 / (metric^k s).
    std::vector<double> costs(ErrorMetric which) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
        {
            std::vector<double> t;
            for (const Measurement& m : seed)
                t.push_back(m.ms());
            out.push_back(std::pow(metricValue(seed.front().error, which), efficiencyPower(which)) * median(t) * 1e-3);
        }
        return out;
    }
    /// Files `m`, the render of seed index k in round `round`, dropping its image unless it is the first's.
    /// Renders may come in any order (a distributed comparison's ranks); every one must have come before the
    /// row is read.
    void set(std::size_t k, int round, Measurement m)
    {
        if (runs.size() <= k)
            runs.resize(k + 1);
        const auto r = static_cast<std::size_t>(round);
        if (runs[k].size() <= r)
            runs[k].resize(r + 1);
        if (k > 0 || r > 0)
            m.image = Image();
        runs[k][r] = std::move(m);
    }
};
} // namespace rt::compare
