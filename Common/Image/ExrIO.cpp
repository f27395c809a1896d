#include "Image/ExrIO.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfStdIO.h>
#include <ImfVersion.h>
#include <half.h>

#include "Error.h"
#include "IO/AtomicFile.h"

namespace rt
{
namespace
{
static_assert(sizeof(vec3) == 3 * sizeof(float), "Image's pixels must be three packed floats for the EXR slices");

constexpr std::array<const char*, 3> kChannels = {"R", "G", "B"};

/// The largest image readExr accepts: 2^28 pixels (16384 x 16384, 3 GiB of floats). A corrupt header's data
/// window must not make a 1 KB file allocate and zero-fill without bound.
constexpr std::int64_t kMaxPixels = std::int64_t(1) << 28;

/// OpenEXR's messages can span lines (and carry a trailing period or space): one line for the user.
std::string oneLine(std::string text)
{
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

/// `value` rounded to the nearest half (ties to even), finite values beyond half's range clamped to the
/// largest half instead of becoming infinities (ExrIO.h).
Imath::half toHalf(float value)
{
    constexpr float kMaxHalf = 65504.0f;
    if (std::isfinite(value))
        value = std::clamp(value, -kMaxHalf, kMaxHalf);
    return Imath::half(value);
}

/// The base pointer of channel `c` of `image`'s pixels, as OpenEXR's slices take it.
char* channelBase(const Image& image, int c)
{
    // OpenEXR's Slice takes a char* for reading and writing alike; the output file only reads through it.
    return reinterpret_cast<char*>(const_cast<float*>(&image.data()->x)) + std::size_t(c) * sizeof(float);
}

/// Writes the EXR file of `image` into `out` (a stream the caller opened and checks afterwards).
void writeExrTo(std::ofstream& out, const std::string& shownName, const Image& image, ExrPixelType type)
{
    const int width = image.width();
    const int height = image.height();
    Imf::StdOFStream stream(out, shownName.c_str());

    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.lineOrder() = Imf::INCREASING_Y;
    const Imf::PixelType pixelType = type == ExrPixelType::Float ? Imf::FLOAT : Imf::HALF;
    for (const char* name : kChannels)
        header.channels().insert(name, Imf::Channel(pixelType));

    Imf::FrameBuffer frameBuffer;
    std::vector<Imath::half> halves;
    if (type == ExrPixelType::Float)
    {
        for (int c = 0; c < 3; ++c)
            frameBuffer.insert(kChannels[c], Imf::Slice(Imf::FLOAT, channelBase(image, c), sizeof(vec3),
                                                        sizeof(vec3) * std::size_t(width)));
    }
    else
    {
        halves.resize(image.pixelCount() * 3);
        const vec3* pixels = image.data();
        for (std::size_t i = 0; i < image.pixelCount(); ++i)
            for (int c = 0; c < 3; ++c)
                halves[3 * i + std::size_t(c)] = toHalf(pixels[i][c]);
        for (int c = 0; c < 3; ++c)
            frameBuffer.insert(kChannels[c],
                               Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.data() + c),
                                          3 * sizeof(Imath::half), 3 * sizeof(Imath::half) * std::size_t(width)));
    }

    // The OutputFile's destructor writes the table of scanline-block offsets; it swallows the exception of a
    // failed write there, which the caller sees in the stream's state (failbit stays set).
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frameBuffer);
    file.writePixels(height);
}

/// The channels of `header`, comma-separated, for a message (the first 12).
std::string channelNames(const Imf::Header& header)
{
    std::string names;
    int count = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++count)
    {
        if (count == 12)
            return names + ", ...";
        names += (names.empty() ? "" : ", ") + std::string(it.name());
    }
    return names.empty() ? "none" : names;
}
} // namespace

void writeExr(const std::filesystem::path& path, const Image& image, ExrPixelType type)
{
    const std::string shownName = path.string();
    if (image.width() <= 0 || image.height() <= 0 ||
        image.pixelCount() != std::size_t(image.width()) * std::size_t(image.height()))
        throw OutputError(fmt::format("cannot write '{}': the image is empty ({}x{}, {} pixels)", shownName,
                                      image.width(), image.height(), image.pixelCount()));

    std::string reason; // OpenEXR's or the C library's, where the write failed
    try
    {
        writeAtomically(path, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out)
            {
                reason = errno != 0 ? std::strerror(errno) : "cannot create the file";
                return false;
            }
            try
            {
                writeExrTo(out, shownName, image, type);
            }
            catch (const std::exception& e)
            {
                reason = oneLine(e.what());
                return false;
            }
            errno = 0;
            out.close();
            if (!out) // a write of the offset table (in the OutputFile's destructor) or the final flush failed
            {
                reason = errno != 0 ? std::strerror(errno) : "the file could not be written completely";
                return false;
            }
            return true;
        });
    }
    catch (const OutputError&)
    {
        // writeAtomically removed the temporary; say why OpenEXR or the stream failed, where one did.
        if (reason.empty())
            throw;
        throw OutputError(fmt::format("cannot write '{}': {}", shownName, reason));
    }
}

