// Image/ExrIO.h: float EXRs are lossless bit for bit, half EXRs are within half's precision with the documented
// clamp, row 0 is the file's top row, files cross-check with OpenEXR's own API and OpenImageIO (both ways), the
// reader reads what other writers make (tiled, mip-mapped, offset data windows, every compression, uint, multi-
// part), and every failure is an error of the right category naming the file: nothing half-written is left.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDeepFrameBuffer.h>
#include <ImfDeepScanLineOutputFile.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfTestFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#ifndef _WIN32
#include "Support/FileSizeLimit.h"
#include <unistd.h>
#endif

#include "Error.h"
#include "Image/ExrIO.h"
#include "Support/AssetErrorOf.h"
#include "Support/FileContents.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMaxHalf = 65504.0f;

float fromBits(std::uint32_t bits) { return std::bit_cast<float>(bits); }
std::uint32_t bitsOf(float v) { return std::bit_cast<std::uint32_t>(v); }

bool bitEqual(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

std::string describe(const vec3& v)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << " [" << std::hex << bitsOf(v.x) << "], " << std::dec << v.y << " [" << std::hex << bitsOf(v.y)
      << "], " << std::dec << v.z << " [" << std::hex << bitsOf(v.z) << "])";
    return s.str();
}

/// 7 x 3 (not square, odd sizes) with values a lossy or transposing writer would change: every pixel different,
/// negatives, -0, subnormals, the largest float, infinities and NaNs with payloads (quiet, negative, signalling).
Image awkwardImage()
{
    Image image(7, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x)
            image.at(x, y) = vec3(float(x) + 0.1f * float(y), -float(y) * 1e-3f - float(x), std::ldexp(1.0f, x * 20 - 70));
    image.at(0, 0) = vec3(-0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max());
    image.at(1, 0) = vec3(-std::numeric_limits<float>::denorm_min(), fromBits(0x007fffffu), -std::numeric_limits<float>::max());
    image.at(2, 1) = vec3(fromBits(0x7fc12345u), fromBits(0xffc00001u), fromBits(0x7f800001u)); // NaNs
    image.at(6, 2) = vec3(kInf, -kInf, 1.0f / 3.0f);
    image.at(5, 2) = vec3(1e30f, -1e30f, 65520.0f);
    return image;
}

/// Pseudo-random values over many magnitudes and both signs, reproducible.
Image noisyImage(int width, int height, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> mantissa(-2.0f, 2.0f);
    std::uniform_int_distribution<int> exponent(-12, 12);
    Image image(width, height);
    for (vec3& p : image.pixels())
        for (int c = 0; c < 3; ++c)
            p[c] = std::ldexp(mantissa(rng), exponent(rng));
    return image;
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
}

bool mentions(const std::string& message, const std::string& what) { return message.find(what) != std::string::npos; }

/// The pixels of `path`'s R, G, B channels read with OpenEXR's own API (not readExr), as floats, keyed by the
/// file's own coordinates: at(x, y) is the pixel of data-window coordinates (x, y).
struct RawPixels
{
    Imath::Box2i dataWindow, displayWindow;
    Imf::LineOrder lineOrder = Imf::INCREASING_Y;
    Imf::Compression compression = Imf::NO_COMPRESSION;
    std::vector<Imf::PixelType> types;
    std::vector<float> values; // 3 per pixel
    int width() const { return dataWindow.max.x - dataWindow.min.x + 1; }
    vec3 at(int x, int y) const
    {
        const std::size_t i = 3 * (std::size_t(y - dataWindow.min.y) * std::size_t(width()) + std::size_t(x - dataWindow.min.x));
        return vec3(values[i], values[i + 1], values[i + 2]);
    }
};

RawPixels readWithOpenExr(const std::filesystem::path& path)
{
    Imf::InputFile file(path.string().c_str());
    RawPixels raw;
    raw.dataWindow = file.header().dataWindow();
    raw.displayWindow = file.header().displayWindow();
    raw.lineOrder = file.header().lineOrder();
    raw.compression = file.header().compression();
    const std::size_t width = std::size_t(raw.width());
    const std::size_t height = std::size_t(raw.dataWindow.max.y - raw.dataWindow.min.y + 1);
    raw.values.assign(3 * width * height, 0.0f);
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
    {
        const Imf::Channel* channel = file.header().channels().findChannel(names[c]);
        raw.types.push_back(channel ? channel->type : Imf::NUM_PIXELTYPES);
        fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, raw.values.data() + c, raw.dataWindow, 3 * sizeof(float),
                                             3 * sizeof(float) * width));
    }
    file.setFrameBuffer(fb);
    file.readPixels(raw.dataWindow.min.y, raw.dataWindow.max.y);
    return raw;
}

// ---- EXR files written with OpenEXR's API in the test, to read with readExr -----------------------------------

struct RawChannel
{
    std::string name;
    Imf::PixelType type = Imf::FLOAT;
};

struct RawExr
{
    int width = 7;
    int height = 3;
    Imath::V2i origin{0, 0}; // the data window's top-left corner
    std::optional<Imath::Box2i> displayWindow;
    std::vector<RawChannel> channels{{"R"}, {"G"}, {"B"}};
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    Imf::LineOrder lineOrder = Imf::INCREASING_Y;
    bool tiled = false;
    int tileWidth = 4, tileHeight = 2;
    Imf::LevelMode levels = Imf::ONE_LEVEL;
};

/// The value of channel `c` at (x, y) of the data window (0-based): distinct, exact in half, uint and float.
float rawValue(int c, int x, int y) { return float(100 * (c + 1) + 10 * x + y) + 0.5f; }
std::uint32_t rawUint(int c, int x, int y) { return std::uint32_t(100 * (c + 1) + 10 * x + y); }
/// What a reader that took the wrong mip level would see.
constexpr float kOtherLevel = -12345.0f;

