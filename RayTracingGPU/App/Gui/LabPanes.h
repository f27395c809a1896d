// The GPU window's strip under the image (WindowLayout): the timings table, titled with the progress of the
// reference it waits for, and the convergence plot of the panel's work, drawn by the views both windows share
// (Gui/TimingsWindow.h, Gui/PlotWindow.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "App/Gui/WindowLayout.h"
#include "Gui/ConvergencePlot.h"
#include "Gui/ReferenceTask.h"
#include "Gui/TimingsTable.h"

namespace rt::gpu::gui
{
struct LabPanesDrawn
{
    bool latestTimingVisible = true;
    bool clearClicked = false; // the table's Clear: the window empties the table, the plot and the references
    bool saveClicked = false; // the plot's Save
    nlohmann::json plot; // PlotDrawn::state, for --state-json
};

/// Draws both panes into `layout`'s rectangles (framebuffer pixels; `framebufferScale` of them per ImGui unit).
LabPanesDrawn drawLabPanes(const WindowLayout& layout, float framebufferScale, const rt::gui::TimingsTable& table,
                           const rt::gui::ConvergencePlot& plot, const RenderRequest& work,
                           const rt::gui::ReferenceProgress& reference);

/// The plot's file name for `work`: "<scene>_<W>x<H>_depth<D>_gpu_convergence.png".
std::string plotFileName(const RenderRequest& work);
} // namespace rt::gpu::gui
