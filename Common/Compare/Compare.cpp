#include "Compare/Compare.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/HeadlessRun.h"
#include "Cli/Interrupt.h"
#include "Cli/ValueParsing.h"
#include "Cluster/Job.h"
#include "Compare/ComparisonRun.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/DistributedLadder.h"
#include "Compare/EqualTimeRun.h"
#include "Compare/ImageFolder.h"
#include "Compare/Ladder.h"
#include "Compare/PythonScript.h"
#include "Error.h"
#include "IO/TemporaryFolder.h"

namespace rt::compare
{
std::vector<int> parseSppList(const std::string& text)
{
    std::vector<int> spps;
    for (const std::string& part : splitCommas(text))
    {
        const auto value = parseInteger(part);
        if (!value || *value < 1 || *value > std::numeric_limits<int>::max())
            throw UsageError(fmt::format("--spp-list must be positive integers separated by commas (got '{}')", text));
        spps.push_back(static_cast<int>(*value));
    }
    if (spps.empty())
        throw UsageError("--spp-list is empty");
    return spps;
}

std::vector<EngineKind> parseEngineList(const std::string& text)
{
    std::vector<EngineKind> engines;
    for (const std::string& part : splitCommas(text))
    {
        const auto e = parseName<EngineKind>(part);
        if (!e)
            throw UsageError(fmt::format("--engines takes single, multi and gpu (got '{}')", part));
        if (std::find(engines.begin(), engines.end(), *e) != engines.end())
            throw UsageError(fmt::format("--engines lists {} twice", toString(*e)));
        engines.push_back(*e);
    }
    if (engines.empty())
        throw UsageError("--engines is empty");
    return engines;
}

std::string keptOnCancel(const CompareOptions& options, bool csvOpen, bool imagesFolder)
{
    std::string kept;
    if (csvOpen)
        kept = fmt::format("{} keeps the rows finished before", options.csv);
    if (imagesFolder)
        kept += fmt::format("{}{} keeps the images rendered before (images.json)", kept.empty() ? "" : "; ",
                            options.images.string());
    return kept.empty() ? ": nothing written" : ": " + kept;
}

void checkComparison(const CompareOptions& options)
{
    if (options.strategies.empty())
        throw UsageError("--compare has no strategy to render");
    checkOutputPath(options.csv, "--csv", {".csv"});
    checkOutputPath(options.plot, "--plot", {".png"});
    checkOutputPath(options.json, "--table", {".json"});
    checkOutputPath(options.grid, "--output", {".png"});
    checkDistinctOutputs(
        {{"--csv", &options.csv}, {"--plot", &options.plot}, {"--table", &options.json}, {"--output", &options.grid}});
    if (!options.plot.empty() && options.csv.empty())
        throw UsageError("--plot draws the rows of --csv: give --csv FILE.csv too");
    if (options.equalTimeMs > 0.0 && options.grid.empty() && options.images.empty())
        throw UsageError("--equal-time writes its figure to --output FILE.png or its images to --images DIR: give "
                         "either");
    if (!options.plot.empty())
    {
        scriptPath("plot_convergence.py");
        requireMatplotlib("--plot");
    }
    if (!options.grid.empty())
    {
        scriptPath(options.equalTimeMs > 0.0 ? "equal_time_grid.py" : "ladder_grid.py");
        requireMatplotlib("--output");
    }
}

namespace
{
/// The reference of a comparison on one process: the file given, the cached render, or a new render by the last
/// engine in two halves of independent seeds, whose mean is the reference and whose difference tells its own
/// error, then cached. nullopt when Ctrl-C stopped it.
std::optional<Reference> obtainReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                                         EngineUnderTest& last)
{
    if (std::optional<Reference> given = givenReference(scene, base, options, last.kind))
        return given;
    std::fprintf(stderr, "reference: rendering 2 x %d spp on the %s engine...\n",
                 referenceHalf(base, options, 0).settings.spp, toString(last.kind));
    Measurement a = measure(*last.engine, referenceHalf(base, options, 0), nullptr);
    if (a.cancelled)
        return std::nullopt;
    Measurement b = measure(*last.engine, referenceHalf(base, options, 1), nullptr);
    if (b.cancelled)
        return std::nullopt;
    return finishReference(scene, base, options, last.kind, a, b);
}
} // namespace

