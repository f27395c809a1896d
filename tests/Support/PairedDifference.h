// Two renders that should differ by round-off or noise only, compared pixel by pixel: renders of one scene
// with the same seeds through two code paths (a specialised and a general pipeline, the GPU's two
// integrators), which follow the same paths until a float comparison flips one.
#pragma once

#include "Image/Image.h"

namespace rt::test
{
/// Pixels where a and b differ by more than round-off (relative 1e-4, any channel).
int differingPixels(const Image& a, const Image& b);

/// z of the mean of the pixels' paired differences (a - b, summed over the channels): 0 for identical images,
/// of order 1 for renders that differ by noise (paths a flipped float comparison sent elsewhere), large for a
/// systematic difference (code one path leaves out that the scene needs). Pairing keeps it exact where the
/// images agree pixel for pixel. The images must have the same size.
double pairedZ(const Image& a, const Image& b);
} // namespace rt::test
