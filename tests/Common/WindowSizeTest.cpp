// --window-size, both windows' one parser: sizes in range pass, anything else is one UsageError that names
// the flag, the text as written and, for a size out of range, the bound.
#include <gtest/gtest.h>

#include "Cli/WindowSize.h"
#include "Error.h"

namespace rt
{
namespace
{
std::string errorOf(const std::string& text)
{
    try
    {
        parseWindowSize(text);
    }
    catch (const UsageError& e)
    {
        return e.what();
    }
    return {};
}

TEST(WindowSize, SizesInRangeParse)
{
    EXPECT_EQ(parseWindowSize("1280x800"), (WindowSize{1280, 800}));
    EXPECT_EQ(parseWindowSize("160x160"), (WindowSize{kMinWindowSide, kMinWindowSide}));
    EXPECT_EQ(parseWindowSize("16384x16384"), (WindowSize{kMaxWindowSide, kMaxWindowSide}));
}

TEST(WindowSize, MalformedSizesNameTheFlagAndTheText)
{
    for (const char* bad : {"abc", "1280", "1280x", "x800", "1280*800", "640x480x2", "1e3x800", ""})
    {
        const std::string error = errorOf(bad);
        EXPECT_NE(error.find("--window-size"), std::string::npos) << bad << ": " << error;
        EXPECT_NE(error.find(std::string("'") + bad + "'"), std::string::npos) << error;
        EXPECT_NE(error.find("WIDTHxHEIGHT"), std::string::npos) << error;
    }
}

TEST(WindowSize, SizesOutOfRangeNameTheBound)
{
    for (const auto& [bad, side] : {std::pair{"0x0", "width"}, {"100000x100000", "width"}, {"800x100", "height"},
                                    {"800x16385", "height"}, {"159x600", "width"}})
    {
        const std::string error = errorOf(bad);
        EXPECT_NE(error.find(std::string("--window-size ") + bad), std::string::npos) << error;
        EXPECT_NE(error.find(std::string("the ") + side + " must be from 160 to 16384 pixels"), std::string::npos)
            << error;
    }
}

TEST(WindowSize, FitCutsToTheWorkAreaAndKeepsTheMinimum)
{
    EXPECT_EQ(fitWindowSize({2000, 1500}, {1280, 800}), (WindowSize{1280, 800}));
    EXPECT_EQ(fitWindowSize({900, 700}, {1280, 800}), (WindowSize{900, 700}));
    EXPECT_EQ(fitWindowSize({2000, 1500}, {0, 0}), (WindowSize{2000, 1500})) << "unknown work area: nothing cut";
    EXPECT_EQ(fitWindowSize({10, 10}, {1280, 800}), (WindowSize{kMinWindowSide, kMinWindowSide}));
}
} // namespace
} // namespace rt
