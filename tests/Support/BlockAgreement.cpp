#include "Support/BlockAgreement.h"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "Support/RenderWithSettings.h"

namespace rt::test
{
BlockEstimate estimateBlocks(RenderEngine& engine, const Scene& scene, RenderSettings settings)
{
    engine.setScene(scene);
    std::vector<Image> images;
    BlockEstimate b;
    for (int k = 0; k < kAgreementSeeds; ++k)
    {
        settings.seed = 1000u + static_cast<std::uint32_t>(k);
        RenderControl control;
        RenderResult r = renderWithSettings(engine, settings, control);
        b.nonFiniteSamples += r.stats.nanSamples + r.stats.infSamples;
        images.push_back(std::move(r.image));
    }
    const int w = images[0].width();
    const int h = images[0].height();
    b.blocksX = w / kAgreementBlock;
    b.blocksY = h / kAgreementBlock;
    for (int by = 0; by < b.blocksY; ++by)
        for (int bx = 0; bx < b.blocksX; ++bx)
        {
            double sum = 0.0;
            double pixelVarianceSum = 0.0;
            for (int y = by * kAgreementBlock; y < (by + 1) * kAgreementBlock; ++y)
                for (int x = bx * kAgreementBlock; x < (bx + 1) * kAgreementBlock; ++x)
                {
                    double s = 0.0;
                    double s2 = 0.0;
                    for (const Image& image : images)
                    {
                        const double l = luminance(image.at(x, y));
                        s += l;
                        s2 += l * l;
                    }
                    const double mean = s / kAgreementSeeds;
                    sum += mean;
                    // Variance of this pixel's mean over seeds.
                    pixelVarianceSum += std::max(0.0, s2 / kAgreementSeeds - mean * mean) / (kAgreementSeeds - 1);
                }
            constexpr double kPixels = kAgreementBlock * kAgreementBlock;
            b.mean.push_back(sum / kPixels);
            b.variance.push_back(pixelVarianceSum / (kPixels * kPixels));
        }
    return b;
}

std::vector<std::string> disagreeingBlocks(const BlockEstimate& a, const BlockEstimate& b, double maxZ)
{
    std::vector<std::string> out;
    if (a.mean.size() != b.mean.size())
        return {fmt::format("{} blocks against {}", a.mean.size(), b.mean.size())};
    for (std::size_t i = 0; i < a.mean.size(); ++i)
    {
        const double difference = b.mean[i] - a.mean[i];
        const double rounding = 1e-5 * std::max(std::fabs(a.mean[i]), std::fabs(b.mean[i]));
        const double sigma = std::sqrt(a.variance[i] + b.variance[i] + rounding * rounding);
        const double z = sigma > 0.0 ? difference / sigma : 0.0;
        if (std::fabs(z) > maxZ)
            out.push_back(fmt::format("block ({}, {}) luminance A {}, B {}, sigma {}, z {:.2f}", i % a.blocksX,
                                      i / a.blocksX, a.mean[i], b.mean[i], sigma, z));
    }
    return out;
}
} // namespace rt::test
