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

#include "Compare/Compare.h"
#include "Compare/ReferenceCache.h"
#ifdef RT_GPU_WINDOW
#include "App/Gui/WindowApp.h"
#endif
#include "Cli/HeadlessRun.h"
#include "Cli/ValueParsing.h"
#include "Cli/WindowSize.h"
#include "Cluster/Job.h"
#include "Compare/AutoCommand.h"
#include "Compare/CompareCommand.h"
#include "Engine/GpuContext.h"
#include "Error.h"
#include "Render/EngineRegistry.h"
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
    int samplesPerFrame = 0;
    std::string rayTracing = "on";
    std::string accumulate = "on";
};

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
        ->check(rt::namesAFile())
        ->needs(frames);
    app.add_option("--state-json", w.stateJson,
                   "Window: at exit, write the window's and the image's sizes, where the last frame drew the panel "
                   "and the image, and the panel's message as JSON here")
        ->check(rt::namesAFile());
    app.add_option("--window-size", w.windowSize,
                   fmt::format("Window: its size WxH in pixels, each side in [{}, {}] (default: the panel and the "
                               "image side by side at one pixel per image pixel, cut to the screen)",
                               rt::kMinWindowSide, rt::kMaxWindowSide));
    app.add_option("--actions", w.actions,
                   "Window: scripted input, one per frame, through the panel's own functions, separated by ';':\n" +
                       rt::gpu::gui::actionHelp());
    app.add_option("--samples-per-frame", w.samplesPerFrame,
                   "Window: samples per pixel traced each frame; 0: as many as take about 50 ms of the device's time, "
                   "measured frame by frame (few samples a frame leave each launch waiting for its slowest paths: "
                   "1 a frame took 3.9x a headless render's time on an H200). The window stops at --spp when it is "
                   "given, with the image of a headless render of that spp; without it, it accumulates until closed")
        ->check(CLI::Range(0, rt::gpu::gui::kMaxSamplesPerFrame))
        ->capture_default_str();
    app.add_option("--raytracing", w.rayTracing, "Window: ray tracing, or (off) the rasterised preview")
        ->capture_default_str();
    app.add_option("--accumulate", w.accumulate, "Window: accumulate samples between frames")->capture_default_str();
}

int runWindow(const rt::CommonOptions& options, const WindowFlags& flags, std::optional<int> device, bool validation,
              rt::GpuIntegrator integrator, const std::string& shaderDir)
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
    // The window traces progressively: random jitter per pass, Sobol's points (indexed by the sample), or
    // stratified samples up to the spp where it stops (--spp).
    if (settings.sampling == rt::PixelSampling::Stratified && !options.given("spp"))
        spdlog::warn("stratified sampling needs the spp where the window stops (--spp N): it accumulates random "
                     "samples instead");
    image.request.settings.sampling = rt::progressiveSampling(settings.sampling, options.given("spp").has_value());
    image.camera = job.scene.camera;
    image.rayTracing = onOff(flags.rayTracing, "--raytracing");
    image.accumulate = onOff(flags.accumulate, "--accumulate");
    // --heatmap names the headless run's file; the window takes on or off, and shows the cost for a file too.
    if (!options.heatmap.empty() && options.heatmap != "on" && options.heatmap != "off")
        spdlog::warn("--heatmap {}: the file is for --headless; the window shows the cost instead", options.heatmap);
    image.heatmap = !options.heatmap.empty() && options.heatmap != "off";
    w.initial.display.samplesPerFrame = flags.samplesPerFrame;
    // The scene's default spp is no reason to stop: only a --spp given is.
    w.initial.display.stopAtSpp = options.given("spp").has_value();
    w.deviceIndex = device;
    w.validation = validation;
    w.integrator = integrator;
    w.shaderDir = shaderDir;
    w.frames = flags.frames;
    w.screenshot = flags.screenshot;
    w.stateJson = flags.stateJson;
    w.savePath = options.output.empty() ? "ray-tracing-gpu.png" : options.output;
    // A given --strategy auto: the window opens on the pilot's choice (the panel's Choose strategy, run before the
    // first frame). Not by default: the first frame shows at once, not after a pilot's pipelines are compiled.
    w.initial.pilotRequest = options.strategy == "auto" && options.strategyGiven;
    w.pilotBudget = rt::compare::pilotBudget(options);
    w.fixedSettings = rt::compare::fixedSettings(options);
    return rt::gpu::gui::runWindow(w, std::move(job.scene));
}
#else
struct WindowFlags
{
};