/// Per-channel buffers of one level, and a frame buffer over them.
struct LevelBuffers
{
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<Imath::half>> halves;
    std::vector<std::vector<std::uint32_t>> uints;
    Imf::FrameBuffer fb;

    LevelBuffers(const RawExr& spec, const Imath::Box2i& window, bool levelZero)
    {
        const int w = window.max.x - window.min.x + 1;
        const int h = window.max.y - window.min.y + 1;
        const std::size_t n = std::size_t(w) * std::size_t(h);
        floats.resize(spec.channels.size());
        halves.resize(spec.channels.size());
        uints.resize(spec.channels.size());
        for (std::size_t c = 0; c < spec.channels.size(); ++c)
        {
            const Imf::PixelType type = spec.channels[c].type;
            floats[c].resize(n);
            halves[c].resize(n);
            uints[c].resize(n);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                {
                    const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                    floats[c][i] = levelZero ? rawValue(int(c), x, y) : kOtherLevel;
                    halves[c][i] = Imath::half(floats[c][i]);
                    uints[c][i] = levelZero ? rawUint(int(c), x, y) : 999999u;
                }
            char* base = type == Imf::FLOAT  ? reinterpret_cast<char*>(floats[c].data())
                         : type == Imf::HALF ? reinterpret_cast<char*>(halves[c].data())
                                             : reinterpret_cast<char*>(uints[c].data());
            const std::size_t size = type == Imf::HALF ? 2 : 4;
            fb.insert(spec.channels[c].name, Imf::Slice::Make(type, base, window, size, size * std::size_t(w)));
        }
    }
};

Imf::Header rawHeader(const RawExr& spec)
{
    const Imath::Box2i data(spec.origin, spec.origin + Imath::V2i(spec.width - 1, spec.height - 1));
    Imf::Header header(spec.displayWindow.value_or(data), data);
    header.compression() = spec.compression;
    header.lineOrder() = spec.lineOrder;
    for (const RawChannel& channel : spec.channels)
        header.channels().insert(channel.name, Imf::Channel(channel.type));
    return header;
}

void writeRawExr(const std::filesystem::path& path, const RawExr& spec)
{
    Imf::Header header = rawHeader(spec);
    if (!spec.tiled)
    {
        LevelBuffers buffers(spec, header.dataWindow(), true);
        Imf::OutputFile file(path.string().c_str(), header);
        file.setFrameBuffer(buffers.fb);
        file.writePixels(spec.height);
        return;
    }
    header.setTileDescription(Imf::TileDescription(spec.tileWidth, spec.tileHeight, spec.levels));
    Imf::TiledOutputFile file(path.string().c_str(), header);
    for (int ly = 0; ly < (spec.levels == Imf::RIPMAP_LEVELS ? file.numYLevels() : 1); ++ly)
        for (int lx = 0; lx < (spec.levels == Imf::ONE_LEVEL ? 1 : file.numXLevels()); ++lx)
        {
            const int levelY = spec.levels == Imf::MIPMAP_LEVELS ? lx : ly;
            LevelBuffers buffers(spec, file.dataWindowForLevel(lx, levelY), lx == 0 && levelY == 0);
            file.setFrameBuffer(buffers.fb);
            file.writeTiles(0, file.numXTiles(lx) - 1, 0, file.numYTiles(levelY) - 1, lx, levelY);
        }
}

/// Checks readExr's image of a RawExr file: its data window, R G B = channels 0 1 2 of rawValue (or rawUint).
void expectRawValues(const Image& image, const RawExr& spec, float relativeTolerance = 0.0f)
{
    ASSERT_EQ(image.width(), spec.width);
    ASSERT_EQ(image.height(), spec.height);
    int channelOf[3] = {-1, -1, -1};
    for (std::size_t c = 0; c < spec.channels.size(); ++c)
        for (int k = 0; k < 3; ++k)
            if (spec.channels[c].name == std::string(1, "RGB"[k]))
                channelOf[k] = int(c);
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x)
            for (int k = 0; k < 3; ++k)
            {
                const int c = channelOf[k];
                const float expected =
                    spec.channels[std::size_t(c)].type == Imf::UINT ? float(rawUint(c, x, y)) : rawValue(c, x, y);
                if (relativeTolerance == 0.0f)
                    EXPECT_EQ(image.at(x, y)[k], expected) << "pixel (" << x << ", " << y << ") channel " << k;
                else
                    EXPECT_NEAR(image.at(x, y)[k], expected, relativeTolerance * std::abs(expected))
                        << "pixel (" << x << ", " << y << ") channel " << k;
            }
}

// ---- Float ----------------------------------------------------------------------------------------------------

TEST(Exr, FloatRoundTripIsBitExact)
{
    // -0, subnormals, +-FLT_MAX, infinities and NaNs (their payloads too: OpenEXR stores the 32 bits as they are).
    const test::ScratchDir dir;
    const Image image = awkwardImage();
    writeExr(dir / "image.exr", image, ExrPixelType::Float);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"image.exr"}) << "no .partial left";
    const Image back = readExr(dir / "image.exr");
    ASSERT_EQ(back.width(), 7);
    ASSERT_EQ(back.height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x)
            EXPECT_TRUE(bitEqual(back.at(x, y), image.at(x, y)))
                << "pixel (" << x << ", " << y << "): " << describe(back.at(x, y)) << " instead of "
                << describe(image.at(x, y));

    // A larger image of many magnitudes, over several of ZIP's 16-scanline blocks and a partial last one.
    const Image noisy = noisyImage(37, 41, 7);
    writeExr(dir / "noisy.exr", noisy, ExrPixelType::Float);
    const Image noisyBack = readExr(dir / "noisy.exr");
    ASSERT_EQ(noisyBack.width(), 37);
    ASSERT_EQ(noisyBack.height(), 41);
    EXPECT_EQ(std::memcmp(noisyBack.data(), noisy.data(), noisy.pixelCount() * sizeof(vec3)), 0);
}

