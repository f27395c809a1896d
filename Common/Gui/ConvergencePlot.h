// The live convergence plot's data (issue 38): relMSE against render time, one line per engine x strategy of each
// work (scene, size, depth and every setting but spp and the seed), a point per finished estimate. A render is a
// point at its time and spp; loop rendering adds its running mean after 1, 2, 4, 8, ... iterations at their time
// together, so a line grows as samples accumulate. Each point is measured against a reference of its own work at
// kDefaultReferenceFactor x its spp (ReferenceTask.h), which the render thread renders while idle or finds in the
// cache: a point waits, with its image, until then.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Compare/ConvergenceCsv.h"
#include "Gui/ReferenceTask.h"
#include "Gui/TimingsTable.h"
#include "Image/Image.h"
#include "Image/Metrics.h"

namespace rt::gui
{
struct PlotPoint
{
    double seconds = 0.0; // tracing time of the estimate (a loop's iterations so far together)
    int spp = 0; // true spp of the estimate
    bool loopMean = false;
    ReferenceTask reference; // the point's own work at kDefaultReferenceFactor x its spp
    std::optional<ErrorMetrics> error; // once measured; its relMSE includes its reference's own
    double referenceRelMse = 0.0;
    std::shared_ptr<const Image> unmeasured; // until then
};

struct PlotLine
{
    TimingKey work; // spp 0: a line's points differ by spp
    EngineKind engine = EngineKind::Multi;
    std::string device;
    std::vector<PlotPoint> points; // in the order they finished
    /// "multi core: nee-mis projected bvh sobol sqrt": the engine and the strategy settings' words.
    std::string label() const;
};

class ConvergencePlot
{
public:
    /// Adds a finished estimate of `request`'s work (its seed: that of the render, or of a loop's first iteration)
    /// by `engine`: `spp` samples in `seconds`, `image` to be measured against a reference of `spp` x
    /// kDefaultReferenceFactor on `referenceEngine`. Returns that reference's task; nullopt when it would pass
    /// 2 x kMaxSpp (the point is left out).
    std::optional<ReferenceTask> add(const RenderRequest& request, EngineKind engine, const std::string& device,
                                     double seconds, int spp, std::shared_ptr<const Image> image,
                                     EngineKind referenceEngine, bool loopMean);
    /// Measures the points waiting for `reference`.
    void attach(const FinishedReference& reference);
    void clear() { m_lines.clear(); }
    const std::vector<PlotLine>& lines() const { return m_lines; }
    /// The lines of `work`'s scene, camera, size and depth (the strategy, spp and seed ignored), in the order of
    /// their first point.
    std::vector<const PlotLine*> linesOf(const RenderRequest& work) const;

    /// One object per line: label, engine, device, scene, width, height, the strategy settings, and points
    /// [{seconds, spp, rel_mse and reference_rel_mse (null until measured), loop_mean}].
    nlohmann::json toJson() const;
    /// The measured points of `lines` as --compare's CSV rows (Compare/ConvergenceCsv.h; plot_convergence.py
    /// draws them), labelled by shortLabels but for the engine (a column of its own).
    static std::vector<compare::ConvergenceRow> csvRows(const std::vector<const PlotLine*>& lines);

private:
    std::vector<PlotLine> m_lines;
};

/// Each line's short name beside the others: its engine ("multi") and the strategy words in which the lines
/// differ ("multi nee-mis", "multi mixture"); the engine alone when they differ in none.
std::vector<std::string> shortLabels(const std::vector<const PlotLine*>& lines);

/// The work a line belongs to: `request`'s scene and settings with spp and seed cleared.
TimingKey plotWork(const RenderRequest& request);
} // namespace rt::gui
