#include "Image/Metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
ErrorMetrics compareImages(const Image& test, const Image& reference, double relMseEpsilon)
{
    if (test.width() != reference.width() || test.height() != reference.height())
        throw UsageError(fmt::format("cannot compare a {}x{} image with a {}x{} reference", test.width(),
                                     test.height(), reference.width(), reference.height()));
    double se = 0.0, rel = 0.0, ape = 0.0;
    std::vector<double> pixelRel(test.pixelCount()); // per pixel, the sum over its channels
    for (std::size_t i = 0; i < test.pixelCount(); ++i)
    {
        double pixel = 0.0;
        for (int c = 0; c < 3; ++c)
        {
            const double r = reference.data()[i][c];
            const double d = double(test.data()[i][c]) - r;
            se += d * d;
            pixel += d * d / (r * r + relMseEpsilon);
            ape += std::fabs(d) / (std::fabs(r) + relMseEpsilon);
        }
        rel += pixel;
        pixelRel[i] = pixel;
    }
    const double n = 3.0 * double(test.pixelCount());
    ErrorMetrics m;
    m.mse = n > 0 ? se / n : 0.0;
    m.rmse = std::sqrt(m.mse);
    m.relMse = n > 0 ? rel / n : 0.0;
    m.mape = n > 0 ? ape / n : 0.0;
    const std::size_t dropped = std::size_t(kTrimmedFraction * double(pixelRel.size()));
    const std::size_t kept = pixelRel.size() - dropped;
    if (kept > 0)
    {
        // The kept pixels are the `kept` smallest: partition there, then sum them.
        std::nth_element(pixelRel.begin(), pixelRel.begin() + std::ptrdiff_t(kept) - 1, pixelRel.end());
        double trimmed = 0.0;
        for (std::size_t i = 0; i < kept; ++i)
            trimmed += pixelRel[i];
        m.trimmedRelMse = trimmed / (3.0 * double(kept));
    }
    m.psnr = m.mse > 0.0 ? 10.0 * std::log10(1.0 / m.mse) : std::numeric_limits<double>::infinity();
    return m;
}

const char* toString(ErrorMetric metric)
{
    switch (metric)
    {
    case ErrorMetric::RelMse: return "relmse";
    case ErrorMetric::TrimmedRelMse: return "trimmed-relmse";
    case ErrorMetric::Mape: return "mape";
    case ErrorMetric::Flip: return "flip";
    }
    return "?";
}

const char* displayName(ErrorMetric metric)
{
    switch (metric)
    {
    case ErrorMetric::RelMse: return "relMSE";
    case ErrorMetric::TrimmedRelMse: return "trim relMSE";
    case ErrorMetric::Mape: return "MAPE";
    case ErrorMetric::Flip: return "FLIP";
    }
    return "?";
}

double metricValue(const ErrorMetrics& m, ErrorMetric metric)
{
    switch (metric)
    {
    case ErrorMetric::RelMse: return m.relMse;
    case ErrorMetric::TrimmedRelMse: return m.trimmedRelMse;
    case ErrorMetric::Mape: return m.mape;
    case ErrorMetric::Flip: return m.flip;
    }
    return m.relMse;
}

int efficiencyPower(ErrorMetric metric)
{
    return metric == ErrorMetric::Mape || metric == ErrorMetric::Flip ? 2 : 1;
}

TwoHalfReference combineReferenceHalves(const Image& halfA, const Image& halfB, double relMseEpsilon)
{
    if (halfA.width() != halfB.width() || halfA.height() != halfB.height())
        throw UsageError(fmt::format("cannot combine a {}x{} reference half with a {}x{} one", halfA.width(),
                                     halfA.height(), halfB.width(), halfB.height()));
    TwoHalfReference r{Image(halfA.width(), halfA.height()), 0.0};
    double rel = 0.0;
    for (std::size_t i = 0; i < halfA.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
        {
            const double a = halfA.data()[i][c], b = halfB.data()[i][c];
            const double mean = 0.5 * (a + b);
            r.mean.data()[i][c] = static_cast<float>(mean);
            rel += 0.25 * (a - b) * (a - b) / (mean * mean + relMseEpsilon);
        }
    const double n = 3.0 * double(halfA.pixelCount());
    r.ownRelMse = n > 0 ? rel / n : 0.0;
    return r;
}
} // namespace rt
