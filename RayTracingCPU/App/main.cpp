// ray-tracing-cpu: the CPU path tracer's command line and, without --headless, its desktop window
// (App/Gui: the thesis' settings panel, renders off the UI thread, timings of every engine side by side). Its
// engines are the registry's (Render/EngineRegistry.h): single and multi, and the GPU engine where the build
// links it (the window's third engine, and --compare's).
#include "Cli/HeadlessRun.h"
#include "Cluster/Job.h"
#include "Compare/AutoCommand.h"
#include "Compare/CompareCommand.h"
#include "Error.h"
#include "Render/EngineRegistry.h"

#ifdef RT_WITH_GUI
#include "App/Gui/GuiApp.h"
#endif

int main(int argc, char** argv)
{
    CLI::App app{"ray-tracing-cpu: path tracer of Shirley's three books on the CPU (seq or TBB-parallel), for "
                 "measuring light-sampling strategies. Without --headless it opens a window."};
    rt::CommonOptions options;
    rt::addCommonOptions(app, options);
    std::string engineName = "multi";
    app.add_option("--engine", engineName,
                   "single (std::execution::seq) or multi (std::execution::par on TBB); in the window also gpu "
                   "(the Vulkan engine, when a ray-tracing device exists)")
        ->capture_default_str();
    std::string specialize = "on";
    app.add_option("--specialize", specialize,
                   "Headless and --compare: on runs the path loop compiled for the render's estimator and the scene's features "
                   "(no media code without media, no texture lookups for solid colours); off runs the general "
                   "loop that tests them at every vertex (the same image bit for bit, for benchmarks)")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    rt::compare::CompareFlags compareFlags;
    rt::compare::addCompareOptions(app, compareFlags);
#ifdef RT_WITH_GUI
    rt::gui::GuiOptions gui;
    rt::gui::addGuiOptions(app, gui);
#endif

    return rt::guardedMain(app, argc, argv, [&] {
        if (rt::runCommonCommands(options))
            return 0;
        const rt::EngineOptions engineOptions{.specialize = *rt::parseName<rt::Specialize>(specialize)}; // checked by CLI11
        if (compareFlags.compare)
            return rt::compare::runCompare(compareFlags, options, engineOptions);
        if (!options.headless && rt::cluster::job().distributed())
            throw rt::UsageError("the window runs as one process: start it without mpirun, or add --headless");
        if (!options.headless)
        {
#ifdef RT_WITH_GUI
            return rt::gui::runGui(options, engineName, gui);
#else
            throw rt::UsageError("this build has no window (RT_BUILD_GUI=OFF): run with --headless");
#endif
        }
#ifdef RT_WITH_GUI
        rt::gui::GuiOptions::rejectIfGiven(app);
#endif
        const auto engine = rt::parseName<rt::EngineKind>(engineName);
        if (!engine || *engine == rt::EngineKind::Gpu)
            throw rt::UsageError("--engine must be single or multi (got '" + engineName + "')");
        if (rt::cluster::job().root())
            rt::checkOutputPaths(options); // root alone writes
        const rt::CommandLineRender job = rt::resolveCommandLine(options);
        const std::unique_ptr<rt::RenderEngine> cpu = rt::engines::make(*engine, engineOptions);
        return rt::runHeadless(*cpu, job.scene, job.request, options,
                               rt::compare::strategyChooser(job.scene, options));
    });
}
