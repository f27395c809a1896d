// The window's layout (WindowLayout.h) at every size that matters: the panel is a column at the left, the
// full height of the window; the timings table and the plot share a strip along the bottom right of it; the
// image is letterboxed above the strip, its aspect kept, as large as fits, centred, never under the panel or
// the strip and never off the window. Issue 13 item 7: at 120 x 120 the panel covered the image, at 600 x 600
// it hid half of it. Issue 38: the table and the plot beside the image at 1280x800 and 1920x1080.
#include <gtest/gtest.h>

#include <cmath>

#include "App/Gui/Panel.h"
#include "App/Gui/WindowLayout.h"

namespace rt::gpu::gui
{
namespace
{
constexpr float kFont = 15.0f;

void expectLetterboxed(Extent window, int panelWidth, Extent image)
{
    SCOPED_TRACE(::testing::Message() << "window " << window.width << "x" << window.height << ", panel "
                                      << panelWidth << ", image " << image.width << "x" << image.height);
    const WindowLayout layout = layoutWindow(window, panelWidth, image, kFont);
    EXPECT_EQ(layout.panel.x, 0);
    EXPECT_EQ(layout.panel.y, 0);
    EXPECT_EQ(layout.panel.height, window.height) << "a full-height column";
    EXPECT_EQ(layout.panel.width, std::min(panelWidth, int(window.width * kMaxPanelShare)));
    ASSERT_FALSE(layout.image.empty());
    EXPECT_FALSE(overlaps(layout.panel, layout.image)) << "never under the panel";
    EXPECT_GE(layout.image.x, layout.panel.width + kLayoutMargin);
    EXPECT_GE(layout.image.y, kLayoutMargin);
    EXPECT_LE(layout.image.x + layout.image.width, window.width - kLayoutMargin);
    const int strip = labStripHeight(window.height, kFont);
    EXPECT_LE(layout.image.y + layout.image.height, window.height - strip - kLayoutMargin);
    // The strip: the table then the plot, side by side, right of the panel, along the bottom, filling it.
    for (const PixelRect& pane : {layout.timings, layout.plot})
    {
        EXPECT_EQ(pane.y, window.height - strip);
        EXPECT_EQ(pane.height, strip);
        EXPECT_FALSE(overlaps(pane, layout.panel));
        EXPECT_FALSE(overlaps(pane, layout.image));
    }
    EXPECT_EQ(layout.timings.x, layout.panel.width);
    EXPECT_EQ(layout.plot.x, layout.timings.x + layout.timings.width);
    EXPECT_EQ(layout.plot.x + layout.plot.width, window.width);
    EXPECT_GE(layout.timings.width, layout.plot.width) << "the table's columns need the width";
    // The aspect kept to the rounding of one pixel.
    EXPECT_NEAR(double(layout.image.width) * image.height, double(layout.image.height) * image.width,
                double(std::max(image.width, image.height)));
    // As large as fits: it touches the free area's sides on one axis, and sits in the middle on the other.
    const int areaWidth = window.width - layout.panel.width - 2 * kLayoutMargin;
    const int areaHeight = window.height - strip - 2 * kLayoutMargin;
    EXPECT_TRUE(layout.image.width >= areaWidth - 1 || layout.image.height >= areaHeight - 1);
    const int left = layout.image.x - (layout.panel.width + kLayoutMargin);
    const int right = areaWidth - layout.image.width - left;
    EXPECT_LE(std::abs(left - right), 1);
    const int top = layout.image.y - kLayoutMargin;
    EXPECT_LE(std::abs(top - (areaHeight - layout.image.height - top)), 1);
}

TEST(WindowLayout, ImageIsLetterboxedBesideThePanelAtAnySize)
{
    for (const Extent window : {Extent{800, 600}, Extent{916, 616}, Extent{640, 400}, Extent{480, 300},
                                Extent{1920, 1080}, Extent{160, 160}, Extent{3000, 200}, Extent{200, 3000}})
        for (const Extent image : {Extent{120, 120}, Extent{600, 600}, Extent{640, 400}, Extent{1, 1},
                                   Extent{4000, 10}, Extent{10, 4000}, Extent{16384, 16384}})
            for (const int panel : {300, 690, 0})
                expectLetterboxed(window, panel, image);
}

TEST(WindowLayout, TheStripHoldsNineToEighteenLinesAndAtMostFortyPercent)
{
    EXPECT_EQ(labStripHeight(800, kFont), 208) << "a quarter and a bit of 800";
    EXPECT_EQ(labStripHeight(1080, kFont), 270) << "18 lines of 15 px at most";
    EXPECT_EQ(labStripHeight(400, kFont), 135) << "9 lines of 15 px at least";
    EXPECT_EQ(labStripHeight(200, kFont), 80) << "but never more than 40 %";
    EXPECT_EQ(labStripHeight(0, kFont), 0);
}

TEST(WindowLayout, TheDefaultWindowShowsPanelAndImageOnePixelPerPixel)
{
    for (const Extent image : {Extent{120, 120}, Extent{600, 600}, Extent{640, 400}, Extent{1200, 700}})
    {
        const WindowSize size = defaultWindowSize(image, int(kPanelWidth), kFont);
        EXPECT_GE(size.width, kMinDefaultWindow.width);
        EXPECT_GE(size.height, kMinDefaultWindow.height);
        const WindowLayout layout = layoutWindow({size.width, size.height}, int(kPanelWidth), image, kFont);
        EXPECT_EQ(layout.panel.width, int(kPanelWidth));
        EXPECT_FALSE(overlaps(layout.panel, layout.image));
        // Exactly 1:1 where the image fills the window; a small image is magnified in the minimum window.
        EXPECT_GE(layout.image.width, image.width) << image.width << "x" << image.height;
        EXPECT_GE(layout.image.height, image.height);
    }
    // The strip's height grows with the window's: the default is the first height whose image area holds 600 px.
    const WindowSize large = defaultWindowSize({800, 600}, 300, kFont);
    EXPECT_EQ(large.width, 1116);
    EXPECT_EQ(large.height - labStripHeight(large.height, kFont) - 2 * kLayoutMargin, 600);
    EXPECT_EQ(defaultWindowSize({120, 120}, 300, kFont), kMinDefaultWindow);
    EXPECT_EQ(defaultWindowSize({60000, 60000}, 300, kFont), (WindowSize{kMaxWindowSide, kMaxWindowSide}));
}

TEST(WindowLayout, NothingIsPlacedInAnEmptyWindowOrForAnEmptyImage)
{
    EXPECT_TRUE(layoutWindow({0, 0}, 300, {600, 600}, kFont).image.empty());
    EXPECT_TRUE(layoutWindow({0, 0}, 300, {600, 600}, kFont).panel.empty());
    EXPECT_TRUE(layoutWindow({800, 600}, 300, {0, 0}, kFont).image.empty());
    EXPECT_FALSE(layoutWindow({800, 600}, 300, {0, 0}, kFont).panel.empty());
}

TEST(WindowLayout, OverlapNeedsASharedPixel)
{
    EXPECT_TRUE(overlaps({0, 0, 10, 10}, {9, 9, 5, 5}));
    EXPECT_FALSE(overlaps({0, 0, 10, 10}, {10, 0, 5, 5})) << "touching edges share no pixel";
    EXPECT_FALSE(overlaps({0, 0, 10, 10}, {3, 3, 0, 5})) << "an empty rectangle overlaps nothing";
}
} // namespace
} // namespace rt::gpu::gui
