// The memory check the command line and both windows make before a render (Render/MemoryBudget.h): the estimate
// grows with the pixels and the scene, a render that does not fit is refused with its figures, and a window
// that replaces the render it holds counts what that render frees (a 4K render asking for another 4K was
// refused on a machine with room for one).
#include <gtest/gtest.h>

#include "Error.h"
#include "Render/MemoryBudget.h"

namespace rt
{
namespace
{
TEST(MemoryBudget, TheEstimateGrowsWithThePixelsTheSceneAndRestir)
{
    EXPECT_EQ(renderBytes(1000, 0), 1000 * kRenderBytesPerPixel);
    EXPECT_EQ(renderBytes(0, 10), 10 * kSceneBytesPerObject);
    RenderSettings s;
    s.width = 400;
    s.aspect = 2.0f;
    EXPECT_EQ(renderBytes(s, 5), renderBytes(400 * 200, 5));
    s.estimator = Estimator::RestirDi;
    EXPECT_EQ(renderBytes(s, 5), renderBytes(400 * 200, 5) + 400 * 200 * kRestirBytesPerPixel);
}

TEST(MemoryBudget, ARenderThatDoesNotFitIsRefusedWithItsFigures)
{
    EXPECT_NO_THROW(checkMemory(100, "a small render", 1000));
    EXPECT_NO_THROW(checkMemory(1ull << 50, "anything", 0)) << "nothing is refused when the memory is unknown";
    try
    {
        checkMemory(3ull << 30, "a 9000x9000 render of many-lights", 1ull << 30);
        FAIL() << "not refused";
    }
    catch (const UsageError& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("a 9000x9000 render of many-lights needs about"), std::string::npos) << what;
        EXPECT_NE(what.find("available"), std::string::npos) << what;
    }
}

TEST(MemoryBudget, AReplacedRenderCountsWhatItFrees)
{
    const std::uint64_t available = availableMemoryBytes();
    if (available == 0)
        GTEST_SKIP() << "this machine does not say how much memory it has";
    const std::uint64_t held = 3ull << 30;
    const std::uint64_t replacing = availableMemoryBytesReplacing(held);
    // MemAvailable moves between two reads: a margin of 256 MB.
    EXPECT_NEAR(double(replacing), double(available + held), double(256ull << 20));
    EXPECT_NO_THROW(checkMemory(available + held / 2, "a render as large as the one it replaces", replacing));
}
} // namespace
} // namespace rt
