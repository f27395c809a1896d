// restir-di on the GPU engine (Shaders/Restir/, RestirPipeline, GpuEngine's passes): the same estimator as the
// CPU's, sample for sample (both engines draw the same numbers for the same pixel, sample and stream, so their
// images agree pixel by pixel up to float rounding), unbiased against nee-mis on its own (heavy), a cancelled
// batch put back, and its memory stated. The CPU's side: tests/Cpu/RestirTest.cpp.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "Render/EngineRegistry.h"
#include "Scenes/Catalogue.h"
#include "GpuTestEnvironment.h"
#include "Support/RestirChecks.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
struct PixelAgreement
{
    double meanRatio = 0.0; // GPU image mean / CPU image mean
    double farPixels = 0.0; // fraction of pixels whose luminance differs by more than 1e-3 relative (+ 1e-4)
};

PixelAgreement comparePixels(const Image& gpu, const Image& cpu)
{
    double g = 0.0, c = 0.0;
    std::size_t far = 0;
    for (int y = 0; y < cpu.height(); ++y)
        for (int x = 0; x < cpu.width(); ++x)
        {
            const double a = luminance(gpu.at(x, y));
            const double b = luminance(cpu.at(x, y));
            g += a;
            c += b;
            far += std::abs(a - b) > 1e-3 * std::abs(b) + 1e-4 ? 1 : 0;
        }
    return {c > 0.0 ? g / c : 0.0, double(far) / (double(cpu.width()) * cpu.height())};
}

/// cornell-box-lights at 32 px, 4 spp (temporal and spatial reuse from the second iteration on), depth 8.
RenderSettings agreementSettings(const Scene& scene)
{
    RenderSettings s = ::rt::test::settingsFor(scene, 32, 4, 8);
    s.estimator = Estimator::RestirDi;
    return s;
}

// The engines draw every number of a (seed, pixel, sample) from the same streams: the camera path, the 32
// candidates, the neighbours, the reservoirs' choices. So the GPU's image is the CPU's up to float rounding (a
// GPU's sin, cos and fused multiply-adds), in the unbiased and the biased combination, without history and with
// another --restir-radius: were a pass, a combination or the history wrong on one engine, whole regions would
// differ.
TEST(GpuRestir, TheImageIsTheCpuEnginesPixelForPixel)
{
    RT_REQUIRE_GPU();
    const Scene scene = makeScene("cornell-box-lights");
    const auto cpuEngine = engines::make(EngineKind::Multi);
    cpuEngine->setScene(scene);
    for (int variant = 0; variant < 4; ++variant)
    {
        RenderSettings s = agreementSettings(scene);
        s.restirBiased = variant == 1;
        s.restirTemporalCap = variant == 2 ? 0 : s.restirTemporalCap;
        s.restirRadius = variant == 3 ? 4 : s.restirRadius;
        SCOPED_TRACE(variant == 0   ? "unbiased"
                     : variant == 1 ? "biased"
                     : variant == 2 ? "no temporal reuse"
                                    : "a radius of 4 px");
        RenderControl control;
        const RenderResult cpu = renderWithSettings(*cpuEngine, s, control);
        const RenderResult gpu = renderOnGpu(scene, s);
        const PixelAgreement a = comparePixels(gpu.image, cpu.image);
        EXPECT_NEAR(a.meanRatio, 1.0, 1e-4);
        EXPECT_LT(a.farPixels, 0.01);
        EXPECT_EQ(gpu.stats.nanSamples + gpu.stats.infSamples, 0u);
    }
}

// A batch cancelled inside its shading pass (two rows per submission, a few bands in) is put back, and the next
// iteration would start without history: the image equals a clean render of the iterations that completed.
TEST(GpuRestir, ACancelledBatchIsPutBack)
{
    RT_REQUIRE_GPU();
    expectCancelInsideABandedBatchPutsTheBatchBack("cornell-box-lights", 32, Estimator::RestirDi);
}

TEST(GpuRestir, ReservoirsTakeAtMost64BytesPerPixelAndTheCombinationIsNamed)
{
    RT_REQUIRE_GPU();
    ::rt::test::expectRestirStats(*sharedEngine());
}

class GpuRestirUnbiased : public ::testing::TestWithParam<std::string>
{
};

// The unbiasedness test (Support/RestirChecks.h) on the GPU engine alone: its restir-di against its own
// nee-mis. Minutes on lavapipe: label heavy.
TEST_P(GpuRestirUnbiased, AgainstNeeMis)
{
    RT_REQUIRE_GPU();
    ::rt::test::expectRestirUnbiased(*sharedEngine(), GetParam());
}

std::string sceneName(const ::testing::TestParamInfo<std::string>& param)
{
    std::string name = param.param;
    std::erase(name, '-');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Heavy, GpuRestirUnbiased,
                         ::testing::Values("cornell-box-lights", "many-lights", "lamp-room"), sceneName);
} // namespace
} // namespace rt::gpu::test