TEST(Exr, FileIsZipCompressedFloatRgbWithEqualWindows)
{
    // What writeExr documents, read back with OpenEXR's own API.
    const test::ScratchDir dir;
    writeExr(dir / "float.exr", awkwardImage(), ExrPixelType::Float);
    writeExr(dir / "half.exr", awkwardImage()); // the default
    for (const char* name : {"float.exr", "half.exr"})
    {
        SCOPED_TRACE(name);
        const Imf::PixelType type = std::string(name) == "float.exr" ? Imf::FLOAT : Imf::HALF;
        bool tiled = true, deep = true;
        ASSERT_TRUE(Imf::isOpenExrFile((dir / name).string().c_str(), tiled, deep));
        EXPECT_FALSE(tiled);
        EXPECT_FALSE(deep);
        Imf::InputFile file((dir / name).string().c_str());
        const Imf::Header& header = file.header();
        EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION);
        EXPECT_EQ(header.lineOrder(), Imf::INCREASING_Y);
        EXPECT_EQ(header.dataWindow(), Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(6, 2)));
        EXPECT_EQ(header.displayWindow(), header.dataWindow());
        std::vector<std::string> channels;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        {
            channels.push_back(it.name());
            EXPECT_EQ(it.channel().type, type) << it.name();
            EXPECT_EQ(it.channel().xSampling, 1);
            EXPECT_EQ(it.channel().ySampling, 1);
        }
        EXPECT_EQ(channels, (std::vector<std::string>{"B", "G", "R"})); // OpenEXR lists them sorted
    }
}

// ---- Half -----------------------------------------------------------------------------------------------------

TEST(Exr, HalfRoundTripIsWithinHalfPrecision)
{
    const test::ScratchDir dir;
    std::vector<float> values;
    // Normal halves' range, [2^-14, 65504], many mantissas, both signs.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(1.0f, 2.0f);
    for (int e = -14; e <= 15; ++e)
        for (int i = 0; i < 40; ++i)
        {
            const float v = std::min(std::ldexp(unit(rng), e), kMaxHalf);
            values.push_back(v);
            values.push_back(-v);
        }
    for (float v : {1.0f, 0.1f, 1.0f / 3.0f, 6.103515625e-05f, 65504.0f, 65519.0f, 2049.0f, 2051.0f})
        values.push_back(v);
    // Below the smallest normal: subnormal halves (spacing 2^-24), and what rounds to zero.
    for (int i = 0; i < 200; ++i)
        values.push_back(std::ldexp(unit(rng), -15 - i % 12) * (i % 2 ? -1.0f : 1.0f));
    const std::size_t normalAndSubnormal = values.size();
    // Overflow and the special values (checked one by one below).
    const std::vector<float> specials = {65520.0f, 1e5f, 1e30f, std::numeric_limits<float>::max(), -65520.0f, -1e30f,
                                         kInf,     -kInf, std::numeric_limits<float>::quiet_NaN(), -0.0f, 0.0f,
                                         std::ldexp(1.0f, -25), -std::ldexp(1.0f, -26), std::numeric_limits<float>::denorm_min()};
    values.insert(values.end(), specials.begin(), specials.end());

    const int width = 17;
    const int height = int((values.size() + 3 * width - 1) / (3 * width));
    Image image(width, height);
    for (std::size_t i = 0; i < values.size(); ++i)
        image.data()[i / 3][int(i % 3)] = values[i];
    writeExr(dir / "half.exr", image, ExrPixelType::Half);
    const Image back = readExr(dir / "half.exr");
    ASSERT_EQ(back.width(), width);
    ASSERT_EQ(back.height(), height);
    auto backValue = [&](std::size_t i) { return back.data()[i / 3][int(i % 3)]; };

    for (std::size_t i = 0; i < normalAndSubnormal; ++i)
    {
        const float v = values[i];
        const float got = backValue(i);
        if (std::abs(v) >= std::ldexp(1.0f, -14))
            EXPECT_LE(std::abs(got - v), std::ldexp(std::abs(v), -11)) << "normal value " << v << " read " << got;
        else
            EXPECT_LE(std::abs(got - v), std::ldexp(1.0f, -25)) << "subnormal value " << v << " read " << got;
        EXPECT_EQ(got, float(Imath::half(v))) << "not rounded to the nearest half: " << v;
        EXPECT_EQ(std::signbit(got), std::signbit(v)) << v;
    }
    auto special = [&](std::size_t k) { return backValue(normalAndSubnormal + k); };
    EXPECT_EQ(special(0), kMaxHalf) << "65520 rounds to half's infinity: clamped to the largest half instead";
    EXPECT_EQ(special(1), kMaxHalf);
    EXPECT_EQ(special(2), kMaxHalf);
    EXPECT_EQ(special(3), kMaxHalf);
    EXPECT_EQ(special(4), -kMaxHalf);
    EXPECT_EQ(special(5), -kMaxHalf);
    EXPECT_EQ(special(6), kInf) << "infinities stay infinities";
    EXPECT_EQ(special(7), -kInf);
    EXPECT_TRUE(std::isnan(special(8))) << "NaN stays NaN";
    EXPECT_EQ(bitsOf(special(9)), bitsOf(-0.0f)) << "-0 keeps its sign";
    EXPECT_EQ(bitsOf(special(10)), bitsOf(0.0f));
    EXPECT_EQ(bitsOf(special(11)), bitsOf(0.0f)) << "2^-25, half-way to the smallest subnormal, rounds to even (0)";
    EXPECT_EQ(bitsOf(special(12)), bitsOf(-0.0f)) << "-2^-26 rounds to -0";
    EXPECT_EQ(bitsOf(special(13)), bitsOf(0.0f)) << "a float subnormal rounds to 0";
    for (std::size_t i = values.size(); i < back.pixelCount() * 3; ++i)
        EXPECT_EQ(bitsOf(backValue(i)), 0u) << "padding";

    // The file holds halves, not floats (with OpenEXR's own API).
    const RawPixels raw = readWithOpenExr(dir / "half.exr");
    EXPECT_EQ(raw.types, (std::vector<Imf::PixelType>{Imf::HALF, Imf::HALF, Imf::HALF}));
}

