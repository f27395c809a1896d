// The wavefront integrator (RayTracingGPU/Engine/WavefrontPipeline.h) against the megakernel, analytic values
// and the CPU engine: the same estimator (the same shading code), an image that does not depend on how the
// paths are cut into waves, cancellation, and its per-kernel timings.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Engine/SceneTracer.h"
#include "Render/EngineRegistry.h"
#include "GpuTestEnvironment.h"
#include "Scenes/Catalogue.h"
#include "Support/BlockAgreement.h"
#include "Support/CatalogueCases.h"
#include "Support/PairedDifference.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
using ::rt::test::differingPixels;
using ::rt::test::pairedZ;

/// Runs its test with the shared engine on the wavefront integrator (waves of `capacity` paths; 0: the
/// device's), then puts the suite's integrator back; no validation message may come.
class GpuWavefront : public ::testing::Test
{
protected:
    void SetUp() override
    {
        RT_REQUIRE_GPU();
        ASSERT_TRUE(sharedEngine()->validationEnabled());
        m_messagesBefore = sharedEngine()->validationMessages();
        useWavefront();
    }
    void TearDown() override
    {
        if (sharedEngine())
        {
            sharedEngine()->setIntegrator(suiteIntegrator());
            EXPECT_EQ(sharedEngine()->validationMessages(), m_messagesBefore) << "Vulkan validation messages";
        }
    }
    static void useWavefront(std::uint32_t capacity = 0)
    {
        sharedEngine()->setIntegrator(GpuIntegrator::Wavefront, capacity);
    }

private:
    std::uint64_t m_messagesBefore = 0;
};

struct IntegratorCase
{
    std::string scene;
    Estimator estimator;
    PixelSampling sampling = PixelSampling::Random;
};

void PrintTo(const IntegratorCase& c, std::ostream* os)
{
    *os << c.scene << " (" << toString(c.estimator) << ", " << toString(c.sampling) << ")";
}

class GpuWavefrontCases : public GpuWavefront, public ::testing::WithParamInterface<IntegratorCase>
{
};

// Each path shades its vertices with the megakernel's code (PathVertex.glsl) and the same numbers, and is
// summed in sample order: lavapipe renders the megakernel's image bit for bit. Another driver compiles the
// two pipelines' arithmetic apart (a compute kernel against ray-tracing stages), and a float comparison that
// flips sends a path elsewhere (the H100: relMSE 1e-6 to 1e-4 between the two on cornell-box-lights at 1000
// spp), so the check is the paired z of the difference, which a left-out term (emission, a shadow ray, the
// MIS weight) moves far beyond 4.
TEST_P(GpuWavefrontCases, RendersTheMegakernelsImage)
{
    const IntegratorCase& c = GetParam();
    const Scene scene = makeScene(c.scene);
    RenderSettings s = ::rt::test::settingsFor(scene, 24, 4, 12);
    s.estimator = c.estimator;
    s.sampling = c.sampling;
    const RenderResult wavefront = renderOnGpu(scene, s);
    sharedEngine()->setIntegrator(GpuIntegrator::Megakernel);
    const RenderResult megakernel = renderOnGpu(scene, s);

    EXPECT_EQ(wavefront.stats.nanSamples + wavefront.stats.infSamples,
              megakernel.stats.nanSamples + megakernel.stats.infSamples);
    EXPECT_GT(wavefront.image.mean().x + wavefront.image.mean().y + wavefront.image.mean().z, 0.0f);
    EXPECT_LT(std::abs(pairedZ(wavefront.image, megakernel.image)), 4.0)
        << differingPixels(wavefront.image, megakernel.image) << " pixels differ beyond round-off";
}

