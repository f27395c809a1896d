// The mean of an image over its pixels and its standard error, treating pixels as independent estimates
// (valid when every pixel has the same expectation, as in a furnace or a uniformly lit plane).
#pragma once

#include "Image/Image.h"

namespace rt::test
{
struct MeanAndError
{
    double mean = 0.0;
    double standardError = 0.0;
    double pixelStdDev = 0.0; // spread of single pixels
};

/// Of channel `channel` (0, 1, 2), or of the channel average (R + G + B) / 3 when `channel` is -1.
MeanAndError pixelStatistics(const Image& image, int channel = -1);
} // namespace rt::test
