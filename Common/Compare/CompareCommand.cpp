#include "Compare/CompareCommand.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/HeadlessRun.h"
#include "Cli/ValueParsing.h"
#include "Compare/AutoCommand.h"
#include "Compare/Compare.h"
#include "Compare/ReferenceRequest.h"
#include "Compare/ReferenceCache.h"
#include "Error.h"
#include "Render/EngineRegistry.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
void addCompareOptions(CLI::App& app, CompareFlags& flags)
{
    flags.referenceCache = defaultReferenceCacheDir().string();
    CLI::Option* compareFlag = app.add_flag("--compare", flags.compare,
                 "Headless comparison: render --scene at every count of --spp-list on every engine of --engines, "
                 "print time, CPU/GPU ratio and relMSE against a --reference-spp render; with --output FILE.png, "
                 "every engine x strategy's image at every spp with its false-colour error image in one figure (the "
                 "thesis' Tables 5.1-5.3); under mpirun, the ranks share its renders (docs/SCALING.md)");
    CLI::Option* sppList =
        app.add_option("--spp-list", flags.sppList, "With --compare: sample counts, comma separated")->capture_default_str();
    app.add_option("--engines", flags.engines,
                   "With --compare: engines, comma separated (single, multi, gpu; default: every engine this app "
                   "links)")
        ->check(CLI::Validator(
            // An empty value (a shell variable left unset) would read as "every engine": a comparison the user did
            // not ask for.
            [](std::string& text) {
                return text.empty() ? std::string("names no engine (single, multi or gpu, comma separated)")
                                    : std::string();
            },
            "ENGINES"));
    app.add_option("--reference-spp", flags.referenceSpp,
                   "With --compare: spp of the reference image (default: 4x the largest count), rendered by the "
                   "last engine in two halves (seeds + 1000 and + 2000) whose difference gives the reference's own "
                   "relMSE")
        ->check(CLI::PositiveNumber);
    app.add_option("--reference", flags.referencePath,
                   "With --compare: a linear PFM or OpenEXR of the same size (e.g. a long --hdr render) to measure against "
                   "instead of rendering a reference")
        ->check(CLI::ExistingFile);
    app.add_option("--table", flags.table, "With --compare: write every figure as JSON here")
        ->check(namesAFile())
        ->needs(compareFlag);
    for (const Setting* setting : strategySettings())
    {
        const std::string flag(setting->compareFlag);
        std::string help = fmt::format("With --compare: values of --{} to compare, comma separated ({}; default: "
                                       "--{}'s)",
                                       setting->name, setting->expected(), setting->name);
        if (setting->name == "estimator")
            help += "; every combination with the other lists is a strategy";
        app.add_option_function<std::string>(
               flag, [&flags, flag](const std::string& value) { flags.strategies[flag] = value; }, help)
            ->type_name("LIST")
            ->needs(compareFlag);
    }
    app.add_option("--csv", flags.csv,
                   "With --compare: one CSV row per engine x strategy x spp (scene, engine, device, strategy, label, "
                   "spp, wall ms, GPU ms, Mpaths/s, MSE, relMSE, RMSE), each written as its render ends (Ctrl-C keeps "
                   "them)")
        ->check(namesAFile())
        ->needs(compareFlag);
    app.add_option("--plot", flags.plot,
                   "With --compare and --csv: a PNG of relMSE against time and against spp (log-log, slope -1 "
                   "drawn) and of the efficiency 1/(relMSE s), drawn by matplotlib (python3-matplotlib)")
        ->check(namesAFile())
        ->needs(compareFlag);
    app.add_option("--equal-time", flags.equalTimeMs,
                   "With --compare: render every engine x strategy for this many milliseconds instead of the "
                   "--spp-list ladder, and write the images with their false-colour error images as one figure to "
                   "--output FILE.png, or the images alone to --images DIR")
        ->check(CLI::Validator(
            [](std::string& text) {
                const std::optional<float> value = parseReal(text);
                return value && std::isfinite(*value) && *value > 0.0
                           ? std::string()
                           : fmt::format("must be a positive number of milliseconds (got '{}')", text);
            },
            "MS"))
        ->needs(compareFlag)
        ->excludes(sppList); // the time sizes each row: a ladder's spp would be silently ignored
    app.add_option("--images", flags.images,
                   "With --compare: write every render's linear image (PFM) and the reference to this folder (made "
                   "when missing), with images.json listing each one's engine, strategy, spp, time and relMSE, for "
                   "analyses of one's own (the error over regions: tests/Bench/veach_regions.py)")
        ->type_name("DIR")
        ->check(namesAFile())
        ->needs(compareFlag);
    app.add_option("--seeds", flags.seeds,
                   "With --compare: render every row (engine x strategy x spp, or each strategy of --equal-time) with "
                   "this many independent seeds (--seed, --seed + 1, ...), 1 to 100; the tables and the JSON give the "
                   "mean relMSE with its 95 % Student-t interval and the median time, --equal-time each strategy's "
                   "efficiency against the best with the interval of the ratio (one that holds 1 is marked no "
                   "different); the CSV and --images keep every seed's render (default: 1, or 4 where restir-di is "
                   "compared: its pixels and iterations are correlated, so one render's relMSE tells little)")
        ->check(CLI::Range(1, 100))
        ->needs(compareFlag);
    app.add_option("--rounds", flags.rounds,
                   "With --compare: time every row this many times, 1 to 20, in interleaved rounds (every row, then "
                   "every row again), after an untimed render of every strategy; the tables report the median time "
                   "and its spread, the CSV and JSON every round")
        ->capture_default_str()
        ->check(CLI::Range(1, 20))
        ->needs(compareFlag);
    app.add_option("--metric", flags.metric,
                   "With --compare: the error the tables show and the efficiencies use: relmse (mean (I - R)^2 / (R^2 + "
                   "0.01)), trimmed-relmse (the same without the worst 0.1 % of pixels: fireflies), mape (mean |I - R| / "
                   "(|R| + 0.01)) or flip (mean HDR-FLIP, Andersson et al. 2021: 0.2 s per 512x384 render). Efficiency "
                   "is 1 / (error x s) for the squared errors and 1 / (error^2 x s) for MAPE and FLIP, so that it does "
                   "not change with spp; the CSV has every metric but FLIP unless it is chosen")
        ->capture_default_str()
        ->check(CLI::IsMember({"relmse", "trimmed-relmse", "mape", "flip"}))
        ->needs(compareFlag);
    app.add_option("--reference-cache", flags.referenceCache,
                   "With --compare: folder of rendered references, re-used when scene, settings, spp, seed and engine "
                   "match ('off': render the reference every time)")
        ->capture_default_str()
        ->needs(compareFlag);
}