// Every estimator; media and moving spheres (their intersection shaders find the path's pixel and sample
// through the launch's queue); image and noise textures, metal and glass (rtnw-final); many emitters of every
// shape; Sobol samples (their state travels with the path).
INSTANTIATE_TEST_SUITE_P(
    Cases, GpuWavefrontCases,
    ::testing::Values(IntegratorCase{"cornell-box-lights", Estimator::NeeMis},
                      IntegratorCase{"cornell-box-lights", Estimator::Nee},
                      IntegratorCase{"cornell-box-lights", Estimator::Mixture},
                      IntegratorCase{"cornell-box-lights", Estimator::BsdfOnly},
                      IntegratorCase{"cornell-box-lights", Estimator::NeeMis, PixelSampling::Sobol},
                      IntegratorCase{"rtnw-final", Estimator::Mixture},
                      IntegratorCase{"rtnw-cornell-smoke", Estimator::NeeMis},
                      IntegratorCase{"rtnw-motion-blur", Estimator::BsdfOnly},
                      IntegratorCase{"triangle-lights", Estimator::NeeMis},
                      IntegratorCase{"many-lights", Estimator::NeeMis, PixelSampling::Stratified}),
    [](const ::testing::TestParamInfo<IntegratorCase>& param) {
        return ::rt::test::testNameOf(param.param.scene + "-" + toString(param.param.estimator) + "-" +
                                      toString(param.param.sampling));
    });

// A path's arithmetic does not depend on the other paths of its wave nor on the order the queues hold them
// in (atomics decide that order), and each pixel adds its samples in sample order: waves of 64 K, 97 and 3
// paths (3 splits the 4 samples of a pixel between two waves) give the same image bit for bit, on any driver.
// A wave that summed a pixel's samples out of order, or traced a queue entry twice, breaks this.
TEST_F(GpuWavefront, TheWaveSizeDoesNotChangeTheImage)
{
    for (const std::string id : {"cornell-box-lights", "rtnw-cornell-smoke"})
    {
        const Scene scene = makeScene(id);
        RenderSettings s = ::rt::test::settingsFor(scene, 16, 4, 12);
        s.estimator = Estimator::NeeMis;
        useWavefront(1u << 16);
        const RenderResult large = renderOnGpu(scene, s);
        EXPECT_EQ(sharedEngine()->tracer().waveCapacity(), 1u << 16);
        for (const std::uint32_t capacity : {97u, 3u})
        {
            useWavefront(capacity);
            const RenderResult small = renderOnGpu(scene, s);
            EXPECT_EQ(small.image.pixels(), large.image.pixels()) << id << ", waves of " << capacity << " paths";
            EXPECT_EQ(small.stats.nanSamples, large.stats.nanSamples);
        }
    }
}

// A frame's first wave starts from the segments the last frame of the same kind of path needed (not from 8):
// the submissions change, not the paths. In waves of 97 paths (many waves, each learning) on one scene: a frame
// looking away from the box, whose paths all leave the scene at their first segment, teaches one segment; the box's
// next frame then starts every wave below its paths' need and must still finish them: the image of a frame that
// started from 8. Then depth 3 and depth 12 again (each kind of path its own start): the same image again.
TEST_F(GpuWavefront, FramesThatStartFromTheLearnedSegmentsRenderTheSameImage)
{
    const Scene scene = makeScene("rtnw-cornell-smoke");
    RenderSettings deep = ::rt::test::settingsFor(scene, 16, 4, 12);
    deep.estimator = Estimator::NeeMis;
    RenderSettings shallow = deep;
    shallow.depth = 3;
    useWavefront(97);
    GpuEngine& engine = *sharedEngine();
    engine.setScene(scene);
    RenderControl control;
    const RenderResult first = renderWithSettings(engine, deep, control);
    CameraDesc away = scene.camera;
    away.lookAt = away.lookFrom + (away.lookFrom - scene.camera.lookAt);
    const RenderResult sky = render(engine, {.scene = {.id = scene.id}, .settings = deep, .camera = away}, control);
    // Black: the scene's background, so every camera ray of that frame left the scene.
    ASSERT_TRUE(std::all_of(sky.image.pixels().begin(), sky.image.pixels().end(),
                            [](const vec3& p) { return p == vec3(0.0f); }));
    const RenderResult fromOne = renderWithSettings(engine, deep, control);
    EXPECT_EQ(fromOne.image.pixels(), first.image.pixels()) << "waves started from one segment";
    const RenderResult between = renderWithSettings(engine, shallow, control);
    const RenderResult again = renderWithSettings(engine, deep, control);
    EXPECT_EQ(again.image.pixels(), first.image.pixels());
    EXPECT_NE(between.image.pixels(), first.image.pixels()) << "depth 3 renders another image";
}

