// Linear radiance to the 8-bit sRGB RGBA the window shows. Progressive previews arrive many times a second,
// and the exact transfer curve (a pow per channel) would cost more than a 1-spp pass of a small image, so
// this reads a table of the curve; Save image writes with Common's exact writer.
#pragma once

#include <vector>

#include "Image/Image.h"

namespace rt::gui
{
/// Row 0 at the top, alpha 255; clamped to [0, 1] like writePng, NaN black.
std::vector<unsigned char> toDisplayRgba(const Image& image);
} // namespace rt::gui
