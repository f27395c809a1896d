#include "Image/Heatmap.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "Check.h"
#include "Error.h"
#include "IO/FileExtension.h"
#include "Image/ExrIO.h"
#include "Image/ImageIO.h"
#include "Shared/HeatmapPalette.h"

namespace rt
{
namespace
{
/// The value below which `fraction` of the sorted values lie (nearest rank).
double quantile(const std::vector<float>& sorted, double fraction)
{
    const auto rank = static_cast<std::size_t>(std::ceil(fraction * double(sorted.size())));
    return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

/// `text` in stb_easy_font's glyphs (quads of about 7 px high) at (x, y), top-left, in `colour`.
void drawText(Image& image, int x, int y, const std::string& text, const vec3& colour)
{
    std::vector<char> quads(16 * 4 * 64 * std::max<std::size_t>(text.size(), 1));
    std::string printable = text;
    const int count = stb_easy_font_print(0.0f, 0.0f, printable.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size()));
    // Each quad: 4 vertices of 16 bytes (x, y, z as floats, then a colour), axis-aligned.
    for (int q = 0; q < count; ++q)
    {
        const auto* v = reinterpret_cast<const float*>(quads.data() + std::size_t(q) * 64);
        const int x0 = x + static_cast<int>(v[0]), y0 = y + static_cast<int>(v[1]);
        const int x1 = x + static_cast<int>(v[8]), y1 = y + static_cast<int>(v[9]);
        for (int py = std::max(y0, 0); py < std::min(y1, image.height()); ++py)
            for (int px = std::max(x0, 0); px < std::min(x1, image.width()); ++px)
                image.at(px, py) = colour;
    }
}

int textWidth(const std::string& text)
{
    std::string printable = text;
    return stb_easy_font_width(printable.data());
}

std::string label(double value)
{
    if (value == 0.0)
        return "0";
    return std::abs(value) >= 100.0 ? fmt::format("{:.0f}", value) : fmt::format("{:.3g}", value);
}
} // namespace

CostSummary summarize(const CostMap& map)
{
    std::vector<float> values;
    values.reserve(map.perSample.size());
    for (float v : map.perSample)
        if (std::isfinite(v))
            values.push_back(v);
    if (values.empty())
        return {};
    std::sort(values.begin(), values.end());
    CostSummary s;
    double sum = 0.0;
    for (float v : values)
        sum += v;
    s.mean = sum / double(values.size());
    s.median = quantile(values, 0.5);
    s.high = quantile(values, 0.99);
    s.max = values.back();
    return s;
}

nlohmann::json toJson(const CostMap& map, const CostSummary& summary)
{
    return {{"unit", map.unit},     {"width", map.width}, {"height", map.height}, {"mean", summary.mean},
            {"median", summary.median}, {"p99", summary.high}, {"max", summary.max}};
}

Image paintHeatmap(const CostMap& map)
{
    RT_CHECK(!map.empty() && map.perSample.size() == std::size_t(map.width) * std::size_t(map.height));
    const CostSummary summary = summarize(map);
    const double top = summary.high > 0.0 ? summary.high : std::max(summary.max, 1e-30);
    const int width = std::max(map.width, kHeatmapMinWidth);
    Image image(width, map.height + kHeatmapLegendRows);
    const int left = (width - map.width) / 2;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
        {
            const float v = map.perSample[std::size_t(y) * std::size_t(map.width) + std::size_t(x)];
            // A value that is not finite (a pixel that traced nothing) is drawn grey, apart from the scale.
            image.at(left + x, y) = std::isfinite(v) ? vec3(shader::heatmapColor(float(double(v) / top)))
                                                     : vec3(0.2f);
        }
    // The bar: the palette from 0 (left) to the top of the scale (right), with ticks at 0, half and the top.
    constexpr int margin = 12;
    const int barTop = map.height + 8;
    const int barRows = 14;
    const int barWidth = width - 2 * margin;
    for (int x = 0; x < barWidth; ++x)
    {
        const vec3 colour(shader::heatmapColor(float(x) / float(std::max(barWidth - 1, 1))));
        for (int y = barTop; y < barTop + barRows; ++y)
            image.at(margin + x, y) = colour;
    }
    const vec3 white(1.0f);
    const int labelTop = barTop + barRows + 4;
    const std::string labels[3] = {label(0.0), label(0.5 * top), label(top)};
    const int tickX[3] = {margin, margin + barWidth / 2, margin + barWidth - 1};
    for (int i = 0; i < 3; ++i)
    {
        for (int y = barTop + barRows; y < labelTop - 1; ++y)
            image.at(tickX[i], y) = white;
        const int w = textWidth(labels[i]);
        const int x = i == 0 ? margin : i == 1 ? tickX[i] - w / 2 : margin + barWidth - w;
        drawText(image, x, labelTop, labels[i], white);
    }
    drawText(image, margin, labelTop + 14, map.unit, white);
    drawText(image, margin, labelTop + 26,
             fmt::format("scale to the 99th percentile; max {}", label(summary.max)), vec3(0.6f));
    return image;
}

HeatmapFormat heatmapFormatOf(const std::filesystem::path& path)
{
    const std::string extension = lowercaseExtension(path);
    if (extension == ".png")
        return HeatmapFormat::Png;
    if (extension == ".pfm")
        return HeatmapFormat::Pfm;
    if (extension == ".exr")
        return HeatmapFormat::Exr;
    throw UsageError(fmt::format("a heatmap is written as .png, .pfm or .exr, not '{}'", path.string()));
}

void writeHeatmap(const std::filesystem::path& path, const CostMap& map, HeatmapFormat format)
{
    if (format == HeatmapFormat::Png)
    {
        writePng(path, paintHeatmap(map));
        return;
    }
    Image values(map.width, map.height);
    for (std::size_t i = 0; i < values.pixelCount(); ++i)
        values.data()[i] = vec3(map.perSample[i]);
    if (format == HeatmapFormat::Pfm)
        writePfm(path, values);
    else
        writeExr(path, values, ExrPixelType::Float);
}
} // namespace rt