TEST(Exr, HalfFileIsHalfTheSizeOfFloatForNoise)
{
    // Sanity that the type reaches the file: incompressible noise takes about 2 bytes a value in half.
    const test::ScratchDir dir;
    const Image image = noisyImage(64, 64, 3);
    writeExr(dir / "half.exr", image, ExrPixelType::Half);
    writeExr(dir / "float.exr", image, ExrPixelType::Float);
    const auto half = std::filesystem::file_size(dir / "half.exr");
    const auto full = std::filesystem::file_size(dir / "float.exr");
    EXPECT_LT(double(half), 0.65 * double(full)) << half << " vs " << full;
}

// ---- Dimensions and orientation -------------------------------------------------------------------------------

TEST(Exr, NonSquareImagesKeepTheirOrientation)
{
    // Row 0 of the image is the file's y = 0 (the top; OpenEXR's y grows downwards), read independently with
    // OpenEXR's API, and readExr gives it back pixel for pixel.
    const test::ScratchDir dir;
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{7, 3}, {3, 7}, {1, 5}, {5, 1}, {1, 1}, {33, 18}})
        for (ExrPixelType type : {ExrPixelType::Half, ExrPixelType::Float})
        {
            SCOPED_TRACE(testing::Message() << w << "x" << h << (type == ExrPixelType::Half ? " half" : " float"));
            Image image(w, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    image.at(x, y) = vec3(float(x), float(y), float(100 * y + x)); // exact in half
            writeExr(dir / "image.exr", image, type);
            const RawPixels raw = readWithOpenExr(dir / "image.exr");
            ASSERT_EQ(raw.dataWindow, Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(w - 1, h - 1)));
            const Image back = readExr(dir / "image.exr");
            ASSERT_EQ(back.width(), w);
            ASSERT_EQ(back.height(), h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                {
                    EXPECT_EQ(raw.at(x, y), image.at(x, y)) << "file pixel (" << x << ", " << y << ")";
                    EXPECT_EQ(back.at(x, y), image.at(x, y)) << "pixel (" << x << ", " << y << ")";
                }
        }
}

// ---- Reading what other writers make ---------------------------------------------------------------------------

TEST(Exr, ReadsTheDataWindowOfOffsetWindowsAndDecreasingLineOrder)
{
    // The data window offset from (0, 0), inside a larger display window: the image is the data window, pixel
    // (0, 0) = the data window's top-left, whatever the line order in the file.
    const test::ScratchDir dir;
    for (Imf::LineOrder order : {Imf::INCREASING_Y, Imf::DECREASING_Y})
    {
        RawExr spec;
        spec.width = 9;
        spec.height = 5;
        spec.origin = Imath::V2i(-3, 17);
        spec.displayWindow = Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(99, 49));
        spec.lineOrder = order;
        writeRawExr(dir / "window.exr", spec);
        SCOPED_TRACE(order == Imf::INCREASING_Y ? "increasing y" : "decreasing y");
        expectRawValues(readExr(dir / "window.exr"), spec);
    }
}

TEST(Exr, ReadsTiledMipMappedRipMappedUintAndHalfChannelsWithExtras)
{
    const test::ScratchDir dir;
    struct Case
    {
        const char* name;
        RawExr spec;
    };
    std::vector<Case> cases;
    {
        RawExr s;
        s.width = 11;
        s.height = 7;
        s.tiled = true;
        s.tileWidth = 4;
        s.tileHeight = 3;
        s.channels = {{"A", Imf::HALF}, {"B", Imf::FLOAT}, {"G", Imf::FLOAT}, {"R", Imf::FLOAT}, {"Z", Imf::FLOAT}};
        cases.push_back({"tiled float with A and Z", s});
        s.levels = Imf::MIPMAP_LEVELS;
        s.origin = Imath::V2i(2, -5);
        s.compression = Imf::PIZ_COMPRESSION;
        cases.push_back({"tiled mip-mapped PIZ, offset window", s});
        s.levels = Imf::RIPMAP_LEVELS;
        s.lineOrder = Imf::RANDOM_Y;
        cases.push_back({"tiled rip-mapped random-y", s});
    }
    {
        RawExr s;
        s.channels = {{"R", Imf::UINT}, {"G", Imf::UINT}, {"B", Imf::UINT}};
        cases.push_back({"uint", s});
        s.channels = {{"R", Imf::HALF}, {"G", Imf::FLOAT}, {"B", Imf::UINT}, {"diffuse.R", Imf::HALF}};
        cases.push_back({"mixed half float uint, and a layer", s});
        s.tiled = true;
        cases.push_back({"mixed, tiled", s});
    }
    for (const Case& c : cases)
    {
        SCOPED_TRACE(c.name);
        writeRawExr(dir / "file.exr", c.spec);
        expectRawValues(readExr(dir / "file.exr"), c.spec);
    }
}