int runComparison(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  const std::function<std::unique_ptr<RenderEngine>(EngineKind)>& makeEngine)
{
    cluster::Job& job = cluster::job();
    if (job.distributed() && options.equalTimeMs > 0.0)
        throw UsageError("--equal-time's renders are not shared over mpirun's ranks: run it as one process");
    if (job.distributed() && !options.autoCandidates.empty())
        throw UsageError("--strategy auto's pilot chooses on one process: run the comparison without mpirun");
    if (job.root())
        checkComparison(options); // root alone writes (on its host's folders)
    else if (options.strategies.empty())
        throw UsageError("--compare has no strategy to render");
    // The ladder's --output figure is drawn from its images: kept in a temporary folder without --images.
    std::optional<TemporaryFolder> gridImages;
    if (job.root() && !options.grid.empty() && !(options.equalTimeMs > 0.0) && options.images.empty())
        gridImages.emplace("ray-tracing-ladder");
    ImageFolder images(!job.root() ? std::filesystem::path() : gridImages ? gridImages->path() : options.images,
                       scene.id, base.settings.width, base.settings.height());
    // relMSE is a mean over pixels whose squared errors are heavy-tailed (a firefly counts its square): over a
    // few thousand pixels a handful decide it, and rows differ by which ones they caught.
    constexpr int kFewPixels = 64 * 64;
    if (job.root() && base.settings.width * base.settings.height() < kFewPixels)
        spdlog::warn("a {}x{} comparison: its errors rest on {} pixels, where a few of the worst decide them; 64x64 or "
                     "more (or --metric trimmed-relmse) measures steadier",
                     base.settings.width, base.settings.height(), base.settings.width * base.settings.height());
    // One engine of each kind, its acceleration structures built once.
    std::vector<EngineUnderTest> engines;
    for (const EngineKind kind : options.engines)
    {
        try
        {
            auto engine = makeEngine(kind);
            const double build = engine->setScene(scene);
            spdlog::info("{} engine on {}: acceleration structures in {:.3f} s", toString(kind), engine->deviceName(),
                         build);
            images.setDevice(kind, engine->deviceName());
            engines.push_back({kind, std::move(engine)});
        }
        catch (const DeviceError& e)
        {
            // Every rank of a job must render every row it may be handed.
            if (job.distributed())
                throw DeviceError(fmt::format("{} engine: {}", toString(kind), e.what()));
            spdlog::warn("{} engine left out: {}", toString(kind), e.what());
        }
    }
    if (engines.empty())
        throw DeviceError("no engine could start");

    InterruptScope interrupt;
    if (job.distributed())
        return runDistributedLadder(scene, base, options, engines, images);
    const std::optional<Reference> reference = obtainReference(scene, base, options, engines.back());
    std::unique_ptr<ConvergenceCsv> csv;
    bool finished = false;
    if (reference)
    {
        images.addReference(reference->image, reference->description, reference->spp, reference->ownRelMse);
        if (!options.csv.empty())
            csv = std::make_unique<ConvergenceCsv>(options.csv);
        finished = options.equalTimeMs > 0.0 ? runEqualTime(scene, base, options, engines, *reference, csv.get(), images)
                                             : runLadder(scene, base, options, engines, *reference, csv.get(), images);
    }
    if (!finished)
    {
        spdlog::warn("comparison cancelled{}", keptOnCancel(options, csv != nullptr, images.enabled()));
        return 130;
    }
    drawFigures(options, images);
    return 0;
}

} // namespace rt::compare
