// The CPU window's pure pieces, without a window: the frame pacer (a render is not disturbed by frames
// nobody asked for; input is answered at once and counted) and the panes' layout with its inverse, the
// default window size (issue 13 items 7 and 8).
#include <gtest/gtest.h>

#include "App/Gui/FramePacer.h"
#include "App/Gui/PaneLayout.h"

namespace rt::gui
{
namespace
{
using Frame = FramePacer::Frame;
using Clock = FramePacer::Clock;

Clock::time_point at(double seconds)
{
    return Clock::time_point{} + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

TEST(FramePacer, DuringARenderOnlyThePaceTheRenderThreadAndInputDrawFrames)
{
    FramePacer pacer;
    ASSERT_EQ(pacer.next(true, false, 0, false, at(100.0)), Frame::Paced);
    EXPECT_EQ(pacer.next(true, false, 0, false, at(100.1)), Frame::Skip) << "the pointer moved: no frame";
    EXPECT_NEAR(pacer.timeout(true, false, at(100.1)), FramePacer::kRenderingInterval - 0.1, 1e-9);
    EXPECT_EQ(pacer.next(true, false, 0, false, at(100.5)), Frame::Paced);
    EXPECT_EQ(pacer.next(true, false, 0, true, at(100.6)), Frame::News) << "a render ended";
    EXPECT_EQ(pacer.next(true, false, 3, false, at(100.7)), Frame::Input) << "a click is answered at once";
    EXPECT_EQ(pacer.next(true, false, 3, false, at(100.8)), Frame::Skip) << "the same input counts once";
}

TEST(FramePacer, AHeldCameraKeyIsInputAtEveryFrameWhileARenderRuns)
{
    // A held key sends no events (or X's repeats): paced frames half a second apart moved the camera in steps,
    // at a fifth of its speed (the move is held to 0.1 s a frame).
    FramePacer pacer;
    ASSERT_EQ(pacer.next(true, false, 0, false, at(200.0)), Frame::Paced);
    EXPECT_NEAR(pacer.timeout(true, false, at(200.0), true), FramePacer::kHeldKeyInterval, 1e-9);
    EXPECT_EQ(pacer.next(true, false, 0, false, at(200.005), true), Frame::Skip) << "not before the interval";
    EXPECT_EQ(pacer.next(true, false, 0, false, at(200.02), true), Frame::Input) << "the held key is input";
    EXPECT_EQ(pacer.next(true, false, 0, false, at(200.04), true), Frame::Input);
    EXPECT_EQ(pacer.next(true, false, 0, false, at(200.06)), Frame::Skip) << "released: paced again";
}

TEST(FramePacer, IdleAnyEventDrawsAndTheWaitIsShort)
{
    FramePacer pacer;
    EXPECT_EQ(pacer.next(false, false, 0, false, at(10.0)), Frame::News);
    EXPECT_EQ(pacer.next(false, false, 0, false, at(10.01)), Frame::News);
    EXPECT_DOUBLE_EQ(pacer.timeout(false, false, at(10.01)), FramePacer::kIdleInterval);
    EXPECT_DOUBLE_EQ(pacer.timeout(false, true, at(10.01)), FramePacer::kAutomatedIdleInterval);
    EXPECT_LE(pacer.timeout(true, false, at(11.0)), FramePacer::kRenderingInterval);
    EXPECT_GT(pacer.timeout(true, false, at(11.0)), 0.0);
}

/// The image pane's room for the image: ImGui's padding and the title bar taken off.
bool holds(const PaneLayout& panes, int width, int height, float font)
{
    return panes.image.width - 16.0f >= float(width) && panes.image.height - (16.0f + font + 6.0f) >= float(height);
}

TEST(PaneLayout, TheDefaultWindowHoldsTheImageOnePixelPerPixel)
{
    for (const float font : {13.0f, 16.0f, 24.0f})
        for (const auto& [w, h] : {std::pair{120, 120}, {600, 600}, {1200, 700}, {64, 900}, {2000, 100}})
        {
            const WindowSize size = defaultWindowSize(w, h, font);
            const PaneLayout panes = layoutPanes(float(size.width), float(size.height), font);
            EXPECT_TRUE(holds(panes, w, h, font)) << w << "x" << h << " at " << font << " px";
            EXPECT_GE(size.width, kMinDefaultWindow.width);
            EXPECT_GE(size.height, kMinDefaultWindow.height);
            // The smallest such window: a pixel less on a side that is above the minimum no longer holds it.
            if (size.width > kMinDefaultWindow.width)
            {
                EXPECT_FALSE(holds(layoutPanes(float(size.width - 1), float(size.height), font), w, h, font));
            }
            if (size.height > kMinDefaultWindow.height)
            {
                EXPECT_FALSE(holds(layoutPanes(float(size.width), float(size.height - 1), font), w, h, font));
            }
        }
    EXPECT_EQ(defaultWindowSize(120, 120, 16.0f), kMinDefaultWindow);
}

TEST(PaneLayout, PanesTileTheWindow)
{
    for (const auto& [w, h] : {std::pair{1280.0f, 800.0f}, {1024.0f, 720.0f}, {300.0f, 200.0f}, {3000.0f, 2000.0f}})
    {
        const PaneLayout p = layoutPanes(w, h, 16.0f);
        EXPECT_FLOAT_EQ(p.panel.x, 0.0f);
        EXPECT_FLOAT_EQ(p.panel.height, h) << "a full-height column";
        EXPECT_FLOAT_EQ(p.image.x, p.panel.width) << "beside the panel, never under it";
        EXPECT_FLOAT_EQ(p.image.x + p.image.width, w);
        EXPECT_FLOAT_EQ(p.timings.y, p.image.height);
        EXPECT_FLOAT_EQ(p.timings.y + p.timings.height, h);
        EXPECT_FLOAT_EQ(p.timings.x, p.image.x);
        EXPECT_FLOAT_EQ(p.plot.x, p.timings.x + p.timings.width) << "the plot right of the table";
        EXPECT_FLOAT_EQ(p.plot.x + p.plot.width, w);
        EXPECT_FLOAT_EQ(p.plot.y, p.timings.y);
        EXPECT_FLOAT_EQ(p.plot.height, p.timings.height);
        EXPECT_GE(p.timings.width, p.plot.width) << "the table's columns need the room";
        EXPECT_LE(p.panel.width, w * 0.5f);
    }
}
} // namespace
} // namespace rt::gui