TEST(Exr, ReadsEveryCompression)
{
    // Lossless ones exactly; PXR24 (floats to 24 bits) and B44 / B44A / DWAA / DWAB (lossy on half RGB) closely.
    const test::ScratchDir dir;
    for (int compression = 0; compression < Imf::NUM_COMPRESSION_METHODS; ++compression)
        for (Imf::PixelType type : {Imf::HALF, Imf::FLOAT})
        {
            RawExr spec;
            spec.width = 21;
            spec.height = 19;
            spec.compression = Imf::Compression(compression);
            spec.channels = {{"R", type}, {"G", type}, {"B", type}};
            const char* names[] = {"NONE", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB"};
            static_assert(std::size(names) == Imf::NUM_COMPRESSION_METHODS);
            const std::string name = names[compression];
            SCOPED_TRACE(testing::Message() << name << (type == Imf::HALF ? " half" : " float"));
            writeRawExr(dir / "file.exr", spec);
            const bool lossy = spec.compression == Imf::B44_COMPRESSION || spec.compression == Imf::B44A_COMPRESSION ||
                               spec.compression == Imf::DWAA_COMPRESSION || spec.compression == Imf::DWAB_COMPRESSION ||
                               spec.compression == Imf::PXR24_COMPRESSION;
            expectRawValues(readExr(dir / "file.exr"), spec, lossy ? 0.01f : 0.0f);
        }
}

TEST(Exr, ReadsTheFirstPartOfAMultiPartFile)
{
    const test::ScratchDir dir;
    RawExr first;
    RawExr second;
    second.width = 4; // a different size, to tell them apart (the display window is shared by every part)
    second.height = 2;
    second.displayWindow = Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(first.width - 1, first.height - 1));
    Imf::Header headers[2] = {rawHeader(first), rawHeader(second)};
    headers[0].setName("first");
    headers[1].setName("second");
    for (Imf::Header& header : headers)
        header.setType(Imf::SCANLINEIMAGE);
    {
        Imf::MultiPartOutputFile file((dir / "parts.exr").string().c_str(), headers, 2);
        for (int part = 0; part < 2; ++part)
        {
            const RawExr& spec = part == 0 ? first : second;
            LevelBuffers buffers(spec, headers[part].dataWindow(), true);
            Imf::OutputPart out(file, part);
            out.setFrameBuffer(buffers.fb);
            out.writePixels(spec.height);
        }
    }
    expectRawValues(readExr(dir / "parts.exr"), first);
}

// ---- OpenImageIO, both ways -------------------------------------------------------------------------------------

#ifndef _WIN32
/// A Python that imports OpenImageIO: $RT_OIIO_PYTHON, python3 on the PATH, or the system's /usr/bin/python3 (a
/// pyenv or virtualenv python3 first on the PATH lacks the distribution's python3-openimageio). Empty if none.
std::string oiioPython()
{
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("RT_OIIO_PYTHON"))
        candidates.emplace_back(env);
    candidates.emplace_back("python3");
    candidates.emplace_back("/usr/bin/python3");
    for (const std::string& python : candidates)
        if (std::system(("'" + python + "' -c 'import OpenImageIO, numpy' >/dev/null 2>&1").c_str()) == 0)
            return python;
    return {};
}

/// Runs `script` (Python, with the arguments after it) and returns its exit status; its output goes to the
/// test's log.
int runPython(const std::string& python, const test::ScratchDir& dir, const std::string& script,
              const std::vector<std::string>& args)
{
    const std::filesystem::path file = dir / "script.py";
    std::ofstream(file) << script;
    std::string command = "'" + python + "' '" + file.string() + "'";
    for (const std::string& arg : args)
        command += " '" + arg + "'";
    return std::system(command.c_str());
}

#define REQUIRE_OIIO_PYTHON(python)                                                                                 \
    const std::string python = oiioPython();                                                                        \
    if (python.empty())                                                                                             \
    {                                                                                                               \
        GTEST_SKIP() << "OpenImageIO's Python module (with numpy) is not importable from $RT_OIIO_PYTHON, python3 " \
                        "or /usr/bin/python3: on Debian / Ubuntu it comes with the package python3-openimageio";    \
    }

TEST(ExrOpenImageIo, ReadsWhatWriteExrWrites)
{
    REQUIRE_OIIO_PYTHON(python);
    const test::ScratchDir dir;
    // OpenImageIO reads the file to float32 and dumps its spec and pixels; they must be readExr's, bit for bit
    // (half: the same half, widened to float by both).
    const std::string script = R"(
import sys, OpenImageIO as oiio, numpy
exr, spec_out, pixels_out = sys.argv[1:4]
inp = oiio.ImageInput.open(exr)
if not inp:
    sys.exit('cannot open: ' + oiio.geterror())
s = inp.spec()
with open(spec_out, 'w') as f:
    f.write('%d %d %d %d %d %d %d %d %s %s %s %d\n' % (s.width, s.height, s.x, s.y, s.full_width, s.full_height,
            s.full_x, s.full_y, ','.join(s.channelnames), str(s.format), s.get_string_attribute('compression'),
            s.tile_width))
pixels = inp.read_image(oiio.FLOAT)
inp.close()
numpy.ascontiguousarray(pixels, dtype=numpy.float32).tofile(pixels_out)
)";
    Image image = noisyImage(13, 6, 5);
    image.at(0, 0) = vec3(1e30f, -1e30f, kInf);
    image.at(12, 5) = vec3(-0.0f, std::numeric_limits<float>::denorm_min(), 1e-6f);
    for (ExrPixelType type : {ExrPixelType::Float, ExrPixelType::Half})
    {
        const bool isFloat = type == ExrPixelType::Float;
        SCOPED_TRACE(isFloat ? "float" : "half");
        writeExr(dir / "ours.exr", image, type);
        ASSERT_EQ(runPython(python, dir, script,
                            {(dir / "ours.exr").string(), (dir / "spec.txt").string(), (dir / "pixels.f32").string()}),
                  0);
        std::string spec = test::fileContents(dir / "spec.txt");
        EXPECT_EQ(spec, std::string("13 6 0 0 13 6 0 0 R,G,B ") + (isFloat ? "float" : "half") + " zip 0\n");
        const std::string bytes = test::fileContents(dir / "pixels.f32");
        ASSERT_EQ(bytes.size(), image.pixelCount() * sizeof(vec3));
        const Image ours = readExr(dir / "ours.exr");
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 13; ++x)
            {
                vec3 theirs;
                std::memcpy(&theirs, bytes.data() + (std::size_t(y) * 13 + std::size_t(x)) * sizeof(vec3), sizeof(vec3));
                EXPECT_TRUE(bitEqual(theirs, ours.at(x, y)))
                    << "pixel (" << x << ", " << y << "): OpenImageIO " << describe(theirs) << ", readExr "
                    << describe(ours.at(x, y));
                if (isFloat)
                {
                    EXPECT_TRUE(bitEqual(theirs, image.at(x, y))) << "pixel (" << x << ", " << y << ")";
                }
            }
        if (!isFloat)
        {
            EXPECT_EQ(ours.at(0, 0), vec3(kMaxHalf, -kMaxHalf, kInf)) << "the clamp, seen by OpenImageIO too";
        }
    }
}

