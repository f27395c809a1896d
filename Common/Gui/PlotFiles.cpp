#include "Gui/PlotFiles.h"

#include "Cli/HeadlessRun.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/PythonScript.h"
#include "IO/AtomicFile.h"

namespace rt::gui
{
std::size_t savePlotFiles(const ConvergencePlot& plot, const RenderRequest& work, const std::filesystem::path& png)
{
    checkOutputPath(png.string(), "the plot", {".png"});
    const std::vector<compare::ConvergenceRow> rows = ConvergencePlot::csvRows(plot.linesOf(work));
    if (rows.empty())
        return 0;
    std::filesystem::path csv = png;
    csv.replace_extension(".csv");
    writeAtomically(csv, [&](const std::filesystem::path& temporary) {
        compare::ConvergenceCsv file(temporary);
        for (const compare::ConvergenceRow& row : rows)
            file.append(row);
        return true;
    });
    compare::drawFigure(png, compare::scriptPath("plot_convergence.py"), {csv.string()});
    return rows.size();
}
} // namespace rt::gui
