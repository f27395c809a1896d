#include "Image/ImageIO.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "HostThreads.h"
#include "Image/ParallelDeflate.h"

namespace
{
// zlib's deflate at level 1 for stb_image_write's PNGs, in place of stb's own (STBIW_ZLIB_COMPRESS), in pieces
// on every core this process may use (Image/ParallelDeflate.h). With the Sub filter below, book 3's 600x600
// 16-spp render encodes in 30 ms on one core instead of 81 with stb's defaults, 15 % smaller; a textured
// render (rtnw-earth) in 5 ms instead of 16, 13 % smaller (one core of the CI kind). Returns a buffer stb
// frees with free(), or nullptr.
unsigned char* deflateForPng(unsigned char* data, int length, int* outLength, int /*quality*/)
{
    const std::vector<unsigned char> stream =
        rt::deflateInParts(data, static_cast<std::size_t>(length), 1, rt::usableCores());
    auto* out = stream.empty() ? nullptr : static_cast<unsigned char*>(std::malloc(stream.size()));
    if (!out)
        return nullptr;
    std::memcpy(out, stream.data(), stream.size());
    *outLength = static_cast<int>(stream.size());
    return out;
}
} // namespace

// stb_image_write built here, its functions static to this file, so that it uses deflateForPng (Debian's
// prebuilt libstb has stb's deflate compiled in).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ZLIB_COMPRESS deflateForPng
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" // the writers of other formats
#endif
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "Error.h"
#include "IO/AtomicFile.h"

namespace rt
{
namespace
{
// One row filter (Sub) instead of stb's trial of all five per row: 30 ms instead of 38 for the render above,
// 0.6 % larger.
[[maybe_unused]] const bool kPngFilter = [] {
    stbi_write_force_png_filter = 1;
    return true;
}();

/// Encodes an 8-bit image as PNG in memory and writes it with every write and the close checked (stb's own
/// file writer ignores fwrite's and fclose's errors: a full disk left a truncated PNG reported as written).
bool writePngBytes(const std::filesystem::path& file, const unsigned char* pixels, int width, int height, int channels)
{
    int length = 0;
    unsigned char* png = stbi_write_png_to_mem(pixels, width * channels, width, height, channels, &length);
    if (!png)
    {
        errno = ENOMEM;
        return false;
    }
    const bool written = writeBytes(file, std::string_view(reinterpret_cast<const char*>(png), std::size_t(length)));
    const int reason = errno;
    std::free(png);
    errno = reason;
    return written;
}

float srgbEncode(float linear)
{
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}
} // namespace

unsigned char linearToSrgb8(float linear)
{
    if (!(linear > 0.0f))
        return 0; // also NaN
    if (linear >= 1.0f)
        return 255;
    return static_cast<unsigned char>(std::lround(srgbEncode(linear) * 255.0f));
}

float srgb8ToLinear(unsigned char encoded)
{
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
        {
            const float c = static_cast<float>(i) / 255.0f;
            t[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
        return t;
    }();
    return table[encoded];
}

void writePng(const std::filesystem::path& path, const Image& image)
{
    // The transfer curve's pow is 9 ns a value (10 ms of a 600x600 render on one core): split over the cores,
    // as the deflate is, in parts of at least 32 K pixels (a thread's start would cost more than a smaller part).
    std::vector<unsigned char> bytes(image.pixelCount() * 3);
    const std::size_t pixels = image.pixelCount();
    const int parts =
        static_cast<int>(std::clamp<std::size_t>(pixels >> 15, 1, static_cast<std::size_t>(usableCores())));
    runInParallel(parts, [&](int part) {
        const std::size_t end = pixels * std::size_t(part + 1) / std::size_t(parts);
        for (std::size_t i = pixels * std::size_t(part) / std::size_t(parts); i < end; ++i)
            for (int c = 0; c < 3; ++c)
                bytes[3 * i + c] = linearToSrgb8(image.data()[i][c]);
    });
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        return writePngBytes(tmp, bytes.data(), image.width(), image.height(), 3);
    });
}

