#include "App/Gui/WindowLayout.h"

#include <algorithm>
#include <cmath>

namespace rt::gpu::gui
{
bool overlaps(const PixelRect& a, const PixelRect& b)
{
    return !a.empty() && !b.empty() && a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

WindowLayout layoutWindow(Extent framebuffer, int panelWidth, Extent image)
{
    WindowLayout layout;
    if (framebuffer.width <= 0 || framebuffer.height <= 0)
        return layout;
    const int panel = std::clamp(panelWidth, 0, int(float(framebuffer.width) * kMaxPanelShare));
    layout.panel = {0, 0, panel, framebuffer.height};

    const PixelRect area{panel + kLayoutMargin, kLayoutMargin, framebuffer.width - panel - 2 * kLayoutMargin,
                         framebuffer.height - 2 * kLayoutMargin};
    if (area.empty() || image.width <= 0 || image.height <= 0)
        return layout;
    const double scale = std::min(double(area.width) / image.width, double(area.height) / image.height);
    // Rounded, then held inside the area: the letterbox never spills under the panel or off the window.
    const int width = std::clamp(int(std::lround(image.width * scale)), 1, area.width);
    const int height = std::clamp(int(std::lround(image.height * scale)), 1, area.height);
    layout.image = {area.x + (area.width - width) / 2, area.y + (area.height - height) / 2, width, height};
    return layout;
}

WindowSize defaultWindowSize(Extent image, int panelWidth)
{
    const auto side = [](long long pixels, int minimum) {
        return int(std::clamp<long long>(pixels, minimum, kMaxWindowSide));
    };
    return {side(panelWidth + 2ll * kLayoutMargin + image.width, kMinDefaultWindow.width),
            side(2ll * kLayoutMargin + image.height, kMinDefaultWindow.height)};
}
} // namespace rt::gpu::gui
