// The flags of ray-tracing-cpu's window (besides the shared ones of Common/Cli, which set the panel's first
// values): automation for tests (--frames, --screenshot, --actions, --state-json), the window's size, and
// the GPU engine's start.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace rt::gui
{
struct GuiOptions
{
    int frames = 0; // > 0: exit after this many frames once the renders have settled
    std::string screenshot; // with frames: save the last frame here (.png)
    std::string actions; // ActionScript
    std::string stateJson; // at exit: panel, image on screen, timings, GPU status
    std::string windowSize; // WxH; empty: the panes around the image at one pixel per pixel (PaneLayout.h)
    bool noGpu = false;
    bool validation = false;

    /// For --headless runs: throws UsageError, listing the window's flags, when one of them was given.
    static void rejectIfGiven(const CLI::App& app);
};

void addGuiOptions(CLI::App& app, GuiOptions& options);

/// Checks, before the window opens, that --screenshot and --state-json can be written. Throws.
void checkGuiOutputPaths(const GuiOptions& options);
} // namespace rt::gui
