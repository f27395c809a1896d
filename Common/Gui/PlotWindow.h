// The convergence plot on screen (ConvergencePlot.h): relMSE against render time on log-log axes, a line per
// engine x strategy of the panel's work (scene, size and depth), drawn with Dear ImGui's draw lists (Debian 12
// packages no plotting library for ImGui). Hovering a point names its line, spp, time and error; Save writes the
// figure and its points' CSV.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "Gui/ConvergencePlot.h"

namespace rt::gui
{
struct PlotDrawn
{
    /// For --state-json: x_label, y_label, the axes' ranges (seconds, relMSE), and per line its label, colour
    /// (RGB) and points as [seconds, spp, relMSE], in the order drawn (by time), and waiting: the points still
    /// without a reference.
    nlohmann::json state;
    bool saveClicked = false; // Save: the window writes the figure and its CSV (as `saveName` says)
};

/// Draws `plot`'s lines of `work` (ConvergencePlot::linesOf) into the current ImGui window; Save's tooltip names
/// `saveName`.
PlotDrawn drawConvergencePlot(const ConvergencePlot& plot, const RenderRequest& work, const std::string& saveName);
} // namespace rt::gui
