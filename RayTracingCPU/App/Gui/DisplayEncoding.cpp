#include "App/Gui/DisplayEncoding.h"

#include <array>

#include "Image/ImageIO.h"

namespace rt::gui
{
namespace
{
// 2^14 steps over [0, 1]: the curve's steepest part (slope 12.92 near 0) moves by 0.2 of a level per step.
constexpr int kSteps = 1 << 14;

unsigned char encode(float linear)
{
    static const std::array<unsigned char, kSteps + 1> table = [] {
        std::array<unsigned char, kSteps + 1> t{};
        for (int i = 0; i <= kSteps; ++i)
            t[i] = linearToSrgb8(float(i) / float(kSteps));
        return t;
    }();
    if (!(linear > 0.0f))
        return 0; // also NaN
    if (linear >= 1.0f)
        return 255;
    return table[static_cast<int>(linear * float(kSteps) + 0.5f)];
}
} // namespace

std::vector<unsigned char> toDisplayRgba(const Image& image)
{
    std::vector<unsigned char> rgba(image.pixelCount() * 4);
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
    {
        const vec3& v = image.data()[i];
        rgba[4 * i + 0] = encode(v.x);
        rgba[4 * i + 1] = encode(v.y);
        rgba[4 * i + 2] = encode(v.z);
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}
} // namespace rt::gui