TEST(ExrOpenImageIo, ReadExrReadsWhatOpenImageIoWrites)
{
    REQUIRE_OIIO_PYTHON(python);
    const test::ScratchDir dir;
    // OpenImageIO writes RGBA from raw float32 values the test makes: (1) tiled, float, PIZ, its data window
    // offset inside a larger display window; (2) scanline, half, decreasing y, ZIPS.
    const std::string script = R"(
import sys, OpenImageIO as oiio, numpy
raw, exr, kind = sys.argv[1:4]
w, h = 13, 9
pixels = numpy.fromfile(raw, dtype=numpy.float32).reshape(h, w, 4)
if kind == 'tiled':
    spec = oiio.ImageSpec(w, h, 4, oiio.FLOAT)
    spec.tile_width, spec.tile_height = 8, 4
    spec.x, spec.y = -4, 3
    spec.full_x, spec.full_y, spec.full_width, spec.full_height = 0, 0, 10, 10
    spec.attribute('compression', 'piz')
else:
    spec = oiio.ImageSpec(w, h, 4, oiio.HALF)
    spec.attribute('compression', 'zips')
    spec.attribute('openexr:lineOrder', 'decreasingY')
spec.channelnames = ('R', 'G', 'B', 'A')
out = oiio.ImageOutput.create(exr)
if not out or not out.open(exr, spec):
    sys.exit('cannot write: ' + oiio.geterror())
if not out.write_image(pixels):
    sys.exit('cannot write: ' + out.geterror())
out.close()
)";
    const int w = 13, h = 9;
    std::vector<float> rgba(std::size_t(w) * h * 4);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> value(-3.0f, 3.0f);
    for (float& v : rgba)
        v = std::ldexp(value(rng), int(rng() % 20) - 10);
    rgba[0] = std::numeric_limits<float>::denorm_min();
    rgba[1] = 3e38f;
    rgba[2] = -0.0f;
    writeBytes(dir / "values.f32", std::string(reinterpret_cast<const char*>(rgba.data()), rgba.size() * sizeof(float)));
    for (const std::string kind : {"tiled", "scanline"})
    {
        SCOPED_TRACE(kind);
        const bool tiled = kind == "tiled";
        ASSERT_EQ(runPython(python, dir, script, {(dir / "values.f32").string(), (dir / "theirs.exr").string(), kind}),
                  0);
        // That OpenImageIO wrote what was asked, seen with OpenEXR's API.
        EXPECT_EQ(Imf::isTiledOpenExrFile((dir / "theirs.exr").string().c_str()), tiled);
        const RawPixels raw = readWithOpenExr(dir / "theirs.exr");
        EXPECT_EQ(raw.compression, tiled ? Imf::PIZ_COMPRESSION : Imf::ZIPS_COMPRESSION);
        if (tiled)
        {
            EXPECT_EQ(raw.dataWindow, Imath::Box2i(Imath::V2i(-4, 3), Imath::V2i(-4 + w - 1, 3 + h - 1)));
            EXPECT_EQ(raw.displayWindow, Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(9, 9)));
        }
        else
            EXPECT_EQ(raw.lineOrder, Imf::DECREASING_Y);

        const Image image = readExr(dir / "theirs.exr");
        ASSERT_EQ(image.width(), w);
        ASSERT_EQ(image.height(), h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
            {
                const float* p = rgba.data() + 4 * (std::size_t(y) * w + std::size_t(x));
                vec3 expected(p[0], p[1], p[2]);
                if (!tiled)
                    expected = vec3(float(Imath::half(p[0])), float(Imath::half(p[1])), float(Imath::half(p[2])));
                EXPECT_TRUE(bitEqual(image.at(x, y), expected))
                    << "pixel (" << x << ", " << y << "): " << describe(image.at(x, y)) << " instead of "
                    << describe(expected);
            }
    }
}
#endif

// ---- Errors ---------------------------------------------------------------------------------------------------

TEST(ExrErrors, MissingForeignEmptyAndFolderAreAssetErrorsNamingTheFile)
{
    const test::ScratchDir dir;
    const auto missing = dir / "missing.exr";
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(missing); }), missing.string()));
    const auto text = dir.write("text.exr", "this is not an image, just text long enough to be read");
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(text); }), text.string()));
    const auto empty = dir.write("empty.exr", "");
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(empty); }), empty.string()));
    const auto magicOnly = dir.write("magic.exr", std::string("\x76\x2f\x31\x01", 4));
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(magicOnly); }), magicOnly.string()));
    std::filesystem::create_directory(dir / "folder.exr");
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(dir / "folder.exr"); }), (dir / "folder.exr").string()));
}

