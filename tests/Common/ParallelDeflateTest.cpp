// Image/ParallelDeflate.h: a stream compressed in pieces on several threads is one valid zlib stream (zlib's
// own inflater, which checks the header and the adler-32, gives the data back), whatever the number of pieces,
// and a PNG large enough to be compressed in pieces decodes to its pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <stb_image.h>
#include <zlib.h>

#include "Image/ImageIO.h"
#include "Image/ParallelDeflate.h"
#include "Random/Pcg.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// Compressible and not: runs of a byte, a ramp, and noise, 1 MiB.
std::vector<unsigned char> mixedData(std::size_t length)
{
    std::vector<unsigned char> data(length);
    Rng rng(7);
    for (std::size_t i = 0; i < length; ++i)
    {
        const std::size_t region = (i / 4096) % 3;
        data[i] = region == 0 ? 42 : region == 1 ? static_cast<unsigned char>(i) : static_cast<unsigned char>(rng.nextUint());
    }
    return data;
}

std::vector<unsigned char> inflateAll(const std::vector<unsigned char>& stream, std::size_t expected)
{
    std::vector<unsigned char> out(expected + 1);
    uLongf size = static_cast<uLongf>(out.size());
    const int result = uncompress(out.data(), &size, stream.data(), static_cast<uLong>(stream.size()));
    if (result != Z_OK)
        throw std::runtime_error("uncompress failed: " + std::to_string(result));
    out.resize(size);
    return out;
}
} // namespace

TEST(ParallelDeflate, AnyNumberOfPiecesInflatesToTheData)
{
    const std::vector<unsigned char> data = mixedData(1 << 20);
    for (int parts : {1, 2, 3, 7, 16})
        for (int level : {1, 6, 9})
        {
            const std::vector<unsigned char> stream = deflateInParts(data.data(), data.size(), level, parts);
            ASSERT_FALSE(stream.empty()) << parts << " parts, level " << level;
            EXPECT_EQ(inflateAll(stream, data.size()), data) << parts << " parts, level " << level;
        }
}

TEST(ParallelDeflate, ShortAndEmptyDataAreOneStreamToo)
{
    for (std::size_t length : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(70000)})
    {
        const std::vector<unsigned char> data = mixedData(length);
        const std::vector<unsigned char> stream = deflateInParts(data.data(), data.size(), 1, 8);
        ASSERT_FALSE(stream.empty()) << length << " bytes";
        EXPECT_EQ(inflateAll(stream, data.size()), data) << length << " bytes";
    }
}

TEST(ParallelDeflate, AFlippedChecksumIsRejected)
{
    // The trailer is the whole data's adler-32 (combined from the pieces'): the inflater checks it.
    const std::vector<unsigned char> data = mixedData(1 << 18);
    std::vector<unsigned char> stream = deflateInParts(data.data(), data.size(), 1, 4);
    ASSERT_GT(stream.size(), 4u);
    stream.back() ^= 1;
    EXPECT_THROW(inflateAll(stream, data.size()), std::runtime_error);
}

TEST(ParallelDeflate, ALargePngDecodesToItsPixels)
{
    // 640 x 400: 768 KB of filtered rows, compressed in pieces on a machine of two cores or more.
    const test::ScratchDir dir;
    Image image(640, 400);
    Rng rng(35);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            image.at(x, y) = vec3(rng.nextFloat(), float(x) / 640.0f, y < 200 ? 0.5f : rng.nextFloat());
    writePng(dir / "large.png", image);
    int w = 0, h = 0, channels = 0;
    stbi_uc* decoded = stbi_load((dir / "large.png").string().c_str(), &w, &h, &channels, 3);
    ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
    ASSERT_EQ(w, 640);
    ASSERT_EQ(h, 400);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                wrong += decoded[3 * (y * w + x) + c] != linearToSrgb8(image.at(x, y)[c]);
    EXPECT_EQ(wrong, 0);
    stbi_image_free(decoded);
}
} // namespace rt