int runCompare(const CompareFlags& flags, const CommonOptions& options, const EngineOptions& engineOptions)
{
    if (!options.heatmap.empty())
        throw UsageError("--heatmap times one render's pixels: run it with --headless, not --compare");
    // One render's outputs, which a comparison of many renders would silently ignore.
    if (!options.hdr.empty())
        throw UsageError("--hdr writes one render's image: with --compare, --images DIR keeps every render's PFM");
    if (!options.stats.empty())
        throw UsageError("--stats records one render: with --compare, --table FILE.json writes every figure");
    const CommandLineRender job = resolveCommandLine(options);
    CompareOptions c;
    c.spps = parseSppList(flags.sppList);
    c.engines = flags.engines.empty() ? engines::available() : parseEngineList(flags.engines);
    // The reference renders in two halves of referenceSpp / 2 each: each half is a render of at most kMaxSpp.
    const long long largest = *std::max_element(c.spps.begin(), c.spps.end());
    const long long referenceSpp = flags.referenceSpp > 0 ? flags.referenceSpp : kDefaultReferenceFactor * largest;
    if (referenceSpp > 2LL * kMaxSpp)
        throw UsageError(fmt::format("the reference's {} spp ({}) is more than two renders of at most {} spp: give "
                                     "--reference-spp up to {} or a smaller --spp-list",
                                     referenceSpp,
                                     flags.referenceSpp > 0 ? "--reference-spp" : "4x the largest of --spp-list",
                                     kMaxSpp, 2LL * kMaxSpp));
    c.referenceSpp = static_cast<int>(referenceSpp);
    c.json = flags.table;
    c.referencePath = flags.referencePath;
    c.strategies = strategyGrid(flags.strategies, job.request.settings);
    c.csv = flags.csv;
    c.plot = flags.plot;
    c.equalTimeMs = flags.equalTimeMs;
    c.grid = options.output;
    c.images = flags.images;
    c.seeds = flags.seeds;
    if (c.seeds == 0)
    {
        const bool restir = std::any_of(c.strategies.begin(), c.strategies.end(), [](const Strategy& x) {
            return x.settings.estimator == Estimator::RestirDi;
        });
        c.seeds = restir ? kRestirSeeds : 1;
        if (restir)
            spdlog::info("--seeds {}: restir-di's pixels and iterations are correlated, so every row is the mean of "
                         "{} independent renders (give --seeds to change it)",
                         kRestirSeeds, kRestirSeeds);
    }
    c.rounds = flags.rounds;
    for (ErrorMetric m : {ErrorMetric::RelMse, ErrorMetric::TrimmedRelMse, ErrorMetric::Mape, ErrorMetric::Flip})
        if (flags.metric == toString(m))
            c.metric = m;
    if (options.strategy == "auto" && options.strategyGiven) // the default adds no row: a comparison names its rows
    {
        c.autoCandidates = commandLineCandidates(job.scene, options, flags.strategies);
        c.pilotBudget = pilotBudget(options);
    }
    if (flags.referenceCache != "off")
        c.referenceCache = flags.referenceCache;
    return runComparison(job.scene, job.request, c,
                         [&](EngineKind kind) { return engines::make(kind, engineOptions); });
}
} // namespace rt::compare
