#include "App/Gui/GuiOptions.h"


#include <spdlog/fmt/fmt.h>

#include "App/Gui/ActionScript.h"
#include "App/Gui/PaneLayout.h"
#include "Cli/HeadlessRun.h"
#include "Cli/WindowSize.h"
#include "Error.h"

namespace rt::gui
{
namespace
{
constexpr const char* kWindowFlags[] = {"--frames", "--screenshot", "--actions", "--state-json", "--window-size",
                                        "--no-gpu", "--validation"};
} // namespace

void GuiOptions::rejectIfGiven(const CLI::App& app)
{
    bool given = false;
    std::string list;
    const std::size_t count = std::size(kWindowFlags);
    for (std::size_t i = 0; i < count; ++i)
    {
        given |= app.count(kWindowFlags[i]) > 0;
        list += (i == 0 ? "" : i + 1 == count ? " and " : ", ") + std::string(kWindowFlags[i]);
    }
    if (given)
        throw UsageError(list + " are for the window: leave out --headless");
}

void addGuiOptions(CLI::App& app, GuiOptions& o)
{
    app.add_option("--frames", o.frames,
                   "Window: once the launch render and --actions have finished, draw N more frames, save "
                   "--screenshot and exit (status 1 if a render or an action failed)")
        ->check(CLI::PositiveNumber);
    app.add_option("--screenshot", o.screenshot, "Window, with --frames: save what the window shows here (.png)")
        ->check(namesAFile());
    app.add_option("--actions", o.actions, "Window: " + actionHelp());
    app.add_option("--state-json", o.stateJson,
                   "Window: at exit, write the panel's settings, those of the image on screen, the timings table and "
                   "the GPU engine's status as JSON here")
        ->check(namesAFile());
    app.add_option("--window-size", o.windowSize,
                   fmt::format("Window: its size WxH in screen pixels, each side in [{}, {}] (default: the panel, the "
                               "image at one pixel per pixel and the timings, at least {}x{}, cut to the screen)",
                               kMinWindowSide, kMaxWindowSide, kMinDefaultWindow.width, kMinDefaultWindow.height));
    app.add_flag("--no-gpu", o.noGpu, "Window: do not start the GPU engine (its entry is greyed out)");
    app.add_flag("--validation", o.validation,
                 "Window: run the GPU engine with VK_LAYER_KHRONOS_validation; exit 1 if it reports anything");
}

void checkGuiOutputPaths(const GuiOptions& o)
{
    checkOutputPath(o.screenshot, "--screenshot", {".png"});
    checkOutputPath(o.stateJson, "--state-json", {".json"});
    if (!o.screenshot.empty() && o.frames == 0)
        throw UsageError("--screenshot needs --frames N (the frame to save)");
}
} // namespace rt::gui
