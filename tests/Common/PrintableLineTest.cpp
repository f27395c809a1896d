// What an error message may quote from outside reaches the terminal escaped (Common/PrintableLine.h): controls of
// every kind and bytes that are not well-formed UTF-8 as \xNN, text in any script as it is.
#include <gtest/gtest.h>

#include <string>

#include "PrintableLine.h"

namespace rt
{
namespace
{
TEST(PrintableLine, KeepsTextLineBreaksAndTabs)
{
    EXPECT_EQ(printableLine("scene 'a b'\n\tgpu 0"), "scene 'a b'\n\tgpu 0");
    EXPECT_EQ(printableLine(""), "");
}

TEST(PrintableLine, EscapesTheControlsOfC0AndDel)
{
    EXPECT_EQ(printableLine("a\x1b[2Jb"), "a\\x1b[2Jb");
    EXPECT_EQ(printableLine(std::string("\0\r\x7f", 3)), "\\x00\\x0d\\x7f");
}

TEST(PrintableLine, KeepsWellFormedUtf8OfEveryLength)
{
    const std::string text = "\xc3\xa9t\xc3\xa9 \xe2\x82\xac \xe6\x97\xa5 \xf0\x9f\x8e\xa8 \xc2\xa0"; // été € 日 🎨 nbsp
    EXPECT_EQ(printableLine(text), text);
    EXPECT_EQ(printableLine("\xf4\x8f\xbf\xbf"), "\xf4\x8f\xbf\xbf"); // U+10FFFF, the last code point
    // The ends of the ranges the table narrows: U+0800, U+D7FF, U+E000, U+10000.
    for (const char* kept : {"\xe0\xa0\x80", "\xed\x9f\xbf", "\xee\x80\x80", "\xf0\x90\x80\x80"})
        EXPECT_EQ(printableLine(kept), kept);
}

TEST(PrintableLine, EscapesTheC1ControlsRawOrEncoded)
{
    EXPECT_EQ(printableLine("a\x9b" "2Jb"), "a\\x9b2Jb"); // CSI as one byte (not UTF-8)
    EXPECT_EQ(printableLine("a\xc2\x9b" "2Jb"), "a\\xc2\\x9b2Jb"); // U+009B, CSI, as UTF-8 encodes it
    EXPECT_EQ(printableLine("\xc2\x80\xc2\x9f"), "\\xc2\\x80\\xc2\\x9f");
}

TEST(PrintableLine, EscapesBytesThatAreNotWellFormedUtf8)
{
    EXPECT_EQ(printableLine("\xc0\xaf"), "\\xc0\\xaf"); // an overlong '/'
    EXPECT_EQ(printableLine("\xe0\x80\xaf"), "\\xe0\\x80\\xaf"); // another
    EXPECT_EQ(printableLine("\xed\xa0\x80"), "\\xed\\xa0\\x80"); // a surrogate
    EXPECT_EQ(printableLine("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80"); // past U+10FFFF
    EXPECT_EQ(printableLine("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(printableLine("ab\xe2\x82"), "ab\\xe2\\x82"); // cut short at the end
    EXPECT_EQ(printableLine("\xe2\x82x"), "\\xe2\\x82x"); // cut short by ASCII
    EXPECT_EQ(printableLine("\x80" "a"), "\\x80a"); // a continuation byte alone
    EXPECT_EQ(printableLine("\xf0\x8f\xbf\xbf"), "\\xf0\\x8f\\xbf\\xbf"); // an overlong U+FFFF
    EXPECT_EQ(printableLine("\xc1\xbf"), "\\xc1\\xbf"); // an overlong lead
    EXPECT_EQ(printableLine("\xf5\x80\x80\x80"), "\\xf5\\x80\\x80\\x80"); // a lead past U+10FFFF
    EXPECT_EQ(printableLine("\xf0\x9f\x8e"), "\\xf0\\x9f\\x8e"); // four bytes cut short at the end
    EXPECT_EQ(printableLine("\xe2\xc3\xa9"), "\\xe2\xc3\xa9"); // the next character read after a bad lead
}
} // namespace
} // namespace rt
