// --heatmap's files (Image/Heatmap.h): the summary's quantiles, the painted PNG's layout and palette (the GPU
// window's, Shared/HeatmapPalette.h), and the PFM's values as recorded.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include "Error.h"
#include "Image/Heatmap.h"
#include "Image/ImageIO.h"
#include "Shared/HeatmapPalette.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// 1, 2, ..., width x height row by row: value k at pixel k - 1.
CostMap ramp(int width, int height)
{
    CostMap map{.width = width, .height = height, .unit = "microseconds per sample"};
    for (int i = 0; i < width * height; ++i)
        map.perSample.push_back(float(i + 1));
    return map;
}
} // namespace

TEST(Heatmap, SummaryIsOverTheFiniteValuesWithNearestRankQuantiles)
{
    CostMap map = ramp(20, 10); // 1 .. 200
    map.perSample[0] = std::numeric_limits<float>::quiet_NaN(); // 2 .. 200 are left: 199 values
    const CostSummary s = summarize(map);
    EXPECT_DOUBLE_EQ(s.mean, 101.0);
    EXPECT_DOUBLE_EQ(s.median, 101.0); // rank ceil(0.5 x 199) = 100: the 100th of 2 .. 200
    EXPECT_DOUBLE_EQ(s.high, 199.0); // rank ceil(0.99 x 199) = 198
    EXPECT_DOUBLE_EQ(s.max, 200.0);
    const nlohmann::json j = toJson(map, s);
    EXPECT_EQ(j.at("unit"), "microseconds per sample");
    EXPECT_DOUBLE_EQ(j.at("p99").get<double>(), 199.0);
    EXPECT_EQ(summarize(CostMap{}).max, 0.0);
}

TEST(Heatmap, PaintsTheMapCentredAboveItsColourBarWithThePaletteOfTheWindow)
{
    CostMap map = ramp(40, 10); // 1 .. 400
    map.perSample[5] = std::numeric_limits<float>::infinity();
    const float top = 397.0f; // the 99th percentile of the 399 finite values: rank 396 of 1 .. 5, 7 .. 400
    ASSERT_EQ(summarize(map).high, top);
    const Image image = paintHeatmap(map);
    ASSERT_EQ(image.width(), kHeatmapMinWidth);
    ASSERT_EQ(image.height(), 10 + kHeatmapLegendRows);
    const int left = (kHeatmapMinWidth - 40) / 2;
    const auto expect = [&](int x, int y, float t) {
        const vec3 want(shader::heatmapColor(t));
        const vec3 got = image.at(left + x, y);
        EXPECT_NEAR(got.x, want.x, 1e-6f) << x << "," << y;
        EXPECT_NEAR(got.y, want.y, 1e-6f) << x << "," << y;
        EXPECT_NEAR(got.z, want.z, 1e-6f) << x << "," << y;
    };
    expect(0, 0, 1.0f / top); // nearly blue
    expect(0, 5, 201.0f / top);
    expect(39, 9, 1.0f); // 400, above the top: red
    EXPECT_EQ(image.at(left + 5, 0), vec3(0.2f)) << "a value that is not finite is grey";
    EXPECT_EQ(image.at(left - 1, 0), vec3(0.0f)) << "the canvas beside a narrow map is black";
    // The bar beneath runs blue to red, left to right.
    const int barRow = 10 + 10;
    EXPECT_GT(image.at(20, barRow).z, 0.9f);
    EXPECT_LT(image.at(20, barRow).x, 0.1f);
    EXPECT_GT(image.at(kHeatmapMinWidth - 20, barRow).x, 0.9f);
    EXPECT_LT(image.at(kHeatmapMinWidth - 20, barRow).z, 0.1f);
    // Text is drawn in the legend: some white pixels beneath the bar.
    int white = 0;
    for (int y = barRow + 10; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            white += image.at(x, y) == vec3(1.0f);
    EXPECT_GT(white, 50);
}

TEST(Heatmap, WritesThePaintedPngOrTheValuesByFormat)
{
    const test::ScratchDir dir;
    const CostMap map = ramp(400, 3); // wider than the least canvas: no margin
    writeHeatmap(dir.path() / "cost.png", map, heatmapFormatOf("cost.PNG"));
    int w = 0, h = 0, channels = 0;
    stbi_uc* decoded = stbi_load((dir.path() / "cost.png").string().c_str(), &w, &h, &channels, 0);
    ASSERT_NE(decoded, nullptr);
    stbi_image_free(decoded);
    EXPECT_EQ(w, 400);
    EXPECT_EQ(h, 3 + kHeatmapLegendRows);

    writeHeatmap(dir.path() / "cost.pfm", map, heatmapFormatOf("cost.pfm"));
    const Image values = readPfm(dir.path() / "cost.pfm");
    ASSERT_EQ(values.width(), 400);
    ASSERT_EQ(values.height(), 3);
    EXPECT_EQ(values.at(0, 0), vec3(1.0f));
    EXPECT_EQ(values.at(399, 2), vec3(1200.0f));
    EXPECT_THROW(heatmapFormatOf("cost.jpg"), UsageError);
}
} // namespace rt
