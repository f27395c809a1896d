// The convergence plot on screen (ConvergencePlot.h): relMSE against render time on log-log axes, a line per
// engine x strategy of the panel's work (scene, size and depth), drawn with Dear ImGui's draw lists (Debian 12
// packages no plotting library for ImGui). Hovering a point names its line, spp, time and error; Save writes the
// figure and its points' CSV.
#pragma once

#include <nlohmann/json.hpp>

#include "App/Gui/Session.h"

namespace rt::gui
{
/// Draws into the current ImGui window. Returns what it drew, for --state-json: x_label, y_label, the axes'
/// ranges (seconds, relMSE), and per line its label, colour (RGBA) and points as [seconds, spp, relMSE], in the
/// order drawn (by time), and waiting: the points still without a reference.
nlohmann::json drawConvergencePlot(Session& session);
} // namespace rt::gui