TEST(ExrErrors, TruncatedFilesAreOneLineAssetErrors)
{
    // Written valid, then cut in half: scanline (ours) and tiled, float and half.
    const test::ScratchDir dir;
    const Image image = noisyImage(64, 48, 1);
    writeExr(dir / "float.exr", image, ExrPixelType::Float);
    writeExr(dir / "half.exr", image, ExrPixelType::Half);
    RawExr tiled;
    tiled.width = 40;
    tiled.height = 30;
    tiled.tiled = true;
    tiled.tileWidth = tiled.tileHeight = 8;
    writeRawExr(dir / "tiled.exr", tiled);
    for (const char* name : {"float.exr", "half.exr", "tiled.exr"})
    {
        SCOPED_TRACE(name);
        const std::string bytes = test::fileContents(dir / name);
        ASSERT_GT(bytes.size(), 1000u);
        const auto cut = dir / (std::string("cut-") + name);
        writeBytes(cut, bytes.substr(0, bytes.size() / 2));
        const std::string message = test::assetErrorOf([&] { readExr(cut); });
        EXPECT_TRUE(mentions(message, cut.string())) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        // One byte short fails too (the last block is incomplete).
        writeBytes(cut, bytes.substr(0, bytes.size() - 1));
        EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(cut); }), cut.string()));
    }
}

TEST(ExrErrors, EveryTruncationAndByteFlipIsAnAssetErrorOrAnImageNeverACrash)
{
    // A small file of ours (two of ZIP's blocks of rows) cut at every length, and with each byte inverted:
    // readExr throws AssetError for every cut, and returns an image or throws AssetError for every flip; nothing
    // else (no other exception, no crash, no runaway allocation from a size field gone wrong).
    const test::ScratchDir dir;
    writeExr(dir / "small.exr", noisyImage(5, 20, 2), ExrPixelType::Half);
    const std::string bytes = test::fileContents(dir / "small.exr");
    int count = 0;
    // Each case a new file, removed after: rewriting one file in place makes ext4 flush it on every close
    // (auto_da_alloc), 20 times slower.
    auto check = [&](const std::string& content, const std::string& what, bool mustFail) {
        const auto bad = dir / ("case-" + std::to_string(count++) + ".exr");
        writeBytes(bad, content);
        try
        {
            (void)readExr(bad);
            EXPECT_FALSE(mustFail) << what << ": read without an error";
        }
        catch (const AssetError& e)
        {
            EXPECT_TRUE(mentions(e.what(), bad.string())) << what << ": " << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << what << ": " << e.what();
        }
        catch (const std::exception& e)
        {
            ADD_FAILURE() << what << ": not an AssetError: " << e.what();
        }
        std::filesystem::remove(bad);
    };
    for (std::size_t length = 0; length < bytes.size(); ++length)
        check(bytes.substr(0, length), "cut at " + std::to_string(length) + " of " + std::to_string(bytes.size()), true);
    for (std::size_t i = 0; i < bytes.size(); ++i)
    {
        std::string flipped = bytes;
        flipped[i] = char(~flipped[i]);
        check(flipped, "byte " + std::to_string(i) + " inverted", false);
    }
}

TEST(ExrErrors, MissingChannelsAreNamed)
{
    const test::ScratchDir dir;
    RawExr noBlue;
    noBlue.channels = {{"R"}, {"G"}, {"A"}};
    writeRawExr(dir / "rga.exr", noBlue);
    const std::string message = test::assetErrorOf([&] { readExr(dir / "rga.exr"); });
    EXPECT_TRUE(mentions(message, (dir / "rga.exr").string())) << message;
    EXPECT_TRUE(mentions(message, "no B channel")) << message;
    EXPECT_TRUE(mentions(message, "A, G, R")) << "lists what the file has: " << message;

    RawExr luminance; // a greyscale EXR (Y), and one whose RGB are only in a layer
    luminance.channels = {{"Y", Imf::HALF}};
    writeRawExr(dir / "y.exr", luminance);
    const std::string yMessage = test::assetErrorOf([&] { readExr(dir / "y.exr"); });
    EXPECT_TRUE(mentions(yMessage, "no R, G, B channels")) << yMessage;
    RawExr layer;
    layer.channels = {{"diffuse.B"}, {"diffuse.G"}, {"diffuse.R"}};
    writeRawExr(dir / "layer.exr", layer);
    EXPECT_TRUE(mentions(test::assetErrorOf([&] { readExr(dir / "layer.exr"); }), "diffuse.R"));
}

TEST(ExrErrors, DeepFilesAreAssetErrors)
{
    // With and without a Z channel (OpenEXR's InputFile would composite the first into a flat image).
    const test::ScratchDir dir;
    const int w = 3, h = 2;
    for (const std::vector<const char*>& channels :
         {std::vector<const char*>{"R", "G", "B"}, std::vector<const char*>{"R", "G", "B", "Z"}})
    {
        SCOPED_TRACE(channels.size() == 4 ? "with Z" : "without Z");
        Imf::Header header(w, h);
        header.compression() = Imf::ZIPS_COMPRESSION;
        header.setType(Imf::DEEPSCANLINE);
        for (const char* name : channels)
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        std::vector<unsigned int> counts(w * h, 1);
        std::vector<float> samples(w * h, 0.5f);
        std::vector<float*> pointers(w * h);
        for (int i = 0; i < w * h; ++i)
            pointers[std::size_t(i)] = &samples[std::size_t(i)];
        {
            Imf::DeepScanLineOutputFile file((dir / "deep.exr").string().c_str(), header);
            Imf::DeepFrameBuffer fb;
            fb.insertSampleCountSlice(Imf::Slice(Imf::UINT, reinterpret_cast<char*>(counts.data()), sizeof(unsigned),
                                                 sizeof(unsigned) * w));
            for (const char* name : channels)
                fb.insert(name, Imf::DeepSlice(Imf::FLOAT, reinterpret_cast<char*>(pointers.data()), sizeof(float*),
                                               sizeof(float*) * w, sizeof(float)));
            file.setFrameBuffer(fb);
            file.writePixels(h);
        }
        const std::string message = test::assetErrorOf([&] { readExr(dir / "deep.exr"); });
        EXPECT_TRUE(mentions(message, (dir / "deep.exr").string())) << message;
        EXPECT_TRUE(mentions(message, "is a deep OpenEXR file")) << message;
    }
}

