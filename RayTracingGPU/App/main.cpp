// ray-tracing-gpu: the Vulkan ray-tracing engine's command line. The flags are ray-tracing-cpu's
// (Common/Cli/CommonOptions.h) plus --device and --validation; the headless flow is the shared one
// (Common/Cli/HeadlessRun.h), so both apps report, write files and fail identically.
#include <cstdio>
#include <optional>

#include <spdlog/spdlog.h>

#include "Cli/HeadlessRun.h"
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
