#include "Support/RestirChecks.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "Math/Math.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"

namespace rt::test
{
namespace
{
constexpr int kBlock = 16; // pixels per block side
} // namespace

OverSeeds renderSeeds(RenderEngine& engine, RenderSettings settings, int seeds, std::uint32_t firstSeed)
{
    const int bx = settings.width / kBlock;
    const int by = settings.height() / kBlock;
    std::vector<double> sum(std::size_t(bx * by) + 1, 0.0), sumSq(sum.size(), 0.0);
    for (int k = 0; k < seeds; ++k)
    {
        settings.seed = firstSeed + std::uint32_t(k);
        RenderControl control;
        const RenderResult r = renderWithSettings(engine, settings, control);
        std::vector<double> means(sum.size(), 0.0);
        for (int y = 0; y < by * kBlock; ++y)
            for (int x = 0; x < bx * kBlock; ++x)
            {
                const double l = luminance(r.image.at(x, y));
                means[std::size_t((y / kBlock) * bx + x / kBlock)] += l / (kBlock * kBlock);
                means.back() += l / (double(bx * by) * kBlock * kBlock);
            }
        for (std::size_t i = 0; i < sum.size(); ++i)
        {
            sum[i] += means[i];
            sumSq[i] += means[i] * means[i];
        }
    }
    OverSeeds out;
    for (std::size_t i = 0; i < sum.size(); ++i)
    {
        const double m = sum[i] / seeds;
        const double v = std::max(0.0, (sumSq[i] / seeds - m * m) * seeds / (seeds - 1.0)) / seeds;
        if (i + 1 == sum.size())
        {
            out.imageMean = m;
            out.imageVariance = v;
        }
        else
        {
            out.mean.push_back(m);
            out.variance.push_back(v);
        }
    }
    return out;
}

double zScore(double a, double va, double b, double vb)
{
    const double sigma = std::sqrt(va + vb);
    return sigma > 0.0 ? (a - b) / sigma : (a == b ? 0.0 : 1e9);
}

RenderSettings restirSettings(const Scene& scene)
{
    RenderSettings s;
    s.width = 48;
    s.spp = 16;
    s.depth = 8;
    s.estimator = Estimator::RestirDi;
    s.aspect = scene.defaults.aspect;
    s.sampling = PixelSampling::Random;
    s.seed = 7;
    s.unidirectionalLight = scene.defaults.unidirectionalLight;
    return s;
}

OverSeeds neeMisReference(RenderEngine& engine, const Scene& scene)
{
    RenderSettings s = restirSettings(scene);
    s.estimator = Estimator::NeeMis;
    s.spp = 128;
    return renderSeeds(engine, s, 8, 5000);
}

void expectRestirUnbiased(RenderEngine& engine, const std::string& id)
{
    const Scene scene = makeScene(id);
    engine.setScene(scene);
    const OverSeeds ref = neeMisReference(engine, scene);
    const OverSeeds restir = renderSeeds(engine, restirSettings(scene), 32, 100);
    for (std::size_t i = 0; i < ref.mean.size(); ++i)
        EXPECT_LT(std::abs(zScore(restir.mean[i], restir.variance[i], ref.mean[i], ref.variance[i])), 4.0)
            << id << " block " << i << ": restir-di " << restir.mean[i] << ", nee-mis " << ref.mean[i];
    const double z = zScore(restir.imageMean, restir.imageVariance, ref.imageMean, ref.imageVariance);
    EXPECT_LT(std::abs(z), 4.0) << id << " image: restir-di " << restir.imageMean << ", nee-mis " << ref.imageMean;
}

void expectRestirStats(RenderEngine& engine)
{
    const Scene scene = makeScene("cornell-box-lights");
    engine.setScene(scene);
    RenderSettings s = restirSettings(scene);
    s.spp = 1;
    const auto statsOf = [&](const RenderSettings& settings) {
        RenderControl control;
        return renderWithSettings(engine, settings, control).stats.toJson();
    };
    const nlohmann::json j = statsOf(s);
    ASSERT_TRUE(j.contains("restir")) << j.dump();
    EXPECT_LE(j["restir"]["reservoirs_bytes_per_pixel"].get<int>(), 64);
    EXPECT_EQ(j["restir"]["reservoirs_bytes"].get<std::uint64_t>(),
              j["restir"]["reservoirs_bytes_per_pixel"].get<std::uint64_t>() * std::uint64_t(s.width) *
                  std::uint64_t(s.height()));
    EXPECT_EQ(j["restir"]["combination"], "unbiased");
    s.restirBiased = true;
    EXPECT_EQ(statsOf(s)["restir"]["combination"], "biased");
    s.estimator = Estimator::NeeMis;
    EXPECT_FALSE(statsOf(s).contains("restir"));
}
} // namespace rt::test
