// ray-tracing-gpu: the Vulkan ray-tracing engine's command line. The flags are ray-tracing-cpu's
// (Common/Cli/CommonOptions.h) plus --device and --validation; the headless flow is the shared one
// (Common/Cli/HeadlessRun.h), so both apps report, write files and fail identically.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "App/Compare.h"
#include "Cli/HeadlessRun.h"
#include "Engine/CpuEngine.h"
#include "Engine/GpuContext.h"
#include "Engine/GpuEngine.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

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
    app.add_flag("--compare", compare,
                 "Headless comparison: render --scene at every count of --spp-list on every engine of --engines, "
                 "print time, CPU/GPU ratio and relMSE against a --reference-spp render");
    app.add_option("--spp-list", sppList, "With --compare: sample counts, comma separated")->capture_default_str();
    app.add_option("--engines", engines, "With --compare: engines, comma separated (single, multi, gpu)")
        ->capture_default_str();
    app.add_option("--reference-spp", referenceSpp,
                   "With --compare: spp of the reference image (default: 4x the largest count), rendered by the "
                   "last engine with seed + 1000");
    app.add_option("--table", table, "With --compare: write every figure as JSON here");
    app.add_flag("--validation", validation,
                 "Run with VK_LAYER_KHRONOS_validation and fail (exit 1) if it reports any warning or error "
                 "(always on in Debug builds and with RT_VULKAN_VALIDATION=1)");

    return rt::guardedMain(app, argc, argv, [&] {
        spdlog::set_pattern("%^%l%$: %v");
        spdlog::set_level(options.quiet ? spdlog::level::warn : spdlog::level::info);
        if (options.listScenes)
        {
            std::fputs(rt::sceneListing().c_str(), stdout);
            return 0;
        }
        if (compare)
        {
            const rt::Scene scene = rt::makeScene(options.scene, options.sceneOptions());
            const rt::RenderSettings settings = rt::resolveSettings(options, scene);
            rt::app::CompareOptions c;
            c.spps = rt::app::parseSppList(sppList);
            c.engines = rt::app::parseEngineList(engines);
            c.referenceSpp = referenceSpp > 0 ? referenceSpp : 4 * *std::max_element(c.spps.begin(), c.spps.end());
            c.json = table;
            return rt::app::runComparison(scene, settings, c, [&](rt::EngineKind kind) -> std::unique_ptr<rt::RenderEngine> {
                if (kind == rt::EngineKind::Gpu)
                    return std::make_unique<rt::gpu::GpuEngine>(
                        rt::gpu::GpuEngineOptions{.deviceIndex = device, .validation = validation || rt::gpu::validationWanted()});
                return std::make_unique<rt::cpu::CpuEngine>(kind);
            });
        }
        if (!options.headless)
            throw rt::UsageError("the interactive window is not built yet: run with --headless");
        rt::checkOutputPaths(options);
        const rt::Scene scene = rt::makeScene(options.scene, options.sceneOptions());
        const rt::RenderSettings settings = rt::resolveSettings(options, scene);
        rt::gpu::GpuEngine gpu({.deviceIndex = device, .validation = validation || rt::gpu::validationWanted()});
        const int status = rt::runHeadless(gpu, scene, settings, options);
        if (gpu.validationMessages() > 0)
        {
            spdlog::error("Vulkan validation reported {} warnings or errors (see above)", gpu.validationMessages());
            return status == 0 ? 1 : status;
        }
        return status;
    });
}
