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
} // namespace rt