/// Runs `write`, expects an OutputError naming `path`, and returns its message.
std::string outputErrorOf(const std::filesystem::path& path, const std::function<void()>& write)
{
    try
    {
        write();
    }
    catch (const OutputError& e)
    {
        EXPECT_TRUE(mentions(e.what(), path.string())) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not an OutputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no error writing " << path;
    return {};
}

TEST(ExrErrors, AMissingFolderOrAnEmptyImageIsAnOutputErrorAndLeavesNoFile)
{
    const test::ScratchDir dir;
    outputErrorOf(dir / "no-such-folder" / "image.exr", [&] { writeExr(dir / "no-such-folder" / "image.exr", Image(2, 2)); });
    dir.write("file", "a file, not a folder");
    outputErrorOf(dir / "file" / "image.exr", [&] { writeExr(dir / "file" / "image.exr", Image(2, 2)); });
    outputErrorOf(dir / "empty.exr", [&] { writeExr(dir / "empty.exr", Image()); });
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"}) << "a file or folder was created";
}

#ifndef _WIN32
TEST(ExrErrors, AnUnwritableFolderIsAnOutputErrorAndLeavesNoFile)
{
    const test::ScratchDir dir;
    const auto folder = dir / "read-only";
    std::filesystem::create_directory(folder);
    std::filesystem::permissions(folder, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const bool stillWritable = ::access(folder.c_str(), W_OK) == 0;
    if (stillWritable)
    {
        // Root writes into a read-only folder; sysfs refuses to create files even for root.
        std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
        const std::filesystem::path sys = "/sys";
        if (!std::filesystem::is_directory(sys))
            GTEST_SKIP() << "a read-only folder is writable for this user (root) and there is no /sys to try instead";
        const std::string message = outputErrorOf(sys / "image.exr", [&] { writeExr(sys / "image.exr", Image(2, 2)); });
        // EACCES, or EROFS where a container mounts /sys read-only.
        EXPECT_TRUE(mentions(message, "ermission denied") || mentions(message, "ead-only file system")) << message;
        EXPECT_FALSE(std::filesystem::exists(sys / "image.exr"));
        EXPECT_FALSE(std::filesystem::exists(sys / "image.exr.partial"));
        return;
    }
    const std::string message = outputErrorOf(folder / "image.exr", [&] { writeExr(folder / "image.exr", Image(2, 2)); });
    EXPECT_TRUE(mentions(message, "ermission denied")) << message;
    std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
    EXPECT_TRUE(std::filesystem::is_empty(folder));
}

using test::FileSizeLimit;

TEST(ExrErrors, AFailedWriteLeavesTheOldFileOrNothingNeverAPartialOne)
{
    // A write that fails after OpenEXR created the temporary (a full disk; here a file size limit): half-way, and
    // one byte short of the end. A large image goes out in pieces as OpenEXR writes its blocks of rows; a small
    // one stays in the stream's buffer until OpenEXR's destructor seeks back to write the table of block
    // offsets, and that destructor swallows the failure: writeExr must see it in the stream. The old file stays
    // whole; no .partial is left.
    const test::ScratchDir dir;
    struct Case
    {
        const char* name;
        Image image;
        ExrPixelType type;
    };
    const Case cases[] = {{"128x96 float noise, written in pieces", noisyImage(128, 96, 4), ExrPixelType::Float},
                          {"16x8 half, buffered to the end", noisyImage(16, 8, 6), ExrPixelType::Half}};
    Image old(2, 1);
    old.at(1, 0) = vec3(42.0f);
    for (const Case& c : cases)
    {
        writeExr(dir / "size.exr", c.image, c.type);
        const auto size = std::filesystem::file_size(dir / "size.exr");
        std::filesystem::remove(dir / "size.exr");
        for (const std::uintmax_t limit : {size / 2, size - 1})
        {
            SCOPED_TRACE(testing::Message() << c.name << ": limit " << limit << " of " << size << " bytes");
            writeExr(dir / "old.exr", old, ExrPixelType::Float);
            std::string message;
            {
                const FileSizeLimit fileSizeLimit(limit);
                message = outputErrorOf(dir / "new.exr", [&] { writeExr(dir / "new.exr", c.image, c.type); });
                outputErrorOf(dir / "old.exr", [&] { writeExr(dir / "old.exr", c.image, c.type); });
            }
            EXPECT_TRUE(mentions(message, "too large")) << "EFBIG's reason: " << message;
            EXPECT_EQ(dir.entries(), std::vector<std::string>{"old.exr"});
            EXPECT_EQ(readExr(dir / "old.exr").at(1, 0), vec3(42.0f)) << "the old file was replaced";
            std::filesystem::remove(dir / "old.exr");
        }
        // Without the limit, the same write succeeds.
        writeExr(dir / "new.exr", c.image, c.type);
        EXPECT_EQ(std::filesystem::file_size(dir / "new.exr"), size);
        std::filesystem::remove(dir / "new.exr");
    }
}
#endif
} // namespace
} // namespace rt
