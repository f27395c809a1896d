// OpenEXR files of the linear radiance images (OpenEXR 3.x C++ library). The writer goes through a temporary
// file renamed into place, as every writer of Image/ImageIO.h does, so a failed or cancelled write never leaves
// a half-written file behind; failures throw OutputError naming the path. The reader throws AssetError naming
// the file, never crashes on a corrupt or truncated one.
#pragma once

#include <filesystem>

#include "Image/Image.h"

namespace rt
{
/// The stored type of the R, G, B channels of writeExr.
enum class ExrPixelType
{
    /// 16-bit IEEE half: 11 significant bits (relative error at most 2^-11 for normal values), half the size.
    Half,
    /// 32-bit IEEE float: the image bit for bit.
    Float,
};

/// Writes `image` as a single-part scanline OpenEXR file: channels "R", "G", "B" (linear, of `type`),
/// ZIP_COMPRESSION (lossless zlib deflate over blocks of 16 scanlines), increasing-y line order (row 0 of the
/// image is the file's top row, y = 0), display window = data window = (0, 0) - (width - 1, height - 1),
/// pixel aspect ratio 1, no chromaticities attribute (readers assume Rec. 709 / sRGB primaries, the image's).
///
/// Float stores every value bit for bit (-0, subnormals, infinities, NaN with its payload).
/// Half rounds each value to the nearest half (ties to even), except:
///  - finite values beyond half's range (|v| > 65504, which would round to infinity) are clamped to
///    +-65504, the largest half, so a very bright pixel stays a bright pixel and not an infinity;
///  - infinities stay infinities (they were not finite to begin with), NaN stays NaN (payload not kept);
///  - values below half's smallest normal (|v| < 2^-14 = 6.1e-5) become half subnormals, with an absolute
///    error of at most 2^-25 (their relative precision drops); |v| <= 2^-25 rounds to a zero of v's sign.
///
/// The file is written to a temporary sibling (createTemporarySibling) and renamed over `path` only once OpenEXR
/// has finished it and every byte reached the stream. Throws OutputError naming `path` (and OpenEXR's or the
/// C library's reason) for a missing or unwritable folder, a full disk, an empty image; no file is left
/// behind, neither `path` nor the temporary.
void writeExr(const std::filesystem::path& path, const Image& image, ExrPixelType type = ExrPixelType::Half);

/// Reads the R, G, B channels of an OpenEXR file: scanline or tiled (level 0 of a mip- or rip-map), any line
/// order and compression, channels of type half, float or uint (converted to float; uint exactly up to 2^24).
/// Other channels (A, Z, layers such as "diffuse.R") are ignored. Of a multi-part file, the first part is read.
///
/// The returned image is the file's data window: its pixel (x, y) is the file's pixel
/// (dataWindow.min.x + x, dataWindow.min.y + y), row 0 = the data window's top row. The display window is
/// not applied: a data window smaller than, larger than or offset from the display window is returned as it
/// is stored, without padding or cropping (writeExr always writes the two equal).
///
/// Throws AssetError with a one-line message naming the file for: a missing or unreadable file, a file that
/// is not OpenEXR, a deep-data file, a missing R, G or B channel (the message names the missing ones and the
/// channels the file has), subsampled R/G/B channels, a data window of more than 2^28 pixels (16384 x 16384;
/// a guard against corrupt headers), a corrupt or truncated file (OpenEXR's reason).
Image readExr(const std::filesystem::path& path);
} // namespace rt
