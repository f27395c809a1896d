// What the two kinds of comparison (the ladder: Ladder.h; the equal-time figure: EqualTimeRun.h) share: the
// engines under test, the run's progress lines, the order and warm-up of the engines, and how a render's figures
// are worded and filed. Internal to Compare/.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Compare/AutoStrategy.h"
#include "Compare/Compare.h"
#include "Compare/Confidence.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/ImageFolder.h"
#include "Compare/Measurement.h"
#include "Compare/RowJob.h"
#include "Compare/Strategy.h"
#include "Image/Metrics.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"
#include "Scene/Scene.h"

namespace rt::compare
{
struct EngineUnderTest
{
    EngineKind kind;
    std::unique_ptr<RenderEngine> engine;
};

/// Progress of the whole run on stderr: one line per finished render, with the elapsed time.
class RunLog
{
public:
    explicit RunLog(std::size_t renders) : m_renders(renders) {}
    void done(const std::string& what)
    {
        ++m_done;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        std::fprintf(stderr, "[%zu/%zu, %.1f s] %s\n", m_done, m_renders, s, what.c_str());
    }

private:
    std::size_t m_renders;
    std::size_t m_done = 0;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// The reference the options name without rendering one: the file of --reference, or the cached render of the
/// same scene, settings and engine kind (ReferenceCache.h); nullopt when neither. Throws UsageError for a file of
/// the wrong size or with pixels that are not finite.
std::optional<Reference> givenReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                                        EngineKind last);
/// The request of the reference's half 0 or 1: referenceSpp / 2 (rounded up) at seed + 1000, and + 2000 for half 1.
RenderRequest referenceHalf(const RenderRequest& base, const CompareOptions& options, int half);
/// The reference from its halves' renders by an engine of kind `last`: their mean, its own relMSE from their
/// difference (Image/Metrics.h); cached (ReferenceCache.h) and reported on stderr.
Reference finishReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                          EngineKind last, const Measurement& a, const Measurement& b);

/// Rows whose relMSE is less than 3x the reference's own carry a third or more of the reference's noise: one
/// warning naming how many and the smallest.
void warnNearReferenceNoise(const Reference& reference, const std::vector<double>& relMses);

/// --table's head, shared by the ladder's and the equal-time comparison's: the base settings by the settings
/// table's keys (no spp: each row names its own), the scene, the reference (its spp, or the file given), relMSE's
/// epsilon, the metric, the reference's own relMSE and each engine's device.
nlohmann::json tableHead(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                         const std::vector<EngineUnderTest>& engines, const Reference& reference);

/// "estimator nee-mis, light-sampler projected, ...": the strategy settings, as the command line names them.
std::string describeStrategy(const RenderSettings& settings);

/// "relMSE against 4096 spp (epsilon 0.01; the reference's own relMSE 3.4e-04 is part of every relMSE)".
std::string againstReference(const Reference& reference, ErrorMetric metric);

/// The order in which the engines run their renders: the GPU's first. After the CPU's rows of a long table
/// (200 s of 16-thread renders) the H100's rows at 10-250 spp were 1.7-5.6x slower than a GPU-only run
/// (docs/notebook/PERFORMANCE.md §2).
std::vector<std::size_t> measurementOrder(const std::vector<EngineUnderTest>& engines);

/// Untimed renders of every strategy the comparison measures, before any timing: warmUp's half second of the
/// first (the GPU's clocks), then one render of each other, so that no row pays a pipeline's compilation or a
/// code path's first use (on an H200, 115 ms charged to whichever row came first: issue 39).
void warmUpStrategies(RenderEngine& engine, const RenderRequest& base, const std::vector<Strategy>& strategies);

/// The auto row's pilot is part of its cost: its renders' time on the engine's clock joins the GPU's time, and the
/// whole pilot on the host's clock (pipeline compilations included) the wall time.
void chargePilot(Measurement& m, const AutoChoice& choice);

/// "auto: nee projected": what the pilot chose, in the words that tell the grid's strategies apart.
std::string autoLabel(const std::vector<Strategy>& grid, const Strategy& chosen);

/// Mean HDR-FLIP of round 0's render against the reference, into m.error.flip, when the comparison measures by
/// FLIP (0.2 s at 512 x 384: every other round renders the same image again).
void measureFlip(const CompareOptions& options, int round, const Reference& reference, Measurement& m);

/// The CSV row of a render by `engine` on `device`, at rank `rank` of the job (0 for one process).
ConvergenceRow csvRow(const std::string& scene, EngineKind engine, const std::string& device, const Strategy& strategy,
                      const std::string& label, const Measurement& m, const Reference& reference, std::uint32_t seed,
                      int round, int rank);

/// The figures of a finished comparison, each when asked for: --plot's of --csv's rows (plot_convergence.py) and,
/// for a ladder, --output's of the images of every engine x strategy at every spp with their error images
/// (ladder_grid.py, from `images`' index; --equal-time draws its own). Says so on stdout. Throws OutputError
/// when a script fails (nothing written in its place).
void drawFigures(const CompareOptions& options, const ImageFolder& images);

/// " ±4.1e-05" (half the 95 % interval) when there are several seeds, else nothing.
std::string plusMinus(const Interval& i);
} // namespace rt::compare
