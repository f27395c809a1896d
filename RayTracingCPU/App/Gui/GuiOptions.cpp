#include "App/Gui/GuiOptions.h"

#include <filesystem>

#include <spdlog/fmt/fmt.h>

#include "App/Gui/ActionScript.h"
#include "Error.h"

namespace rt::gui
{
namespace
{
constexpr const char* kWindowFlags[] = {"--frames", "--screenshot", "--actions", "--state-json", "--window-size",
                                        "--no-gpu", "--validation"};

void checkPath(const std::string& path, const char* flag, const char* extension)
{
    if (path.empty())
        return;
    const std::filesystem::path p(path);
    if (p.extension() != extension)
        throw UsageError(fmt::format("{} '{}' must end in {}", flag, path, extension));
    const std::filesystem::path parent = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(parent))
        throw OutputError(fmt::format("{} '{}': folder '{}' does not exist", flag, path, parent.string()));
}
} // namespace

bool GuiOptions::anyGiven(const CLI::App& app) const
{
    for (const char* flag : kWindowFlags)
        if (app.count(flag) > 0)
            return true;
    return false;
}

void addGuiOptions(CLI::App& app, GuiOptions& o)
{
    app.add_option("--frames", o.frames,
                   "Window: once the launch render and --actions have finished, draw N more frames, save "
                   "--screenshot and exit (status 1 if a render or an action failed)")
        ->check(CLI::PositiveNumber);
    app.add_option("--screenshot", o.screenshot, "Window, with --frames: save what the window shows here (.png)");
    app.add_option("--actions", o.actions, "Window: " + actionHelp());
    app.add_option("--state-json", o.stateJson,
                   "Window: at exit, write the panel's settings, those of the image on screen, the timings table and "
                   "the GPU engine's status as JSON here");
    app.add_option("--window-size", o.windowSize, "Window size WxH in screen pixels")->capture_default_str();
    app.add_flag("--no-gpu", o.noGpu, "Window: do not start the GPU engine (its entry is greyed out)");
    app.add_flag("--validation", o.validation,
                 "Window: run the GPU engine with VK_LAYER_KHRONOS_validation; exit 1 if it reports anything");
}

WindowSize parseWindowSize(const std::string& text)
{
    WindowSize s;
    char x = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &s.width, &x, &s.height, &rest) != 3 || x != 'x' || s.width < 1 ||
        s.height < 1 || s.width > 16384 || s.height > 16384)
        throw UsageError(fmt::format("--window-size must be WxH, e.g. 1280x800 (got '{}')", text));
    return s;
}

void checkGuiOutputPaths(const GuiOptions& o)
{
    checkPath(o.screenshot, "--screenshot", ".png");
    checkPath(o.stateJson, "--state-json", ".json");
    if (!o.screenshot.empty() && o.frames == 0)
        throw UsageError("--screenshot needs --frames N (the frame to save)");
}
} // namespace rt::gui
