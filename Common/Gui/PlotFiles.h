// The convergence plot saved to disk, by either window (the plot pane's Save, the save-plot action): the measured
// points of the panel's work as --compare's CSV (Compare/ConvergenceCsv.h) and the figure plot_convergence.py
// draws from it, so a plot saved from a window reads like one --compare wrote.
#pragma once

#include <cstddef>
#include <filesystem>

#include "Gui/ConvergencePlot.h"

namespace rt::gui
{
/// Writes the measured points of `plot`'s lines of `work` (ConvergencePlot::linesOf) to `png` with ".csv"
/// (atomically) and draws `png` from them. Returns the points written; 0 when none has its relMSE yet (nothing is
/// written). Throws rt::UsageError for a name that is not a .png, rt::OutputError when a file cannot be written
/// or the figure not drawn.
std::size_t savePlotFiles(const ConvergencePlot& plot, const RenderRequest& work, const std::filesystem::path& png);
} // namespace rt::gui