// The furnace converges to Le / (1 - a) in every pixel (GpuFurnace.* on the suite's integrator).
TEST_F(GpuWavefront, TheFurnaceGivesLeOverOneMinusAlbedo)
{
    expectFurnaceOnGpu(0.8f, 0.25f, Estimator::NeeMis, 16);
    expectFurnaceOnGpu(0.5f, 0.5f, Estimator::Mixture, 16);
}

// The estimator against the other engine, block by block (tests/Support/BlockAgreement.h).
TEST_F(GpuWavefront, AgreesWithTheCpuEngine)
{
    const Scene scene = makeScene("cornell-box-lights");
    RenderSettings s = ::rt::test::settingsFor(scene, 32, 16, 16);
    const auto cpuEngine = engines::make(EngineKind::Multi);
    const auto failures = ::rt::test::disagreeingBlocks(::rt::test::estimateBlocks(*cpuEngine, scene, s),
                                                        ::rt::test::estimateBlocks(*sharedEngine(), scene, s),
                                                        ::rt::test::kMaxZ);
    for (const std::string& f : failures)
        ADD_FAILURE() << "(A = CPU, B = GPU wavefront): " << f;
}

// A batch cut into bands is put back when cancelled between two of them (GpuEngine's snapshot), whatever
// traces the bands: the image is a complete render of its true spp, bit for bit.
TEST_F(GpuWavefront, CancelInsideABandedBatchPutsTheBatchBack)
{
    expectCancelInsideABandedBatchPutsTheBatchBack("cornell-box-lights", 32);
}

// The wavefront's waves are indices in the frame's row order: bands of interleaved rows give the image of one
// submission per batch.
TEST_F(GpuWavefront, BandsGiveTheImageOfOneSubmission)
{
    expectBandsGiveTheImageOfOneSubmission("cornell-box-lights", 24);
}

// A wave's pixel indices are positions in the frame's row order: one pass traces every sixteenth row.
TEST_F(GpuWavefront, OnePassTracesEverySixteenthRow)
{
    expectOnePassTracesEverySixteenthRow(GpuIntegrator::Wavefront);
}

// Each kernel's GPU time is in the stats (a timestamp after every kernel), within the launches' own total.
TEST_F(GpuWavefront, StageTimesAreWithinTheTrace)
{
    if (sharedEngine()->context().device().properties().timestampValidBits == 0)
        GTEST_SKIP() << "the device's queue has no timestamps";
    const Scene scene = makeScene("cornell-box-lights");
    const RenderResult r = renderOnGpu(scene, ::rt::test::settingsFor(scene, 16, 2, 8));
    const std::map<std::string, double>& stages = r.stats.stageSeconds;
    double kernels = 0.0;
    for (const char* stage : {"wave_generate_gpu", "wave_extend_gpu", "wave_shade_gpu", "wave_shadow_gpu",
                              "wave_accumulate_gpu", "wave_prepare_gpu"})
    {
        ASSERT_EQ(stages.count(stage), 1u) << stage;
        EXPECT_GT(stages.at(stage), 0.0) << stage;
        kernels += stages.at(stage);
    }
    EXPECT_LE(kernels, stages.at("trace_gpu") * 1.0001);
    EXPECT_NE(r.stats.frameConfiguration.find("integrator wavefront"), std::string::npos) << r.stats.frameConfiguration;
}
} // namespace
} // namespace rt::gpu::test
