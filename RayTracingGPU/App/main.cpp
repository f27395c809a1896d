// ray-tracing-gpu: the Vulkan ray-tracing engine's command line. The flags are ray-tracing-cpu's
// (Common/Cli/CommonOptions.h) plus --device and --validation; the headless flow is the shared one
// (Common/Cli/HeadlessRun.h), so both apps report, write files and fail identically. Without --headless the
// app opens its window (App/Gui/WindowApp.h); the common flags give the window's initial settings.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/spdlog.h>

#include "App/Compare/Compare.h"
#include "App/Compare/ReferenceCache.h"
#ifdef RT_GPU_WINDOW
#include "App/Gui/WindowApp.h"
#endif
#include "Cli/HeadlessRun.h"
#include "Cli/ValueParsing.h"
#include "Cli/WindowSize.h"
#include "Engine/CpuEngine.h"
#include "Engine/GpuContext.h"
#include "Engine/GpuEngine.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

namespace
{
#ifdef RT_GPU_WINDOW
/// The window's command-line flags beside the common ones.
struct WindowFlags
{
    std::optional<int> frames;
    std::string screenshot;
    std::string stateJson;
    std::string actions;
    std::string windowSize; // empty: the panel and the image side by side
    int samplesPerFrame = 1;
    std::string rayTracing = "on";
    std::string accumulate = "on";
    std::string heatmap = "off";
};

/// --specialize's value (checked by CLI11): on, strategy, off.
rt::gpu::Specialize specializeMode(const std::string& value)
{
    return value == "off" ? rt::gpu::Specialize::Off
           : value == "strategy" ? rt::gpu::Specialize::Strategy
                                 : rt::gpu::Specialize::Full;
}

bool onOff(const std::string& value, const char* flag)
{
    if (const auto on = rt::parseOnOff(value))
        return *on;
    throw rt::UsageError(fmt::format("{} must be on or off (got '{}')", flag, value));
}

void addWindowOptions(CLI::App& app, WindowFlags& w)
{
    auto* frames = app.add_option("--frames", w.frames,
                                  "Window: run N frames after the --actions, then exit (0 on success): with "
                                  "--screenshot, tests and demos run without a person");
    frames->check(CLI::PositiveNumber);
    app.add_option("--screenshot", w.screenshot, "Window: save what the window shows in the last frame (.png)")
        ->needs(frames);
    app.add_option("--state-json", w.stateJson,
                   "Window: at exit, write the window's and the image's sizes, where the last frame drew the panel "
                   "and the image, and the panel's message as JSON here");
    app.add_option("--window-size", w.windowSize,
                   fmt::format("Window: its size WxH in pixels, each side in [{}, {}] (default: the panel and the "
                               "image side by side at one pixel per image pixel, cut to the screen)",
                               rt::kMinWindowSide, rt::kMaxWindowSide));
    app.add_option("--actions", w.actions,
                   "Window: scripted input, one per frame, through the panel's own functions, separated by ';':\n" +
                       rt::gpu::gui::actionHelp());
    app.add_option("--samples-per-frame", w.samplesPerFrame, "Window: samples per pixel traced each frame")
        ->check(CLI::Range(1, rt::gpu::gui::kMaxSamplesPerFrame))
        ->capture_default_str();
    app.add_option("--raytracing", w.rayTracing, "Window: ray tracing, or (off) the rasterised preview")
        ->capture_default_str();
    app.add_option("--accumulate", w.accumulate, "Window: accumulate samples between frames")->capture_default_str();
    app.add_option("--heatmap", w.heatmap, "Window: show the time per pixel (needs VK_KHR_shader_clock)")
        ->capture_default_str();
}

int runWindow(const rt::CommonOptions& options, const WindowFlags& flags, std::optional<int> device, bool validation,
              rt::gpu::GpuIntegrator integrator, const std::string& shaderDir)
{
    if (!options.hdr.empty() || !options.stats.empty())
        spdlog::warn("--hdr and --stats are for --headless; the window's Save writes the PFM beside the PNG");
    rt::checkOutputPaths(options);
    rt::gpu::gui::WindowOptions w;
    if (!flags.windowSize.empty())
        w.windowSize = rt::parseWindowSize(flags.windowSize);
    rt::checkOutputPath(flags.screenshot, "--screenshot", {".png"});
    rt::checkOutputPath(flags.stateJson, "--state-json", {".json"});
    w.actions = rt::gpu::gui::parseActions(flags.actions);
    rt::CommandLineRender job = rt::resolveCommandLine(options);
    const rt::RenderSettings& settings = job.request.settings;
    rt::gpu::gui::ImageSettings& image = w.initial.image;
    image.request = job.request;
    // The window traces progressively: random jitter per pass, or Sobol's points (indexed by the sample).
    if (settings.sampling == rt::PixelSampling::Stratified)
        spdlog::warn("the window accumulates random or Sobol samples progressively; stratified sampling is for "
                     "--headless");
    if (settings.sampling != rt::PixelSampling::Sobol)
        image.request.settings.sampling = rt::PixelSampling::Accumulate;
    image.camera = job.scene.camera;
    image.rayTracing = onOff(flags.rayTracing, "--raytracing");
    image.accumulate = onOff(flags.accumulate, "--accumulate");
    image.heatmap = onOff(flags.heatmap, "--heatmap");
    w.initial.display.samplesPerFrame = flags.samplesPerFrame;
    w.initial.display.targetSpp = options.spp.value_or(0); // the scene's default spp is no reason to stop
    w.deviceIndex = device;
    w.validation = validation;
    w.integrator = integrator;
    w.shaderDir = shaderDir;
    w.frames = flags.frames;
    w.screenshot = flags.screenshot;
    w.stateJson = flags.stateJson;
    w.savePath = options.output.empty() ? "ray-tracing-gpu.png" : options.output;
    return rt::gpu::gui::runWindow(w, std::move(job.scene));
}
#else
struct WindowFlags
{
};

void addWindowOptions(CLI::App&, WindowFlags&) {}

int runWindow(const rt::CommonOptions&, const WindowFlags&, std::optional<int>, bool, rt::gpu::GpuIntegrator,
              const std::string&)
{
    throw rt::UsageError("this build has no window (configured with RT_BUILD_GUI=OFF): run with --headless");
}
#endif
} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"ray-tracing-gpu: path tracer of Shirley's three books on a Vulkan ray-tracing device (hardware "
                 "RT pipeline, or a software one such as lavapipe), for measuring light-sampling strategies"};
    rt::CommonOptions options;
    rt::addCommonOptions(app, options);
    std::optional<int> device;
    bool validation = false;
    app.add_option("--device", device,
                   "Vulkan device index in vkEnumeratePhysicalDevices order (default: the first suitable "
                   "discrete GPU, else any suitable device); an unsuitable one is refused with what it lacks");
    bool compare = false;
    std::string sppList = "10,50,100";
    std::string engines = "single,multi,gpu";
    int referenceSpp = 0;
    std::string table;
    CLI::Option* compareFlag = app.add_flag("--compare", compare,
                 "Headless comparison: render --scene at every count of --spp-list on every engine of --engines, "
                 "print time, CPU/GPU ratio and relMSE against a --reference-spp render");
    app.add_option("--spp-list", sppList, "With --compare: sample counts, comma separated")->capture_default_str();
    app.add_option("--engines", engines, "With --compare: engines, comma separated (single, multi, gpu)")
        ->capture_default_str();
    app.add_option("--reference-spp", referenceSpp,
                   "With --compare: spp of the reference image (default: 4x the largest count), rendered by the "
                   "last engine in two halves (seeds + 1000 and + 2000) whose difference gives the reference's own "
                   "relMSE");
    std::string referencePath;
    app.add_option("--reference", referencePath,
                   "With --compare: a linear PFM of the same size (e.g. a long --hdr render) to measure against "
                   "instead of rendering a reference")
        ->check(CLI::ExistingFile);
    app.add_option("--table", table, "With --compare: write every figure as JSON here");
    rt::app::StrategyLists strategyLists;
    app.add_option("--estimators", strategyLists.estimators,
                   "With --compare: estimators to compare, comma separated (bsdf, mixture, nee, nee-mis; default: "
                   "--estimator's); every combination with the lists below is a strategy")
        ->needs(compareFlag);
    app.add_option("--light-samplers", strategyLists.lightSamplers,
                   "With --compare: NEE's light samplers to compare (area, solid-angle, projected)")
        ->needs(compareFlag);
    app.add_option("--light-selections", strategyLists.lightSelections,
                   "With --compare: NEE's light selections to compare (uniform, power, bvh)")
        ->needs(compareFlag);
    app.add_option("--samplings", strategyLists.samplings,
                   "With --compare: pixel samplings to compare (random, stratified, accumulate, sobol)")
        ->needs(compareFlag);
    app.add_option("--roulettes", strategyLists.roulettes, "With --compare: Russian roulette settings to compare (on, off)")
        ->needs(compareFlag);
    std::string csv;
    app.add_option("--csv", csv,
                   "With --compare: one CSV row per engine x strategy x spp (scene, engine, device, strategy, label, "
                   "spp, wall ms, GPU ms, Mpaths/s, MSE, relMSE, RMSE), each written as its render ends (Ctrl-C keeps "
                   "them)")
        ->needs(compareFlag);
    std::string plot;
    app.add_option("--plot", plot,
                   "With --compare and --csv: a PNG of relMSE against time and against spp (log-log, slope -1 "
                   "drawn) and of the efficiency 1/(relMSE s), drawn by matplotlib (python3-matplotlib)")
        ->needs(compareFlag);
    double equalTimeMs = 0.0;
    app.add_option("--equal-time", equalTimeMs,
                   "With --compare: render every engine x strategy for this many milliseconds instead of the "
                   "--spp-list ladder, and write the images with their false-colour error images as one figure to "
                   "--output FILE.png")
        ->check(CLI::PositiveNumber)
        ->needs(compareFlag);
    std::string referenceCache = rt::app::defaultReferenceCacheDir().string();
    app.add_option("--reference-cache", referenceCache,
                   "With --compare: folder of rendered references, re-used when scene, settings, spp, seed and engine "
                   "match ('off': render the reference every time)")
        ->capture_default_str()
        ->needs(compareFlag);
    app.add_flag("--validation", validation,
                 "Run with VK_LAYER_KHRONOS_validation and fail (exit 1) if it reports any warning or error "
                 "(always on in Debug builds and with RT_VULKAN_VALIDATION=1)");
    std::string specialize = "on";
    app.add_option("--specialize", specialize,
                   "Headless and --compare: on compiles a pipeline for the render's estimator, light sampler, light "
                   "selection and pixel sampling and for the scene's features (geometry kinds, media, motion, "
                   "materials, texture kinds, light shapes, lens, background), so that the driver drops the code of "
                   "every other choice and the pipeline holds only the hit groups the scene needs (faster; book 3's "
                   "mixture is compiled for its settings only, which the H100 runs faster than with feature "
                   "constants); "
                   "strategy specialises on the render's settings only; off runs the general pipeline that reads "
                   "them at run time")
        ->check(CLI::IsMember({"on", "strategy", "off"}))
        ->capture_default_str();
    std::string integrator = "auto";
    app.add_option("--integrator", integrator,
                   "GPU: megakernel runs each camera sample's whole path in one ray-tracing invocation; wavefront "
                   "runs kernels per segment over waves of paths (path rays, shading in a compute kernel, shadow "
                   "rays): the same estimator, the same image within noise, up to 3.5x faster on NEE renders "
                   "(docs/PERFORMANCE.md); auto takes the wavefront on a GPU for nee and nee-mis over two emitters "
                   "or more from 2^20 camera paths (width x height x spp), for the mixture over two lights or more "
                   "and for scenes of 256 primitives or more from 2^24 paths, else the megakernel")
        ->check(CLI::IsMember({"auto", "megakernel", "wavefront"}))
        ->capture_default_str();
    std::uint32_t wavePaths = 0;
    app.add_option("--wave-paths", wavePaths,
                   "GPU, wherever the wavefront runs: paths traced at once (each holds 204 bytes of state); 0: by the "
                   "device (16 M on a GPU of 48 GiB or more, 64 K on a CPU device)")
        ->check(CLI::Range(0u, 1u << 26));
    std::string shaderDir;
    app.add_option("--shader-dir", shaderDir,
                   "Load the SPIR-V shaders from this folder instead of the 'shaders' folder beside the app (the same "
                   "layout: Shaders/CMakeLists.txt's glslc output), to try or time a variant of the GLSL without "
                   "rebuilding the app (docs/GPU.md)")
        ->check(CLI::ExistingDirectory);
    WindowFlags window;
    addWindowOptions(app, window);

    return rt::guardedMain(app, argc, argv, [&] {
        if (rt::runCommonCommands(options))
            return 0;
        validation = validation || rt::gpu::validationWanted();
        // The headless engine's and --compare's (the window adds its presentation to the device and integrator).
        const auto engineOptions = [&] {
            return rt::gpu::GpuEngineOptions{.deviceIndex = device,
                                             .validation = validation,
                                             .shaderDir = shaderDir,
                                             .specialize = specializeMode(specialize),
                                             .integrator = *rt::gpu::parseIntegrator(integrator), // checked by CLI11
                                             .wavePaths = wavePaths};
        };
        if (compare)
        {
            const rt::CommandLineRender job = rt::resolveCommandLine(options);
            rt::app::CompareOptions c;
            c.spps = rt::app::parseSppList(sppList);
            c.engines = rt::app::parseEngineList(engines);
            c.referenceSpp = referenceSpp > 0 ? referenceSpp : 4 * *std::max_element(c.spps.begin(), c.spps.end());
            c.json = table;
            c.referencePath = referencePath;
            c.strategies = rt::app::strategyGrid(strategyLists, job.request.settings);
            c.csv = csv;
            c.plot = plot;
            c.equalTimeMs = equalTimeMs;
            c.grid = options.output;
            if (referenceCache != "off")
                c.referenceCache = referenceCache;
            return rt::app::runComparison(job.scene, job.request, c, [&](rt::EngineKind kind) -> std::unique_ptr<rt::RenderEngine> {
                if (kind == rt::EngineKind::Gpu)
                    return std::make_unique<rt::gpu::GpuEngine>(engineOptions());
                return std::make_unique<rt::cpu::CpuEngine>(kind);
            });
        }
        if (!options.headless)
            return runWindow(options, window, device, validation, engineOptions().integrator, shaderDir);
        rt::checkOutputPaths(options);
        const rt::CommandLineRender job = rt::resolveCommandLine(options);
        rt::gpu::GpuEngine gpu(engineOptions());
        const int status = rt::runHeadless(gpu, job.scene, job.request, options);
        if (gpu.validationMessages() > 0)
        {
            spdlog::error("Vulkan validation reported {} warnings or errors (see above)", gpu.validationMessages());
            return status == 0 ? 1 : status;
        }
        return status;
    });
}
