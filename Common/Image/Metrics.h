// Error metrics between a test image and a reference, both linear radiance of the same size, averaged over
// every pixel and RGB channel (research notes §5). Throws UsageError on a size mismatch.
#pragma once

#include "Image/Image.h"

namespace rt
{
struct ErrorMetrics
{
    double mse = 0.0; // mean (I - R)^2
    double rmse = 0.0; // sqrt(mse)
    double relMse = 0.0; // mean (I - R)^2 / (R^2 + epsilon)
    double psnr = 0.0; // 10 log10(peak^2 / mse), peak = 1 (display white); +inf for identical images
};

inline constexpr double kRelMseEpsilon = 1e-2; // Gharbi et al. 2019's choice, stated wherever relMSE is shown

ErrorMetrics compareImages(const Image& test, const Image& reference, double relMseEpsilon = kRelMseEpsilon);
} // namespace rt