void writePng8(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgba)
{
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * height * 4)
        throw UsageError(fmt::format("cannot write '{}': {} bytes for a {}x{} RGBA image", path.string(), rgba.size(),
                                     width, height));
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        return writePngBytes(tmp, rgba.data(), width, height, 4);
    });
}

void writePfm(const std::filesystem::path& path, const Image& image)
{
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        // A negative scale declares little-endian data.
        out << "PF\n" << image.width() << ' ' << image.height() << "\n-1.0\n";
        for (int y = image.height() - 1; y >= 0; --y)
            out.write(reinterpret_cast<const char*>(&image.at(0, y)), std::streamsize(sizeof(vec3)) * image.width());
        out.close();
        return static_cast<bool>(out);
    });
}

std::vector<std::filesystem::path> writePngWithLinear(const std::filesystem::path& png, const Image& image)
{
    std::filesystem::path pfm = png, exr = png;
    pfm.replace_extension(".pfm");
    exr.replace_extension(".exr");
    writePng(png, image);
    writePfm(pfm, image);
    writeExr(exr, image, ExrPixelType::Float);
    return {pfm, exr};
}

Image readLinearImage(const std::filesystem::path& path)
{
    return path.extension() == ".exr" ? readExr(path) : readPfm(path);
}

Image readPfm(const std::filesystem::path& path)
{
    // Not a pipe, a device or a folder: opening a pipe waits for a writer that may never come.
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw AssetError(fmt::format("cannot open '{}': it is not a regular file", path.string()));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw AssetError(fmt::format("cannot open '{}'", path.string()));
    std::string magic;
    int width = 0, height = 0;
    float scale = 0.0f;
    in >> magic >> width >> height >> scale;
    in.get(); // the single whitespace character before the data
    if (magic != "PF" || width <= 0 || height <= 0 || scale == 0.0f)
        throw AssetError(fmt::format("'{}' is not an RGB PFM file", path.string()));
    // The pixels the header claims must be in the file before they are allocated: a corrupt header of 99999 x
    // 99999 was "out of memory" instead of the broken file it is.
    const std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    in.seekg(start);
    const std::uint64_t needed = std::uint64_t(width) * std::uint64_t(height) * sizeof(vec3);
    if (start < 0 || end < start || std::uint64_t(end - start) < needed)
        throw AssetError(fmt::format("'{}' is truncated: its header says {}x{} pixels ({} bytes), the file holds {} "
                                     "bytes of pixels",
                                     path.string(), width, height, needed, start < 0 || end < start ? 0 : end - start));
    Image image(width, height);
    const bool bigEndian = scale > 0.0f;
    for (int y = height - 1; y >= 0; --y)
    {
        in.read(reinterpret_cast<char*>(&image.at(0, y)), std::streamsize(sizeof(vec3)) * width);
        if (bigEndian)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c)
                {
                    std::uint32_t bits;
                    std::memcpy(&bits, &image.at(x, y)[c], 4);
                    bits = __builtin_bswap32(bits);
                    std::memcpy(&image.at(x, y)[c], &bits, 4);
                }
    }
    if (!in)
        throw AssetError(fmt::format("'{}' is truncated", path.string()));
    return image;
}

void writeImage(const std::filesystem::path& path, const Image& image, ExrPixelType exrType)
{
    const std::string ext = path.extension().string();
    if (ext == ".png" || ext == ".PNG")
        writePng(path, image);
    else if (ext == ".pfm" || ext == ".PFM")
        writePfm(path, image);
    else if (ext == ".exr" || ext == ".EXR")
        writeExr(path, image, exrType);
    else
        throw UsageError(fmt::format("cannot write '{}': the image format must be .png, .pfm or .exr", path.string()));
}
} // namespace rt
