// ray-tracing-cpu's window: the frame loop that ties the window, the render thread, the panel, the image
// and the timings together. The UI thread only draws and forwards commands; renders run on RenderJob's
// thread.
#pragma once

#include <string>

#include "App/Gui/GuiOptions.h"
#include "Cli/CommonOptions.h"

namespace rt::gui
{
/// Opens the window with the panel set from the command line, starts that render, and runs until the window
/// is closed (or --frames). Returns the exit status. Throws rt::Error for bad flags or no display.
int runGui(const CommonOptions& options, const std::string& engine, const GuiOptions& gui);
} // namespace rt::gui
