// A cost map (Render/CostMap.h) as files: a PNG painted with the heatmap palette that the GPU window's display
// pass uses (Shared/HeatmapPalette.h), with a colour bar, its scale and its unit beneath the image; or the values
// themselves, linear, in a PFM or an OpenEXR (the same value in R, G and B), for a script to read.
#pragma once

#include <filesystem>

#include <nlohmann/json_fwd.hpp>

#include "Image/Image.h"
#include "Render/CostMap.h"

namespace rt
{
/// The figures a heatmap is read by, in the map's unit.
struct CostSummary
{
    double mean = 0.0; // over the pixels
    double median = 0.0;
    double high = 0.0; // the 99th percentile: the top of the PNG's scale (a few pixels above it are clamped)
    double max = 0.0;
};

/// Over the finite values of `map` (zeros when there are none).
CostSummary summarize(const CostMap& map);

/// {"unit", "mean", "median", "p99", "max"}: the stats JSON's "heatmap".
nlohmann::json toJson(const CostMap& map, const CostSummary& summary);

/// The painted heatmap: the map's pixels coloured by value / summary.high (blue cheap, red costly), on a canvas at
/// least kHeatmapMinWidth wide (the map centred), with the colour bar beneath, labelled 0, half and the top of the
/// scale, the unit and the maximum. A pixel whose value is not finite is grey. Linear colours (writePng encodes
/// them). Precondition: !map.empty(), perSample.size() == width x height.
Image paintHeatmap(const CostMap& map);
inline constexpr int kHeatmapMinWidth = 320;
/// Rows paintHeatmap adds beneath the map (bar, labels, unit).
inline constexpr int kHeatmapLegendRows = 66;

enum class HeatmapFormat
{
    Png, // paintHeatmap's picture
    Pfm, // the values, float
    Exr, // the values, float OpenEXR
};
/// By the extension of `path` (.png, .pfm, .exr, in any case); UsageError for another.
HeatmapFormat heatmapFormatOf(const std::filesystem::path& path);

/// Writes `map` to `path` as `format`. Throws AssetError when the file cannot be written.
void writeHeatmap(const std::filesystem::path& path, const CostMap& map, HeatmapFormat format);
} // namespace rt
