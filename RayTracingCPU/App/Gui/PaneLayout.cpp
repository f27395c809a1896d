#include "App/Gui/PaneLayout.h"

#include <algorithm>
#include <cmath>

namespace rt::gui
{
namespace
{
float panelWidth(float width, float font) { return std::min(std::max(font * 25.0f, width * 0.28f), width * 0.5f); }

float timingsHeight(float height, float font)
{
    return std::min(std::clamp(height * 0.26f, font * 9.0f, font * 18.0f), height * 0.4f);
}

/// Room the image pane takes around its image: ImGui's window padding (8 each side) and the title bar (the
/// font and its frame padding).
float paneFrameWidth() { return 16.0f; }
float paneFrameHeight(float font) { return 16.0f + font + 6.0f; }
} // namespace

PaneLayout layoutPanes(float width, float height, float fontPixels)
{
    const float panel = panelWidth(width, fontPixels);
    const float timings = timingsHeight(height, fontPixels);
    // The table needs the width for its columns; the plot, a square's worth of it.
    const float table = std::floor(std::max((width - panel) * 0.58f, width - panel - timings * 1.6f));
    return {.panel = {0.0f, 0.0f, panel, height},
            .image = {panel, 0.0f, width - panel, height - timings},
            .timings = {panel, height - timings, table, timings},
            .plot = {panel + table, height - timings, width - panel - table, timings}};
}

WindowSize defaultWindowSize(int imageWidth, int imageHeight, float fontPixels)
{
    // The smallest width and height whose image pane holds the image, found by stepping up: each pane's
    // share grows with the window, so the first size that fits is the answer.
    const float needWidth = float(imageWidth) + paneFrameWidth();
    const float needHeight = float(imageHeight) + paneFrameHeight(fontPixels);
    float width = needWidth;
    while (width < kMaxWindowSide && layoutPanes(width, 1.0f, fontPixels).image.width < needWidth)
        width += 1.0f;
    float height = needHeight;
    while (height < kMaxWindowSide && layoutPanes(1.0f, height, fontPixels).image.height < needHeight)
        height += 1.0f;
    return {std::clamp(int(std::ceil(width)), kMinDefaultWindow.width, kMaxWindowSide),
            std::clamp(int(std::ceil(height)), kMinDefaultWindow.height, kMaxWindowSide)};
}
} // namespace rt::gui
