// What the Monte Carlo tests share: fixed-seed uniform points, histogramming into a domain's cells,
// and the significance level of every chi-square test (research notes §2.1: alpha 0.01, Šidák over the
// configurations a test runs). tests/Common's samplers and tests/Gpu's chi-square of their GPU twins.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "Math/Math.h"
#include "Random/Pcg.h"

namespace rt::test
{
inline constexpr double kChiSquareAlpha = 0.01;

/// A point of the unit square from the project's generator: the warps see what the renderers feed them.
inline vec2 uniform2(Rng& rng)
{
    const float x = rng.nextFloat();
    const float y = rng.nextFloat();
    return {x, y};
}

/// Counts per cell of `cellCount` cells; `cellOf` returns -1 for a point outside the domain, counted in
/// `outside` (a test decides whether any is allowed).
struct Histogram
{
    std::vector<double> counts;
    long outside = 0;
};

inline Histogram histogram(int cellCount, long samples, std::uint32_t seed, const std::function<int(Rng&)>& cellOf)
{
    Histogram h;
    h.counts.assign(static_cast<std::size_t>(cellCount), 0.0);
    Rng rng(pcgHash(seed));
    for (long i = 0; i < samples; ++i)
    {
        const int c = cellOf(rng);
        if (c < 0)
            ++h.outside;
        else
            h.counts[static_cast<std::size_t>(c)] += 1.0;
    }
    return h;
}

/// Mean and standard error of the mean of `samples` values of an estimator.
struct MeanEstimate
{
    double mean = 0.0;
    double standardError = 0.0;
};

inline MeanEstimate estimateMean(long samples, const std::function<double(long)>& value)
{
    // Welford's update: the values can be large (1 / pdf) and their sum of squares would lose the variance.
    double mean = 0.0, m2 = 0.0;
    for (long i = 0; i < samples; ++i)
    {
        const double x = value(i);
        const double delta = x - mean;
        mean += delta / double(i + 1);
        m2 += delta * (x - mean);
    }
    const double variance = samples > 1 ? m2 / double(samples - 1) : 0.0;
    return {mean, std::sqrt(variance / double(samples))};
}
} // namespace rt::test
