#include "Image/Metrics.h"

#include <cmath>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
ErrorMetrics compareImages(const Image& test, const Image& reference, double relMseEpsilon)
{
    if (test.width() != reference.width() || test.height() != reference.height())
        throw UsageError(fmt::format("cannot compare a {}x{} image with a {}x{} reference", test.width(),
                                     test.height(), reference.width(), reference.height()));
    double se = 0.0, rel = 0.0;
    for (std::size_t i = 0; i < test.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
        {
            const double r = reference.data()[i][c];
            const double d = double(test.data()[i][c]) - r;
            se += d * d;
            rel += d * d / (r * r + relMseEpsilon);
        }
    const double n = 3.0 * double(test.pixelCount());
    ErrorMetrics m;
    m.mse = n > 0 ? se / n : 0.0;
    m.rmse = std::sqrt(m.mse);
    m.relMse = n > 0 ? rel / n : 0.0;
    m.psnr = m.mse > 0.0 ? 10.0 * std::log10(1.0 / m.mse) : std::numeric_limits<double>::infinity();
    return m;
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
