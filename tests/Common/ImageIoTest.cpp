// Image/ImageIO.h: PFM is lossless and laid out as the format says, PNG holds the sRGB encoding of the
// clamped linear image, and every writer either leaves the finished file or nothing (no .partial), with
// errors of the right category.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <stb_image.h>

#include "Error.h"
#include "Image/ImageIO.h"
#include "Support/FileContents.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// 7 x 3 (not square, odd sizes) with values a lossy or transposing writer would change: negatives, huge and
/// subnormal magnitudes, -0, infinities, and every pixel different.
Image awkwardImage()
{
    Image image(7, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x)
            image.at(x, y) = vec3(float(x) + 0.1f * float(y), -float(y) * 1e-3f, std::ldexp(1.0f, x * 20 - 70));
    image.at(0, 0) = vec3(-0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max());
    image.at(6, 2) = vec3(std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 1.0f / 3.0f);
    return image;
}

bool bitEqual(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

TEST(Pfm, RoundTripIsBitExact)
{
    const test::ScratchDir dir;
    const Image image = awkwardImage();
    writePfm(dir / "image.pfm", image);
    const Image back = readPfm(dir / "image.pfm");
    ASSERT_EQ(back.width(), image.width());
    ASSERT_EQ(back.height(), image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            EXPECT_TRUE(bitEqual(back.at(x, y), image.at(x, y))) << "pixel (" << x << ", " << y << ")";
}

TEST(Pfm, FollowsTheFormatLittleEndianBottomRowFirst)
{
    // "PF", width height, a negative scale for little-endian data, then rows from the bottom of the image.
    const test::ScratchDir dir;
    const Image image = awkwardImage();
    writePfm(dir / "image.pfm", image);
    const std::string bytes = test::fileContents(dir / "image.pfm");
    const std::string header = "PF\n7 3\n-1.0\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    ASSERT_EQ(bytes.size(), header.size() + 7 * 3 * 12);
    static_assert(std::endian::native == std::endian::little, "the check below reads the floats natively");
    vec3 first;
    std::memcpy(&first, bytes.data() + header.size(), sizeof(vec3));
    EXPECT_TRUE(bitEqual(first, image.at(0, 2))) << "the file must start with the bottom row";
}

TEST(Pfm, ReadsBigEndianFiles)
{
    // A positive scale declares big-endian floats (other tools write them).
    const test::ScratchDir dir;
    std::string file = "PF\n2 1\n1.0\n";
    for (float v : {1.0f, 2.0f, 3.0f, -4.5f, 0.25f, 1e20f})
    {
        const std::uint32_t b = std::bit_cast<std::uint32_t>(v);
        const std::uint32_t bits = (b >> 24) | ((b >> 8) & 0xFF00u) | ((b << 8) & 0xFF0000u) | (b << 24);
        file.append(reinterpret_cast<const char*>(&bits), 4);
    }
    const Image image = readPfm(dir.write("big.pfm", file));
    ASSERT_EQ(image.width(), 2);
    EXPECT_EQ(image.at(0, 0), vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(image.at(1, 0), vec3(-4.5f, 0.25f, 1e20f));
}

TEST(Pfm, RejectsTruncatedAndForeignFiles)
{
    const test::ScratchDir dir;
    EXPECT_THROW(readPfm(dir.write("short.pfm", "PF\n2 2\n-1.0\n0123456789")), AssetError);
    EXPECT_THROW(readPfm(dir.write("grey.pfm", "Pf\n1 1\n-1.0\n0123")), AssetError);
    EXPECT_THROW(readPfm(dir.write("text.pfm", "hello")), AssetError);
    EXPECT_THROW(readPfm(dir / "missing.pfm"), AssetError);
}

TEST(WriteImage, AnUnknownExtensionIsAUsageErrorAndWritesNothing)
{
    const test::ScratchDir dir;
    for (const char* name : {"image.jpg", "image.tiff", "image"})
    {
        EXPECT_THROW(writeImage(dir / name, Image(2, 2)), UsageError) << name;
    }
    EXPECT_TRUE(dir.entries().empty());
    EXPECT_NO_THROW(writeImage(dir / "image.PNG", Image(2, 2))) << "the extension's case does not matter";
}

TEST(WriteImage, AMissingFolderIsAnOutputErrorAndLeavesNoFile)
{
    const test::ScratchDir dir;
    for (const char* name : {"image.png", "image.pfm"})
    {
        const auto path = dir / "no-such-folder" / name;
        try
        {
            writeImage(path, Image(2, 2));
            ADD_FAILURE() << "no OutputError for " << path;
        }
        catch (const OutputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(dir.entries().empty()) << "a file or folder was created";
}

TEST(WriteImage, ReplacesAnExistingFileWholeAndLeavesNoPartial)
{
    const test::ScratchDir dir;
    dir.write("image.pfm", std::string(10'000, 'x'));
    Image image(1, 1);
    image.at(0, 0) = vec3(0.5f);
    writeImage(dir / "image.pfm", image);
    EXPECT_EQ(readPfm(dir / "image.pfm").at(0, 0), vec3(0.5f));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"image.pfm"});
}

// ---- PNG and the sRGB curve -------------------------------------------------------------------------------

/// The sRGB encoding (IEC 61966-2-1) in double, written independently of ImageIO.
double srgbEncode(double linear)
{
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

TEST(Srgb, KnownValues)
{
    EXPECT_EQ(linearToSrgb8(0.5f), 188); // 255 (1.055 * 0.5^(1/2.4) - 0.055) = 187.5...
    EXPECT_EQ(linearToSrgb8(0.0f), 0);
    EXPECT_EQ(linearToSrgb8(1.0f), 255);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(linearToSrgb8(-1.0f), 0);
    EXPECT_EQ(linearToSrgb8(7.0f), 255);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(linearToSrgb8(0.001f), 3); // the linear toe: 255 * 12.92 * 0.001 = 3.3 (a pure gamma would give 12)
}

TEST(Srgb, EncodingRoundsTheStandardCurve)
{
    // To the nearest code: within half a code of 255 * encode(x), give or take float rounding (1e-3 code).
    for (int i = 0; i <= 10'000; ++i)
    {
        const float x = float(i) / 10'000.0f;
        EXPECT_NEAR(double(linearToSrgb8(x)), 255.0 * srgbEncode(x), 0.5 + 1e-3) << "x = " << x;
    }
}

TEST(Srgb, DecodingInvertsEncodingOnEveryCode)
{
    for (int code = 0; code < 256; ++code)
    {
        const float linear = srgb8ToLinear(static_cast<unsigned char>(code));
        EXPECT_EQ(linearToSrgb8(linear), code);
        EXPECT_NEAR(255.0 * srgbEncode(linear), double(code), 1e-3);
    }
}

TEST(Png, DecodesToTheSrgbCodesOfTheClampedImage)
{
    // Decoded with stb_image (not the writer): 8-bit RGB, row 0 at the top, each channel linearToSrgb8.
    const test::ScratchDir dir;
    Image image(3, 2);
    const float values[6][3] = {{0.0f, 0.5f, 1.0f},   {2.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()},
                                {0.2f, 0.04f, 0.001f}, {0.75f, 0.9f, 0.01f},
                                {1e-6f, 0.3f, 0.6f},   {0.18f, 0.18f, 0.18f}};
    for (int i = 0; i < 6; ++i)
        image.at(i % 3, i / 3) = vec3(values[i][0], values[i][1], values[i][2]);
    writePng(dir / "image.png", image);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"image.png"});
    int w = 0, h = 0, channels = 0;
    stbi_uc* decoded = stbi_load((dir / "image.png").string().c_str(), &w, &h, &channels, 0);
    ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, 3);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(channels, 3);
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c)
        {
            const float v = values[i][c];
            const int expected = std::isnan(v) || v <= 0.0f ? 0 : v >= 1.0f ? 255 : int(std::lround(255.0 * srgbEncode(v)));
            EXPECT_EQ(int(decoded[3 * i + c]), expected) << "pixel " << i << " channel " << c << " value " << v;
        }
    stbi_image_free(decoded);
}
} // namespace
} // namespace rt
