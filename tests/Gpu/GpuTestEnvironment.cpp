#include "GpuTestEnvironment.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <thread>

#include "Engine/BandPlan.h"
#include "Engine/GpuContext.h"
#include "Engine/RenderTarget.h"
#include "Engine/SceneTracer.h"
#include "Error.h"
#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"
#include "Shared/BandOrder.h"
#include "Vulkan/CommandBuffer.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
struct Shared
{
    std::unique_ptr<GpuEngine> engine;
    std::string error;
};

Shared& shared()
{
    static Shared s = [] {
        Shared out;
        try
        {
            out.engine =
                std::make_unique<GpuEngine>(GpuEngineOptions{.validation = true, .integrator = suiteIntegrator()});
        }
        catch (const DeviceError& e)
        {
            out.error = e.what();
        }
        return out;
    }();
    return s;
}
} // namespace

GpuIntegrator suiteIntegrator()
{
    const char* name = std::getenv("RT_GPU_INTEGRATOR");
    if (!name || !*name)
        return GpuIntegrator::Auto;
    if (const auto integrator = parseName<GpuIntegrator>(name))
        return *integrator;
    throw UsageError(std::string("RT_GPU_INTEGRATOR must be megakernel or wavefront (got '") + name + "')");
}

GpuEngine* sharedEngine() { return shared().engine.get(); }

const std::string& engineError() { return shared().error; }

void expectFurnaceOnGpu(float albedo, float radiance, Estimator estimator, int spp)
{
    const Scene scene = makeFurnace(albedo, radiance);
    RenderSettings s;
    s.width = 32;
    s.aspect = 1.0f;
    s.spp = spp;
    s.depth = 50;
    s.estimator = estimator;
    s.unidirectionalLight = false;
    const RenderResult r = renderOnGpu(scene, s);
    const double expected = radiance * (1.0 - std::pow(double(albedo), s.depth)) / (1.0 - albedo);
    EXPECT_EQ(r.stats.nanSamples + r.stats.infSamples, 0u);
    for (int channel = 0; channel < 3; ++channel)
    {
        const MeanAndError m = pixelStatistics(r.image, channel);
        // BSDF-only sampling has zero variance here: only rounding separates it from the expectation.
        const double tolerance = std::max(3.0 * m.standardError, 1e-5 * expected);
        EXPECT_NEAR(m.mean, expected, tolerance) << toString(estimator) << ", channel " << channel
                                                 << ", standard error " << m.standardError;
    }
}

void expectCancelInsideABandedBatchPutsTheBatchBack(const std::string& sceneId, int width,
                                                    std::optional<Estimator> estimator)
{
    const Scene scene = makeScene(sceneId);
    sharedEngine()->setScene(scene);
    sharedEngine()->setBandRows(2);
    RenderSettings s = ::rt::test::settingsFor(scene, width, 100000, 8);
    if (estimator)
        s.estimator = *estimator;
    RenderControl control;
    const std::uint64_t pixels = std::uint64_t(s.width) * std::uint64_t(s.height());
    std::thread canceller([&] { // a few bands into a batch after the first
        while (control.done() < pixels + std::uint64_t(s.width) * 6)
            std::this_thread::yield();
        control.requestCancel();
    });
    const RenderResult cancelled = renderWithSettings(*sharedEngine(), s, control);
    canceller.join();
    sharedEngine()->setBandRows(0);
    ASSERT_TRUE(cancelled.stats.cancelled);
    ASSERT_GE(cancelled.stats.trueSpp, 1);
    EXPECT_GT(control.done(), cancelled.stats.paths) << "the cancel landed inside a batch: bands were undone";
    RenderSettings same = s;
    same.spp = cancelled.stats.trueSpp;
    const RenderResult clean = renderOnGpu(scene, same);
    EXPECT_EQ(cancelled.image.pixels(), clean.image.pixels());
    EXPECT_EQ(cancelled.stats.nanSamples, clean.stats.nanSamples);
}

void expectBandsGiveTheImageOfOneSubmission(const std::string& sceneId, int width)
{
    const Scene scene = makeScene(sceneId);
    RenderSettings s = ::rt::test::settingsFor(scene, width, 3, 8);
    s.aspect = float(width) / 37.0f;
    ASSERT_EQ(s.height(), 37);
    sharedEngine()->setBandRows(3);
    const RenderResult banded = renderOnGpu(scene, s);
    sharedEngine()->setBandRows(37);
    const RenderResult whole = renderOnGpu(scene, s);
    sharedEngine()->setBandRows(0);
    EXPECT_EQ(banded.stats.trueSpp, 3);
    EXPECT_GT(banded.image.mean().x, 0.0f);
    EXPECT_EQ(banded.image.pixels(), whole.image.pixels());
}

void expectOnePassTracesEverySixteenthRow(GpuIntegrator integrator)
{
    SceneBuilder b("sky");
    b.sphere(b.world(), vec3(0.0f, 0.0f, 50.0f), 0.1f, b.lambertian(vec3(0.5f))); // behind the camera
    b.scene().background = {BackgroundType::Constant, vec3(1.0f), vec3(1.0f)};
    b.scene().camera.lookFrom = vec3(0.0f);
    b.scene().camera.lookAt = vec3(0.0f, 0.0f, -1.0f);
    const Scene scene = b.finish();
    GpuEngine& engine = *sharedEngine();
    engine.setScene(scene);
    const SceneTracer& tracer = engine.tracer();
    const vk::Device& device = engine.context().device();
    const std::uint32_t width = 24, height = 37;
    RenderSettings s = ::rt::test::settingsFor(scene, int(width), 1, 4);
    s.aspect = float(width) / float(height);
    const shader::RenderUniforms uniforms = tracer.uniforms(scene.camera, s, {width, height});
    tracer.prepare(uniforms, integrator);
    RenderTarget target(device, width, height);
    target.reset(uniforms);
    const TracingDescriptors descriptors = tracer.makeDescriptors(target.bindings());
    const std::uint32_t rows = BandPlan(height).passRows();
    vk::submitAndWait(device, engine.context().commandPool(), [&](VkCommandBuffer cmd) { target.recordClear(cmd); });
    vk::submitAndWait(device, engine.context().commandPool(), [&](VkCommandBuffer cmd) {
        tracer.recordLaunch(cmd, {&descriptors.set, 1}, uniforms, integrator, 0, 1, {width, rows}, nullptr, 0,
                            shader::kBandInterleave);
    });
    vk::submitAndWait(device, engine.context().commandPool(), [&](VkCommandBuffer cmd) { target.recordReadback(cmd); });
    const Image image = target.readEstimate(1, 0, 1);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            ASSERT_EQ(image.at(int(x), int(y)).x, y % shader::kBandInterleave == 0 ? 1.0f : 0.0f)
                << "pixel (" << x << ", " << y << ")";
}

RenderResult renderOnGpu(const Scene& scene, const RenderSettings& settings)
{
    GpuEngine& engine = *sharedEngine();
    engine.setScene(scene);
    RenderControl control;
    return renderWithSettings(engine, settings, control);
}

} // namespace rt::gpu::test
