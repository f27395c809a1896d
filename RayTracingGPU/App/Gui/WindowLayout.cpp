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

int labStripHeight(int windowHeight, float fontPixels)
{
    const float height = float(std::max(windowHeight, 0));
    return int(std::floor(std::min(std::clamp(height * 0.26f, fontPixels * 9.0f, fontPixels * 18.0f), height * 0.4f)));
}

WindowLayout layoutWindow(Extent framebuffer, int panelWidth, Extent image, float fontPixels)
{
    WindowLayout layout;
    if (framebuffer.width <= 0 || framebuffer.height <= 0)
        return layout;
    const int panel = std::clamp(panelWidth, 0, int(float(framebuffer.width) * kMaxPanelShare));
    layout.panel = {0, 0, panel, framebuffer.height};
    const int strip = labStripHeight(framebuffer.height, fontPixels);
    // The table needs the width for its columns; the plot, a square's worth of it.
    const int right = framebuffer.width - panel;
    const int table = std::max(int(float(right) * 0.58f), right - int(float(strip) * 1.6f));
    layout.timings = {panel, framebuffer.height - strip, table, strip};
    layout.plot = {panel + table, framebuffer.height - strip, right - table, strip};

    const PixelRect area{panel + kLayoutMargin, kLayoutMargin, framebuffer.width - panel - 2 * kLayoutMargin,
                         framebuffer.height - strip - 2 * kLayoutMargin};
    if (area.empty() || image.width <= 0 || image.height <= 0)
        return layout;
    const double scale = std::min(double(area.width) / image.width, double(area.height) / image.height);
    // Rounded, then held inside the area: the letterbox never spills under the panel or off the window.
    const int width = std::clamp(int(std::lround(image.width * scale)), 1, area.width);
    const int height = std::clamp(int(std::lround(image.height * scale)), 1, area.height);
    layout.image = {area.x + (area.width - width) / 2, area.y + (area.height - height) / 2, width, height};
    return layout;
}

WindowSize defaultWindowSize(Extent image, int panelWidth, float fontPixels)
{
    const auto side = [](long long pixels, int minimum) {
        return int(std::clamp<long long>(pixels, minimum, kMaxWindowSide));
    };
    // The strip's share grows with the window: the first height whose image area holds the image.
    int height = std::clamp(2 * kLayoutMargin + image.height, 1, kMaxWindowSide);
    while (height < kMaxWindowSide && height - labStripHeight(height, fontPixels) - 2 * kLayoutMargin < image.height)
        ++height;
    return {side(panelWidth + 2ll * kLayoutMargin + image.width, kMinDefaultWindow.width),
            side(height, kMinDefaultWindow.height)};
}
} // namespace rt::gpu::gui
