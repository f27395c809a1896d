#include "Support/PixelStatistics.h"

#include <cmath>

namespace rt::test
{
MeanAndError pixelStatistics(const Image& image, int channel)
{
    const double n = double(image.pixelCount());
    const auto value = [channel](const vec3& p) {
        return channel < 0 ? (double(p.x) + p.y + p.z) / 3.0 : double(p[channel]);
    };
    MeanAndError r;
    for (const vec3& p : image.pixels())
        r.mean += value(p);
    r.mean /= n;
    double squares = 0.0; // two passes: the one-pass formula cancels for nearly constant images
    for (const vec3& p : image.pixels())
        squares += (value(p) - r.mean) * (value(p) - r.mean);
    const double variance = squares / (n - 1.0);
    r.pixelStdDev = std::sqrt(variance);
    r.standardError = std::sqrt(variance / n);
    return r;
}
} // namespace rt::test
