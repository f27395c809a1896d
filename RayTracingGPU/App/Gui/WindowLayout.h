// Where the window puts things, in framebuffer pixels: the settings panel is a column at the left, the full
// height of the window; right of it, a strip along the bottom holds the timings table and the convergence plot
// beside it (as the CPU window's panes), and the image is letterboxed above the strip: as large as fits, its
// aspect kept, centred, never under the panel or the strip, at any image and window size. Pure arithmetic, so a unit test covers every size;
// the window writes the rectangles it drew with to --state-json for the window tests.
#pragma once

#include "App/Gui/WindowState.h"
#include "Cli/WindowSize.h"

namespace rt::gpu::gui
{
struct PixelRect
{
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;

    bool empty() const { return width <= 0 || height <= 0; }
    bool operator==(const PixelRect&) const = default;
};

/// True when the two rectangles share a pixel.
bool overlaps(const PixelRect& a, const PixelRect& b);

struct WindowLayout
{
    PixelRect panel; // the settings column
    PixelRect image; // where the ray-traced image (or the preview) is drawn; empty when there is no room
    PixelRect timings; // the timings table: the strip's left part
    PixelRect plot; // the convergence plot, right of the table
};

/// Pixels between the panel, the image and the window's edges.
inline constexpr int kLayoutMargin = 8;
/// The panel takes at most this share of the window's width (a large font or a small window), so that the
/// image keeps the rest; its widgets then scroll.
inline constexpr float kMaxPanelShare = 0.5f;
/// The smallest window the default size gives: the panel's sections need the height, and a small image is
/// shown magnified.
inline constexpr WindowSize kMinDefaultWindow{1024, 720};

/// Height of the table and plot's strip in a window `windowHeight` pixels high whose font is `fontPixels` high:
/// a quarter of the window, but room for 9 to 18 lines of the font, and never more than 40 % of it.
int labStripHeight(int windowHeight, float fontPixels);

/// The layout of a `framebuffer`-sized window whose panel wants `panelWidth` pixels and whose font is
/// `fontPixels` high, showing an `image`.
WindowLayout layoutWindow(Extent framebuffer, int panelWidth, Extent image, float fontPixels);

/// A window that shows the panel at `panelWidth` and the image at one window pixel per image pixel above the
/// strip, at least kMinDefaultWindow (the caller fits it to the monitor: fitWindowSize).
WindowSize defaultWindowSize(Extent image, int panelWidth, float fontPixels);
} // namespace rt::gpu::gui
