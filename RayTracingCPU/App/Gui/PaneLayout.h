// The window's four panes, in ImGui's coordinates: the settings panel a full-height column at the left, the
// image pane right of it (the image letterboxed inside: ImageView), the timings table below the image and the
// convergence plot right of the table. Sized
// by the font first, the window second, so that a larger font widens the panel and a window too small for
// that squeezes every pane. Pure arithmetic, and its inverse for the default window size.
#pragma once

#include "Cli/WindowSize.h"

namespace rt::gui
{
struct PaneRect
{
    float x = 0.0f;
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
};

struct PaneLayout
{
    PaneRect panel;
    PaneRect image; // the image pane, title bar included
    PaneRect timings;
    PaneRect plot;
};

/// The panes of a `width` x `height` window whose font is `fontPixels` high.
PaneLayout layoutPanes(float width, float height, float fontPixels);

/// A window whose image pane shows an `imageWidth` x `imageHeight` image at one pixel per image pixel beside
/// the panel and above the timings, at least kMinDefaultWindow (the caller fits it to the monitor).
WindowSize defaultWindowSize(int imageWidth, int imageHeight, float fontPixels);

/// The smallest window the default size gives: the panel's sections need the height, and a small image is
/// shown magnified.
inline constexpr WindowSize kMinDefaultWindow{1024, 720};
} // namespace rt::gui
