// The value parsers both apps' flags and --actions use: whole values only.
#include <gtest/gtest.h>

#include "Cli/ValueParsing.h"

namespace rt
{
namespace
{
TEST(ValueParsing, IntegersAreWholeDecimalNumbers)
{
    EXPECT_EQ(parseInteger("42"), 42);
    EXPECT_EQ(parseInteger("-7"), -7);
    EXPECT_EQ(parseInteger("4294967295"), 4294967295ll);
    for (const char* bad : {"", "4x", " 4", "+4", "4.0", "x", "99999999999999999999"})
        EXPECT_FALSE(parseInteger(bad)) << bad;
}

TEST(ValueParsing, RealsAreWholeNumbers)
{
    EXPECT_EQ(parseReal("1.5"), 1.5f);
    EXPECT_EQ(parseReal("-2"), -2.0f);
    EXPECT_EQ(parseReal("1e2"), 100.0f);
    for (const char* bad : {"", "1.5f", " 1", "one", "1,5"})
        EXPECT_FALSE(parseReal(bad)) << bad;
}

TEST(ValueParsing, OnOffAndSizes)
{
    EXPECT_EQ(parseOnOff("on"), true);
    EXPECT_EQ(parseOnOff("off"), false);
    EXPECT_FALSE(parseOnOff("yes"));
    EXPECT_FALSE(parseOnOff("On"));
    EXPECT_EQ(parseSize("1280x800"), (std::pair<long long, long long>{1280, 800}));
    EXPECT_EQ(parseSize("0x0"), (std::pair<long long, long long>{0, 0}));
    for (const char* bad : {"1280", "1280x", "x800", "1280*800", "12x8x4", "axb"})
        EXPECT_FALSE(parseSize(bad)) << bad;
}

TEST(ValueParsing, CommaListsKeepEmptyPartsButNotATrailingComma)
{
    using Parts = std::vector<std::string>;
    EXPECT_EQ(splitCommas("10,50,100"), (Parts{"10", "50", "100"}));
    EXPECT_EQ(splitCommas("a,,b"), (Parts{"a", "", "b"}));
    EXPECT_EQ(splitCommas(",a"), (Parts{"", "a"}));
    EXPECT_EQ(splitCommas("a,b,"), (Parts{"a", "b"}));
    EXPECT_EQ(splitCommas("solo"), (Parts{"solo"}));
    EXPECT_TRUE(splitCommas("").empty());
}
} // namespace
} // namespace rt