Image readExr(const std::filesystem::path& path)
{
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw AssetError(fmt::format("cannot open '{}': it is a folder", name));
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw AssetError(fmt::format("cannot open '{}': it is not a regular file", name)); // a pipe would block
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw AssetError(errno != 0 ? fmt::format("cannot open '{}': {}", name, std::strerror(errno))
                                    : fmt::format("cannot open '{}'", name));

    // The magic number first, for a clear message instead of OpenEXR's about any other file; then the version
    // field's flags: OpenEXR's InputFile would composite a single-part deep file that has a Z channel (and fail
    // on one without), where this reader rejects deep files alike.
    unsigned char start[8] = {};
    in.read(reinterpret_cast<char*>(start), 8);
    if (in.gcount() < 4 || !Imf::isImfMagic(reinterpret_cast<const char*>(start)))
        throw AssetError(fmt::format("'{}' is not an OpenEXR file", name));
    const int version = int(std::uint32_t(start[4]) | std::uint32_t(start[5]) << 8 | std::uint32_t(start[6]) << 16 |
                            std::uint32_t(start[7]) << 24);
    if (in.gcount() == 8 && !Imf::isMultiPart(version) && Imf::isNonImage(version))
        throw AssetError(fmt::format("'{}' is a deep OpenEXR file (only flat images are read)", name));
    in.clear();
    in.seekg(0);

    try
    {
        Imf::StdIFStream stream(in, name.c_str());
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        if (header.hasType() && Imf::isDeepData(header.type()))
            throw AssetError(fmt::format("'{}' is a deep OpenEXR file (only flat images are read)", name));

        std::string missing;
        for (const char* channel : kChannels)
        {
            const Imf::Channel* found = header.channels().findChannel(channel);
            if (!found)
                missing += (missing.empty() ? "" : ", ") + std::string(channel);
            else if (found->xSampling != 1 || found->ySampling != 1)
                throw AssetError(fmt::format("'{}': channel {} is subsampled ({}x{}), which is not supported", name,
                                             channel, found->xSampling, found->ySampling));
        }
        if (!missing.empty())
            throw AssetError(fmt::format("'{}' has no {} channel{} (its channels: {})", name, missing,
                                         missing.size() > 1 ? "s" : "", channelNames(header)));

        const Imath::Box2i window = header.dataWindow();
        const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
        const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || width * height > kMaxPixels)
            throw AssetError(fmt::format("'{}' has a data window of {}x{} pixels, which is not readable", name,
                                         width, height));

        // The first row first, into memory that is not zero-filled (pages are touched only as OpenEXR writes
        // them): a width that a corrupt header inflated fails here to decode its block, before the whole image
        // is allocated and zero-filled. (A height is bounded by the file's size already: OpenEXR reads a table
        // of 8-byte offsets, one per block of rows, before this.)
        {
            const std::unique_ptr<float[]> row(new float[3 * std::size_t(width)]);
            Imf::FrameBuffer rowBuffer;
            for (int c = 0; c < 3; ++c)
                rowBuffer.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, row.get() + c, window.min, width, 1,
                                                                sizeof(vec3), sizeof(vec3) * std::size_t(width)));
            file.setFrameBuffer(rowBuffer);
            file.readPixels(window.min.y, window.min.y);
        }

        Image image(static_cast<int>(width), static_cast<int>(height));
        Imf::FrameBuffer frameBuffer;
        for (int c = 0; c < 3; ++c)
            frameBuffer.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, channelBase(image, c), window, sizeof(vec3),
                                                              sizeof(vec3) * std::size_t(width)));
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
        return image;
    }
    catch (const AssetError&)
    {
        throw;
    }
    catch (const std::bad_alloc&)
    {
        throw AssetError(fmt::format("cannot read '{}': out of memory (corrupt header?)", name));
    }
    catch (const std::exception& e)
    {
        // Iex::BaseExc (a std::exception) for a corrupt or truncated file; std::length_error and the like for
        // a header whose sizes make no sense.
        throw AssetError(fmt::format("cannot read OpenEXR file '{}': {}", name, oneLine(e.what())));
    }
}
} // namespace rt
