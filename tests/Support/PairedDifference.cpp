#include "Support/PairedDifference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt::test
{
int differingPixels(const Image& a, const Image& b)
{
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
        {
            double largest = 0.0;
            for (int c = 0; c < 3; ++c)
            {
                const double u = a.at(x, y)[c];
                const double v = b.at(x, y)[c];
                largest = std::max(largest, std::abs(u - v) / std::max(1e-3, std::abs(v)));
            }
            n += largest > 1e-4 ? 1 : 0;
        }
    return n;
}

double pairedZ(const Image& a, const Image& b)
{
    double sum = 0.0, sum2 = 0.0;
    const std::size_t n = a.pixelCount();
    for (std::size_t i = 0; i < n; ++i)
    {
        const vec3 d = a.pixels()[i] - b.pixels()[i];
        const double v = double(d.x) + double(d.y) + double(d.z);
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / double(n);
    const double variance = std::max(0.0, sum2 / double(n) - mean * mean);
    if (variance == 0.0)
        return mean == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return mean / std::sqrt(variance / double(n - 1));
}
} // namespace rt::test
