// ray-tracing-cpu: the CPU path tracer's command line (and, with no --headless, its desktop app).
#include <cstdio>

#include <spdlog/spdlog.h>

#include "Cli/HeadlessRun.h"
#include "Engine/CpuEngine.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

int main(int argc, char** argv)
{
    CLI::App app{"ray-tracing-cpu: path tracer of Shirley's three books on the CPU (seq or TBB-parallel), for "
                 "measuring light-sampling strategies"};
    rt::CommonOptions options;
    rt::addCommonOptions(app, options);
    std::string engineName = "multi";
    app.add_option("--engine", engineName, "single (std::execution::seq) or multi (std::execution::par on TBB)")
        ->capture_default_str();

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
        const auto engine = rt::parseEngine(engineName);
        if (!engine || *engine == rt::EngineKind::Gpu)
            throw rt::UsageError("--engine must be single or multi (got '" + engineName + "')");
        rt::checkOutputPaths(options);
        const rt::Scene scene = rt::makeScene(options.scene, options.sceneOptions());
        const rt::RenderSettings settings = rt::resolveSettings(options, scene);
        rt::cpu::CpuEngine cpu(*engine);
        return rt::runHeadless(cpu, scene, settings, options);
    });
}
