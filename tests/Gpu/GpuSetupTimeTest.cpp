// The setup of a GPU render apart from its tracing (issue 38): a frame whose pipeline is new compiles it in
// beginFrame, with one row of one sample launched there too (lavapipe finishes compiling at a pipeline's first
// launch: restir-di's three passes took 7.6 s of a 96-px render's "tracing" before), and names that time
// (stageSeconds' pipeline_host); a frame of a pipeline prepared before names none. The launch leaves no trace: the
// render that compiled draws the image of the one that found the pipeline cached, bit for bit, and traces about as
// long. compileAhead (the pilot's candidates, each on a thread of its own) compiles the pipelines their frames run.
#include <gtest/gtest.h>

#include "Engine/GpuEngine.h"
#include "Engine/RestirPipeline.h"
#include "Engine/SceneTracer.h"
#include "Engine/WavefrontPipeline.h"
#include "GpuTestEnvironment.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
TEST(GpuSetupTime, AFirstRenderNamesItsPipelinesCompilationAndDrawsTheImageOfACachedOne)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    engine.setIntegrator(GpuIntegrator::Megakernel);
    // A scene and strategy the rest of the suite does not render, so that a run of the whole suite in one process
    // (tests/Bench/device_run.sh tests) still finds the pipelines new; CTest runs each test in a process of its own.
    const Scene scene = makeScene("rect-light-closeup");
    engine.setScene(scene);
    for (const Estimator estimator : {Estimator::Nee, Estimator::RestirDi})
    {
        SCOPED_TRACE(toString(estimator));
        RenderSettings s = ::rt::test::settingsFor(scene, 24, 3, 6);
        s.estimator = estimator;
        s.lightSelection = LightSelection::Power;
        s.sampling = PixelSampling::Sobol;
        const auto compiledSoFar = [&] {
            return estimator == Estimator::RestirDi ? engine.tracer().restir().compiledCount()
                                                    : engine.tracer().pipeline().compiledCount();
        };
        const std::size_t before = compiledSoFar();
        RenderControl first;
        const RenderResult compiled = ::rt::test::renderWithSettings(engine, s, first);
        EXPECT_GT(compiledSoFar(), before) << "the pipeline was compiled before: this test checks nothing";
        ASSERT_TRUE(compiled.stats.stageSeconds.contains("pipeline_host"));
        EXPECT_GT(compiled.stats.stageSeconds.at("pipeline_host"), 0.0);
        RenderControl second;
        const RenderResult cached = ::rt::test::renderWithSettings(engine, s, second);
        EXPECT_FALSE(cached.stats.stageSeconds.contains("pipeline_host"));
        // Tracing alone: the render that compiled traced about as long as the cached one. A first launch left in
        // it took seconds more on lavapipe (a driver's disk cache can hide that: then both are short).
        EXPECT_LT(compiled.stats.renderSeconds,
                  cached.stats.renderSeconds + 0.5 * compiled.stats.stageSeconds.at("pipeline_host") + 0.2);
        EXPECT_EQ(compiled.image.pixels(), cached.image.pixels());
    }
    engine.setIntegrator(suiteIntegrator());
}
TEST(GpuSetupTime, PipelinesCompiledAheadAreTheOnesTheirFramesRunEachLaunchedOnceInItsFirstFrame)
{
    RT_REQUIRE_GPU();
    GpuEngine& engine = *sharedEngine();
    struct SuiteIntegratorAfter
    {
        GpuEngine& engine;
        ~SuiteIntegratorAfter() { engine.setIntegrator(suiteIntegrator()); }
    } restore{engine};
    // Strategies the rest of the suite does not render on this scene, so that they are new in one process too; each
    // integrator's its own light selection, so that the pipelines the one before compiled do not count.
    const Scene scene = makeScene("triangle-lights");
    engine.setScene(scene);
    const std::pair<GpuIntegrator, LightSelection> cases[] = {{GpuIntegrator::Megakernel, LightSelection::Power},
                                                              {GpuIntegrator::Wavefront, LightSelection::Uniform},
                                                              {GpuIntegrator::Auto, LightSelection::Bvh}};
    for (const auto& [integrator, selection] : cases)
    {
        SCOPED_TRACE(toString(selection));
        engine.setIntegrator(integrator);
        const auto compiledSoFar = [&] {
            const WavefrontPipeline* wavefront = engine.tracer().wavefront();
            return engine.tracer().pipeline().compiledCount() + (wavefront ? wavefront->compiledCount() : 0u);
        };
        std::vector<RenderSettings> frames;
        for (const LightSampler sampler : {LightSampler::Area, LightSampler::SolidAngle, LightSampler::ProjectedExact})
        {
            // Auto runs these on the wavefront (many paths a pixel) or the megakernel, as their frames do.
            RenderSettings s = ::rt::test::settingsFor(scene, 16, 12, 4);
            s.estimator = Estimator::Nee;
            s.lightSampler = sampler;
            s.lightSelection = selection;
            s.sampling = PixelSampling::Sobol;
            frames.push_back(s);
        }
        frames.push_back(frames.front()); // the same pipeline twice compiles once
        const std::size_t before = compiledSoFar();
        engine.compileAhead(frames);
        const std::size_t ahead = compiledSoFar();
        ASSERT_EQ(ahead - before, 3u) << "some pipelines were compiled before (this test would check less), or the "
                                         "same one was compiled twice";
        for (std::size_t i = 0; i + 1 < frames.size(); ++i)
        {
            SCOPED_TRACE(toString(frames[i].lightSampler));
            RenderControl first;
            const RenderResult r = ::rt::test::renderWithSettings(engine, frames[i], first);
            EXPECT_EQ(compiledSoFar(), ahead) << "the frame ran a pipeline compileAhead did not compile";
            // Its first frame launches it once (a driver may finish compiling there), out of the render's time.
            EXPECT_TRUE(r.stats.stageSeconds.contains("pipeline_host"));
            RenderControl second;
            EXPECT_FALSE(::rt::test::renderWithSettings(engine, frames[i], second).stats.stageSeconds.contains(
                "pipeline_host"));
        }
    }
}
} // namespace rt::gpu::test
