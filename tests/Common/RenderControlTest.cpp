// What engines and watchers read from RenderControl: progress, cancel, and the preview throttle.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "Render/RenderControl.h"

namespace rt
{
namespace
{
TEST(RenderControl, ProgressCountsUnits)
{
    RenderControl c;
    EXPECT_EQ(c.fraction(), 0.0);
    EXPECT_LT(c.etaSeconds(), 0.0);
    c.begin(4);
    c.advance();
    EXPECT_EQ(c.fraction(), 0.25);
    EXPECT_FALSE(c.cancelRequested());
    c.requestCancel();
    EXPECT_TRUE(c.cancelRequested());
}

TEST(RenderControl, PreviewsAreDueEveryTimeByDefault)
{
    RenderControl c;
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(c.previewDue()) << i;
}

TEST(RenderControl, PreviewsAreDueOncePerInterval)
{
    RenderControl c;
    c.setPreviewInterval(std::chrono::hours(1));
    EXPECT_TRUE(c.previewDue()); // the first one
    EXPECT_FALSE(c.previewDue());
    EXPECT_FALSE(c.previewDue());
    c.setPreviewInterval(std::chrono::nanoseconds(0));
    EXPECT_TRUE(c.previewDue());
}
TEST(RenderControl, ATimeLimitCancelsFromTheRendersStart)
{
    RenderControl c;
    c.setTimeLimit(std::chrono::milliseconds(1));
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    EXPECT_FALSE(c.cancelRequested()) << "the limit counts from begin(), not from when it was set";
    c.begin(10);
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    EXPECT_TRUE(c.timeLimitPassed());
    EXPECT_TRUE(c.cancelRequested());

    RenderControl unlimited;
    unlimited.begin(10);
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    EXPECT_FALSE(unlimited.cancelRequested());
    EXPECT_FALSE(unlimited.timeLimitPassed());
}
} // namespace
} // namespace rt
