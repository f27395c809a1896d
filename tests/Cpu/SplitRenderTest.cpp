// A frame rendered in parts (the render driver's FramePart: an MPI rank's share, Cluster/SplitRender.h) is
// the frame: the parts' accumulators add up to one render's, sample for sample, under every pixel sampling.
#include <gtest/gtest.h>

#include <cmath>

#include "Cluster/SplitRender.h"
#include "Engine/CpuEngine.h"
#include "RenderTestSupport.h"
#include "Scenes/Catalogue.h"

namespace rt::test
{
namespace
{
struct Traced
{
    std::vector<double> sums;
    RenderResult result;
    std::uint64_t progressTotal = 0;
};

Traced renderPart(const Scene& scene, const RenderSettings& s, const FramePart& part)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    RenderControl control;
    const RenderRequest request{.scene = {.id = scene.id}, .settings = s};
    Traced t;
    t.result = render(engine, request, control, {}, part);
    t.sums = engine.radianceSums();
    t.progressTotal = control.total();
    return t;
}

class SplitRender : public ::testing::TestWithParam<PixelSampling>
{
};

TEST_P(SplitRender, ThreeRanksSharesAddUpToOneRender)
{
    const Scene scene = makeScene("cornell-box-lights");
    RenderSettings s = smallSettings(24, 16, 8, Estimator::NeeMis);
    s.sampling = GetParam();
    const Traced whole = renderPart(scene, s, {});
    const auto spp = static_cast<std::uint32_t>(s.trueSpp());
    std::vector<double> added(whole.sums.size(), 0.0);
    std::uint32_t samples = 0;
    for (int rank = 0; rank < 3; ++rank)
    {
        const FramePart share = cluster::shareOf(spp, rank, 3);
        const Traced part = renderPart(scene, s, share);
        EXPECT_EQ(part.result.stats.trueSpp, static_cast<int>(*share.samples));
        EXPECT_EQ(part.progressTotal, whole.progressTotal) << "progress counts the whole frame on every rank";
        for (std::size_t i = 0; i < added.size(); ++i)
            added[i] += part.sums[i];
        samples += *share.samples;
    }
    EXPECT_EQ(samples, spp);
    // Sums of the same samples in another order: equal to double's rounding. A sample traced twice or missed,
    // or a share drawing another share's random numbers, moves a pixel by a whole sample (~1e-2 here).
    double worst = 0.0;
    for (std::size_t i = 0; i < added.size(); ++i)
        worst = std::max(worst, std::abs(added[i] - whole.sums[i]) / std::max(1e-3, std::abs(whole.sums[i])));
    EXPECT_LT(worst, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(EverySampling, SplitRender,
                         ::testing::Values(PixelSampling::Random, PixelSampling::Stratified,
                                           PixelSampling::Sobol, PixelSampling::Accumulate),
                         [](const ::testing::TestParamInfo<PixelSampling>& p)
                         { return std::string(toString(p.param)); });

TEST(SplitRender, ARankWithNoSampleTracesNothing)
{
    const Scene scene = makeScene("cornell-box-lights");
    const RenderSettings s = smallSettings(8, 1, 4, Estimator::NeeMis);
    const FramePart share = cluster::shareOf(1, 1, 2);
    ASSERT_EQ(*share.samples, 0u);
    const Traced part = renderPart(scene, s, share);
    EXPECT_EQ(part.result.stats.paths, 0u);
    EXPECT_FALSE(part.result.stats.cancelled);
    for (double v : part.sums)
        EXPECT_EQ(v, 0.0);
}
} // namespace
} // namespace rt::test