void addWindowOptions(CLI::App&, WindowFlags&) {}

int runWindow(const rt::CommonOptions&, const WindowFlags&, std::optional<int>, bool, rt::GpuIntegrator,
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
    bool listDevicesFlag = false;
    app.add_flag("--list-devices", listDevicesFlag,
                 "Print every Vulkan device this process sees, what each lacks for the ray tracer and which one a "
                 "headless render takes (under mpirun: each rank's, by rank)");
    rt::compare::CompareFlags compareFlags;
    rt::compare::addCompareOptions(app, compareFlags);
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
                   "(docs/notebook/PERFORMANCE.md); auto takes the wavefront on a GPU for nee and nee-mis over two emitters "
                   "or more from 2^20 camera paths (width x height x spp); from 2^24 paths for the mixture over two "
                   "lights or more, NEE at one emitter in a scene of more than that emitter, scenes with media and "
                   "scenes of 256 primitives or more; else the megakernel")
        ->check(CLI::IsMember({"auto", "megakernel", "wavefront"}))
        ->capture_default_str();
    std::uint32_t wavePaths = 0;
    app.add_option("--wave-paths", wavePaths,
                   "GPU, wherever the wavefront runs: paths traced at once (each holds 204 bytes of state); 0: by the "
                   "device (16 M on a GPU of 48 GiB or more, 64 K on a CPU device)")
        ->check(CLI::Range(0u, 1u << 26));
    bool countRays = false;
    app.add_flag("--count-rays", countRays,
                 "Headless and --compare: count the rays traced by kind (camera, extension, shadow) and report them "
                 "per second in the summary line, --stats (\"rays\") and --compare's CSV; and NEE's light samples by "
                 "outcome (drawn, made by a fallback sampler, declined: --stats' \"light_samples\"). The counting is a "
                 "specialization constant: off, the pipelines hold none of it; on, the rays cost 0.94-1.07x of the "
                 "time on the H100, the light samples 3-4 % more on the H200's cornell-box-lights (docs/GPU.md)");
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
        if (listDevicesFlag)
        {
            rt::cluster::Job& job = rt::cluster::job();
            std::string mine;
            try
            {
                mine = rt::gpu::listDevices(device, job.localRank());
            }
            catch (const rt::Error& e)
            {
                mine = std::string("  ") + e.what();
            }
            const std::vector<std::string> all = job.gather(mine);
            for (std::size_t r = 0; r < all.size(); ++r)
                std::printf("%s:\n%s\n", job.distributed() ? job.name(static_cast<int>(r)).c_str() : "Vulkan devices",
                            all[r].c_str());
            return 0;
        }
        const rt::EngineOptions engineOptions{.specialize = *rt::parseName<rt::Specialize>(specialize), // checked by CLI11
                                              .device = device,
                                              .validation = validation,
                                              .shaderDir = shaderDir,
                                              .integrator = *rt::parseName<rt::GpuIntegrator>(integrator), // checked by CLI11
                                              .wavePaths = wavePaths,
                                              .countRays = countRays};
        if (compareFlags.compare)
            return rt::compare::runCompare(compareFlags, options, engineOptions);
        if (!options.headless && rt::cluster::job().distributed())
            throw rt::UsageError("the window runs as one process: start it without mpirun, or add --headless");
        if (!options.headless)
            return runWindow(options, window, device, validation || rt::gpu::validationWanted(),
                             engineOptions.integrator, shaderDir);
        if (rt::cluster::job().root())
            rt::checkOutputPaths(options); // root alone writes
        const rt::CommandLineRender job = rt::resolveCommandLine(options);
        const std::unique_ptr<rt::RenderEngine> gpu = rt::engines::make(rt::EngineKind::Gpu, engineOptions);
        const int status = rt::runHeadless(*gpu, job.scene, job.request, options,
                                           rt::compare::strategyChooser(job.scene, options));
        if (gpu->validationMessages() > 0)
        {
            spdlog::error("Vulkan validation reported {} warnings or errors (see above)", gpu->validationMessages());
            return status == 0 ? 1 : status;
        }
        return status;
    });
}
