#include "Compare/Compare.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "Render/SettingsTable.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/Confidence.h"
#include "Compare/EqualTime.h"
#include "Compare/ImageFolder.h"
#include "Compare/Measurement.h"
#include "Compare/PythonScript.h"
#include "Compare/ReferenceCache.h"
#include "Cli/HeadlessRun.h"
#include "Cli/Interrupt.h"
#include "Cli/ValueParsing.h"
#include "Error.h"
#include "IO/AtomicFile.h"
#include "Image/Flip.h"
#include "Image/ImageIO.h"
#include "Image/Metrics.h"

namespace rt::compare
{
namespace
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

/// What every relMSE of a comparison is measured against.
struct Reference
{
    Image image;
    std::optional<double> ownRelMse; // the reference's own noise in every relMSE (none known for a file)
    std::string description; // "4096 spp" or the file's path
    int spp = 0; // both halves together; 0 for a file
};

/// The reference image: the file given, the cached render of the same scene and settings, or a new render by
/// the last engine at referenceSpp in two halves of independent seeds (seed + 1000 and seed + 2000), whose
/// mean is the reference and whose difference tells its own error (Image/Metrics.h), then cached. nullopt
/// when Ctrl-C stopped it.
std::optional<Reference> obtainReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                                         EngineUnderTest& last)
{
    if (!options.referencePath.empty())
    {
        Image reference = readLinearImage(options.referencePath);
        if (reference.width() != base.settings.width || reference.height() != base.settings.height())
            throw UsageError(fmt::format("--reference {} is {}x{}; the comparison renders {}x{}", options.referencePath,
                                         reference.width(), reference.height(), base.settings.width,
                                         base.settings.height()));
        std::size_t notFinite = 0;
        for (std::size_t i = 0; i < reference.pixelCount(); ++i)
            notFinite += isFinite(reference.data()[i]) ? 0 : 1;
        if (notFinite > 0)
            throw UsageError(fmt::format("--reference {}: {} of its pixels are not finite (NaN or Inf): no relMSE can "
                                         "be measured against it",
                                         options.referencePath, notFinite));
        spdlog::info("reference: {}", options.referencePath);
        return Reference{std::move(reference), std::nullopt, options.referencePath, 0};
    }
    const int halfSpp = std::max(1, (options.referenceSpp + 1) / 2);
    const int referenceSpp = 2 * halfSpp; // both halves
    const std::string description = fmt::format("{} spp", referenceSpp);
    RenderRequest request = base;
    request.settings.spp = options.referenceSpp;
    request.settings.seed += 1000;
    const ReferenceCache cache(options.referenceCache);
    if (std::optional<TwoHalfReference> cached = cache.find(scene, request, last.kind))
    {
        std::fprintf(stderr, "reference: %s on the %s engine, from the cache (%s)\n", description.c_str(),
                     toString(last.kind), options.referenceCache.string().c_str());
        return Reference{std::move(cached->mean), cached->ownRelMse, description, referenceSpp};
    }
    std::fprintf(stderr, "reference: rendering 2 x %d spp on the %s engine...\n", halfSpp, toString(last.kind));
    RenderRequest half = request;
    half.settings.spp = halfSpp;
    Measurement a = measure(*last.engine, half, nullptr);
    if (a.cancelled)
        return std::nullopt;
    half.settings.seed += 1000;
    Measurement b = measure(*last.engine, half, nullptr);
    if (b.cancelled)
        return std::nullopt;
    TwoHalfReference combined = combineReferenceHalves(a.image, b.image);
    std::fprintf(stderr, "reference: %.1f s; its own relMSE %.3g (from its halves)\n", (a.wallMs + b.wallMs) * 1e-3,
                 combined.ownRelMse);
    const auto stored = cache.store(scene, request, last.kind, combined);
    if (!stored.empty())
        std::fprintf(stderr, "reference: cached as %s\n", stored.string().c_str());
    return Reference{std::move(combined.mean), combined.ownRelMse, description, referenceSpp};
}

/// Rows whose relMSE is less than 3x the reference's own carry a third or more of the reference's noise: one
/// warning naming how many and the smallest.
void warnNearReferenceNoise(const Reference& reference, const std::vector<double>& relMses)
{
    if (!reference.ownRelMse)
        return;
    const double floor = *reference.ownRelMse;
    const auto near = std::count_if(relMses.begin(), relMses.end(), [&](double e) { return e < 3.0 * floor; });
    if (near == 0)
        return;
    spdlog::warn("{} of {} renders have a relMSE below 3x the reference's own ({:.3g}; the smallest {:.3g}): a "
                 "third or more of their error is the reference's noise; raise --reference-spp",
                 near, relMses.size(), floor, *std::min_element(relMses.begin(), relMses.end()));
}

/// "relMSE against 4096 spp (epsilon 0.01; the reference's own relMSE 3.4e-04 is part of every value)".
/// "estimator nee-mis, light-sampler projected, ...": the strategy settings, as the command line names them.
std::string describeStrategy(const RenderSettings& settings)
{
    std::vector<std::string> parts;
    for (const Setting* s : strategySettings())
        parts.push_back(fmt::format("{} {}", s->name, s->text(settings)));
    return fmt::format("{}", fmt::join(parts, ", "));
}

std::string againstReference(const Reference& reference, ErrorMetric metric)
{
    std::string text = fmt::format("{} against {} (", displayName(metric), reference.description);
    text += metric == ErrorMetric::Flip ? std::string("HDR-FLIP, exposures from the reference")
                                        : fmt::format("epsilon {:g}", kRelMseEpsilon);
    if (reference.ownRelMse)
        text += fmt::format("; the reference's own relMSE {:.2e} is part of every relMSE", *reference.ownRelMse);
    return text + ")";
}

/// The order in which the engines run their renders: the GPU's first. After the CPU's rows of a long table
/// (200 s of 16-thread renders) the H100's rows at 10-250 spp were 1.7-5.6x slower than a GPU-only run
/// (docs/notebook/PERFORMANCE.md §2).
std::vector<std::size_t> measurementOrder(const std::vector<EngineUnderTest>& engines)
{
    std::vector<std::size_t> order(engines.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t e) { return engines[e].kind == EngineKind::Gpu; });
    return order;
}

/// One row of a comparison: its render with each of options.seeds seeds (the request's seed + k), timed in
/// each of options.rounds interleaved rounds. A seed renders the same image in every round (the same streams);
/// the rounds measure its time again. The first seed's first round keeps its image (the CPU/GPU comparison, the
/// equal-time figure); the others' images are dropped once measured.
struct SeededRow
{
    std::vector<std::vector<Measurement>> runs; // [seed][round]

    const Measurement& first() const { return runs.front().front(); }
    /// Round 0's value of each seed.
    std::vector<double> values(double (*of)(const Measurement&)) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
            out.push_back(of(seed.front()));
        return out;
    }
    static double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
    /// Every seed's and round's value.
    std::vector<double> all(double (*of)(const Measurement&)) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
            for (const Measurement& m : seed)
                out.push_back(of(m));
        return out;
    }
    double ms() const { return median(all([](const Measurement& m) { return m.ms(); })); }
    double wallMs() const { return median(all([](const Measurement& m) { return m.wallMs; })); }
    double gpuMs() const { return median(all([](const Measurement& m) { return m.gpuMs; })); }
    /// (max - min) / median of every time: the rounds' (and seeds') spread.
    double spread() const
    {
        const std::vector<double> t = all([](const Measurement& m) { return m.ms(); });
        return (*std::max_element(t.begin(), t.end()) - *std::min_element(t.begin(), t.end())) / median(t);
    }
    Interval relMse() const { return metric(ErrorMetric::RelMse); }
    /// The metric's mean over the seeds (round 0's value: every round renders the same image).
    Interval metric(ErrorMetric which) const
    {
        std::vector<double> v;
        for (const auto& seed : runs)
            v.push_back(metricValue(seed.front().error, which));
        return meanInterval(v);
    }
    /// metric^k x seconds per seed (k = efficiencyPower), at the median of its rounds' times: the inverse of
    /// the efficiency 1 / (metric^k s).
    std::vector<double> costs(ErrorMetric which) const
    {
        std::vector<double> out;
        for (const auto& seed : runs)
        {
            std::vector<double> t;
            for (const Measurement& m : seed)
                t.push_back(m.ms());
            out.push_back(std::pow(metricValue(seed.front().error, which), efficiencyPower(which)) * median(t) * 1e-3);
        }
        return out;
    }
    /// Files `m`, the render of seed index k in its round, dropping its image unless it is the first's.
    void add(std::size_t k, Measurement m)
    {
        if (runs.size() <= k)
            runs.resize(k + 1);
        if (k > 0 || !runs[k].empty())
            m.image = Image();
        runs[k].push_back(std::move(m));
    }
};

/// Untimed renders of every strategy the comparison measures, before any timing: warmUp's half second of the
/// first (the GPU's clocks), then one render of each other, so that no row pays a pipeline's compilation or a
/// code path's first use (on an H200, 115 ms charged to whichever row came first: issue 39).
void warmUpStrategies(RenderEngine& engine, const RenderRequest& base, const std::vector<Strategy>& strategies)
{
    warmUp(engine, strategies.front().request(base, 4));
    for (std::size_t s = 1; s < strategies.size(); ++s)
        if (measure(engine, strategies[s].request(base, 1), nullptr).cancelled)
            return;
}

/// The auto row's pilot is part of its cost: its renders' time on the engine's clock joins the GPU's time, and the
/// whole pilot on the host's clock (pipeline compilations included) the wall time.
void chargePilot(Measurement& m, const AutoChoice& choice)
{
    m.wallMs += choice.pilotWallSeconds * 1e3;
    if (m.gpuMs >= 0.0)
        m.gpuMs += choice.pilotMs;
}

/// "auto: nee projected": what the pilot chose, in the words that tell the grid's strategies apart.
std::string autoLabel(const std::vector<Strategy>& grid, const Strategy& chosen)
{
    std::vector<Strategy> all = grid;
    all.push_back(chosen);
    return "auto: " + distinctLabels(all).back();
}

/// Mean HDR-FLIP of round 0's render against the reference, into m.error.flip, when the comparison measures by
/// FLIP (0.2 s at 512 x 384: every other round renders the same image again).
void measureFlip(const CompareOptions& options, int round, const Reference& reference, Measurement& m)
{
    if (options.metric == ErrorMetric::Flip && round == 0)
        m.error.flip = meanHdrFlip(m.image, reference.image);
}

ConvergenceRow csvRow(const std::string& scene, const EngineUnderTest& e, const Strategy& strategy,
                      const std::string& label, const Measurement& m, const Reference& reference, std::uint32_t seed,
                      int round)
{
    return {scene, toString(e.kind), e.engine->deviceName(), strategy.name(), label, m.spp, m.wallMs, m.gpuMs,
            m.mpathsPerSecond, m.error.mse, m.error.relMse, m.error.rmse, reference.ownRelMse.value_or(-1.0), seed,
            round, m.error.trimmedRelMse, m.error.mape, m.error.flip};
}

/// " ±4.1e-05" (half the 95 % interval) when there are several seeds, else nothing.
std::string plusMinus(const Interval& i)
{
    return i.count > 1 ? fmt::format(" ±{:<8.2g}", 0.5 * (i.hi - i.lo)) : std::string();
}

/// The ladder: every engine x strategy x spp against the reference; rows to the CSV as they finish, the table
/// to stdout and the JSON at the end. Returns false when Ctrl-C stopped it.
bool runLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
               std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
               ImageFolder& images)
{
    const std::vector<std::string> labels = distinctLabels(options.strategies);
    const std::size_t strategyCount = options.strategies.size();
    const bool autoRow = !options.autoCandidates.empty();
    const std::size_t rowCount = strategyCount + (autoRow ? 1 : 0); // the auto row last
    // runs[engine][strategy][spp index]
    std::vector<std::vector<std::vector<SeededRow>>> runs(engines.size());
    // The auto row's choices: choices[engine][spp index][seed].
    std::vector<std::vector<std::vector<AutoChoice>>> choices(engines.size());
    RunLog log(engines.size() * rowCount * options.spps.size() * std::size_t(options.seeds) *
               std::size_t(options.rounds));
    // Each engine runs all its rows back to back after its warm-up: row by row interleaving with 16-thread CPU
    // renders cost an H100 2-3x (docs/notebook/PERFORMANCE.md). Within an engine the rounds interleave the rows:
    // every row once, then every row again, so that a drift of the clocks spreads over all of them.
    for (const std::size_t e : measurementOrder(engines))
    {
        RenderEngine& engine = *engines[e].engine;
        warmUpStrategies(engine, base, options.strategies);
        runs[e].assign(rowCount, std::vector<SeededRow>(options.spps.size()));
        choices[e].assign(options.spps.size(), std::vector<AutoChoice>(std::size_t(options.seeds)));
        for (int round = 0; round < options.rounds; ++round)
            for (std::size_t s = 0; s < rowCount; ++s)
                for (std::size_t row = 0; row < options.spps.size(); ++row)
                    for (int k = 0; k < options.seeds; ++k)
                    {
                        const bool isAuto = s == strategyCount;
                        RenderRequest request = isAuto ? base : options.strategies[s].request(base, options.spps[row]);
                        request.settings.spp = options.spps[row];
                        request.settings.seed += std::uint32_t(k);
                        AutoChoice& choice = choices[e][row][std::size_t(k)];
                        if (isAuto && round == 0)
                        {
                            choice = chooseStrategy(engine, request, options.autoCandidates, options.pilotBudget);
                            if (choice.cancelled)
                                return false;
                        }
                        const Strategy strategy = isAuto ? choice.chosen : options.strategies[s];
                        const std::string label = isAuto ? autoLabel(options.strategies, choice.chosen) : labels[s];
                        request.settings = strategy.applyTo(request.settings);
                        Measurement m = measure(engine, request, &reference.image);
                        if (m.cancelled)
                            return false;
                        if (isAuto)
                            chargePilot(m, choice);
                        measureFlip(options, round, reference, m);
                        const std::uint32_t seed = request.settings.seed;
                        log.done(fmt::format("{} {}, {} spp, seed {}, round {}: {:.1f} ms, {} {:.3g}",
                                             toString(engines[e].kind), label, m.spp, seed, round, m.ms(),
                                             displayName(options.metric), metricValue(m.error, options.metric)));
                        if (csv)
                            csv->append(csvRow(scene.id, engines[e], strategy, label, m, reference, seed, round));
                        if (round == 0)
                            images.add(engines[e].kind, strategy.name(), label, m, seed);
                        runs[e][s][row].add(std::size_t(k), std::move(m));
                    }
    }

    const RenderSettings& b = base.settings;
    nlohmann::json json = toJson(b); // the base settings by the settings table's keys; each row names its spp
    json.erase("spp");
    json["scene"] = scene.id;
    json["height"] = b.height();
    if (options.referencePath.empty())
        json["reference_spp"] = reference.spp;
    else
        json["reference"] = options.referencePath;
    json["relmse_epsilon"] = kRelMseEpsilon;
    json["metric"] = toString(options.metric);
    json["reference_relmse"] = reference.ownRelMse ? nlohmann::json(*reference.ownRelMse) : nlohmann::json();
    for (const EngineUnderTest& e : engines)
        json["devices"][toString(e.kind)] = e.engine->deviceName();
    json["rows"] = nlohmann::json::array();

    const bool ratio = engines.size() > 1 && engines.back().kind == EngineKind::Gpu;
    for (std::size_t s = 0; s < rowCount; ++s)
    {
        const bool isAuto = s == strategyCount;
        std::string strategyText;
        if (isAuto)
        {
            strategyText = "--strategy auto, the pilot's time included; chosen";
            for (std::size_t e = 0; e < engines.size(); ++e)
                for (std::size_t row = 0; row < options.spps.size(); ++row)
                    strategyText += fmt::format("{} {} at {} spp: {}", e + row == 0 ? "" : ",", toString(engines[e].kind),
                                                options.spps[row],
                                                autoLabel(options.strategies, choices[e][row].front().chosen).substr(6));
        }
        else
            strategyText = describeStrategy(options.strategies[s].applyTo(b));
        std::printf("\n%s: %dx%d, depth %d, %s; %s\n", scene.id.c_str(), b.width, b.height(), b.depth,
                    strategyText.c_str(), againstReference(reference, options.metric).c_str());
        std::string header = fmt::format("{:>6}", "spp");
        for (const EngineUnderTest& e : engines)
            header += fmt::format(" | {:>9} {:>9}{}{}", fmt::format("{} ms", toString(e.kind)),
                                  displayName(options.metric),
                                  options.seeds > 1 ? fmt::format(" {:<9}", "±95%") : std::string(),
                                  options.rounds > 1 ? fmt::format(" {:>6}", "range%") : std::string());
        if (ratio)
            header += fmt::format(" | {:>10} | {:>11}", "CPU/GPU", "relMSE C-G");
        std::printf("%s\n%s\n", header.c_str(), std::string(header.size(), '-').c_str());
        for (std::size_t row = 0; row < options.spps.size(); ++row)
        {
            std::string line = fmt::format("{:>6}", runs.front()[s][row].first().spp);
            nlohmann::json jrow;
            jrow["spp"] = runs.front()[s][row].first().spp;
            jrow["strategy"] = isAuto ? std::string("auto") : options.strategies[s].name();
            const SeededRow* gpu = nullptr;
            const SeededRow* cpu = nullptr; // the fastest CPU engine of the row
            for (std::size_t e = 0; e < engines.size(); ++e)
            {
                const SeededRow& seeded = runs[e][s][row];
                const Measurement& m = seeded.first();
                const Interval relMse = seeded.relMse();
                const Interval shown = seeded.metric(options.metric);
                line += fmt::format(" | {:>9.1f} {:>9.2e}{}", seeded.ms(), shown.mean, plusMinus(shown));
                if (options.rounds > 1)
                    line += fmt::format(" {:>6.1f}", 100.0 * seeded.spread());
                nlohmann::json& j = jrow[toString(engines[e].kind)];
                j = {{"render_ms", seeded.wallMs()},
                     {"gpu_ms", seeded.gpuMs()},
                     {"mpaths_per_second", m.mpathsPerSecond},
                     {"mse", m.error.mse},
                     {"relmse", relMse.mean},
                     {"trimmed_relmse", seeded.metric(ErrorMetric::TrimmedRelMse).mean},
                     {"mape", seeded.metric(ErrorMetric::Mape).mean},
                     {"rmse", m.error.rmse}};
                if (options.metric == ErrorMetric::Flip)
                    j["flip"] = shown.mean;
                if (options.rounds > 1)
                {
                    j["rounds"] = options.rounds;
                    j["ms_spread"] = seeded.spread();
                    j["ms_rounds"] = nlohmann::json::array();
                    for (const auto& seedRuns : seeded.runs)
                    {
                        nlohmann::json times = nlohmann::json::array();
                        for (const Measurement& x : seedRuns)
                            times.push_back(x.ms());
                        j["ms_rounds"].push_back(times);
                    }
                }
                if (options.seeds > 1)
                {
                    j["seeds"] = options.seeds;
                    j["relmse_ci95"] = {relMse.lo, relMse.hi};
                    j["relmse_seeds"] = seeded.values([](const Measurement& x) { return x.error.relMse; });
                    if (options.metric != ErrorMetric::RelMse)
                        j[fmt::format("{}_ci95", toString(options.metric))] = {shown.lo, shown.hi};
                    j["mse"] = meanInterval(seeded.values([](const Measurement& x) { return x.error.mse; })).mean;
                    j["rmse"] = meanInterval(seeded.values([](const Measurement& x) { return x.error.rmse; })).mean;
                }
                if (isAuto)
                {
                    j["strategy_choice"] = nlohmann::json::array();
                    for (const AutoChoice& c : choices[e][row])
                        j["strategy_choice"].push_back(c.toJson());
                }
                if (engines[e].kind == EngineKind::Gpu)
                    gpu = &seeded;
                else if (!cpu || seeded.wallMs() < cpu->wallMs())
                    cpu = &seeded;
            }
            if (ratio && gpu && cpu)
            {
                const double between = compareImages(cpu->first().image, gpu->first().image).relMse;
                line += fmt::format(" | {:>9.1f}x | {:>11.2e}", cpu->wallMs() / gpu->ms(), between);
                jrow["cpu_over_gpu"] = cpu->wallMs() / gpu->ms();
                jrow["relmse_cpu_gpu"] = between;
            }
            std::printf("%s\n", line.c_str());
            json["rows"].push_back(jrow);
        }
    }
    std::printf("(GPU ms from timestamp queries around the trace dispatches; CPU ms from the host clock; "
                "CPU/GPU uses the fastest CPU engine of the row)\n");
    std::vector<double> relMses;
    for (const auto& engineRuns : runs)
        for (const auto& strategyRuns : engineRuns)
            for (const SeededRow& row : strategyRuns)
                relMses.push_back(row.relMse().mean);
    warnNearReferenceNoise(reference, relMses);
    if (!options.json.empty())
        writeFileAtomically(options.json, json.dump(2) + "\n");
    return true;
}

/// The equal-time comparison: every engine x strategy for options.equalTimeMs, one figure (tiles in the
/// engines' order). Returns false when Ctrl-C stopped it.
bool runEqualTime(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
                  ImageFolder& images)
{
    const std::vector<std::string> labels = distinctLabels(options.strategies);
    const std::size_t strategyCount = options.strategies.size();
    const bool autoRow = !options.autoCandidates.empty();
    const std::size_t rowCount = strategyCount + (autoRow ? 1 : 0); // the auto row last
    RunLog log(engines.size() * rowCount * std::size_t(options.seeds) * std::size_t(options.rounds));
    std::string devices;
    for (const EngineUnderTest& e : engines)
        devices += (devices.empty() ? "" : ", ") + e.engine->deviceName();
    // seeded[engine][strategy]: the first seed's first render is the tile.
    std::vector<std::vector<SeededRow>> seeded(engines.size());
    // The auto row's choice of each seed: choices[engine][seed].
    std::vector<std::vector<AutoChoice>> choices(engines.size());
    for (const std::size_t index : measurementOrder(engines))
    {
        EngineUnderTest& e = engines[index];
        warmUpStrategies(*e.engine, base, options.strategies);
        seeded[index].resize(rowCount);
        choices[index].resize(std::size_t(options.seeds));
        // What the budget gave each strategy's first seed; the auto row's per seed (each its own choice).
        std::vector<int> spps(strategyCount, 0), autoSpps(std::size_t(options.seeds), 0);
        for (int round = 0; round < options.rounds; ++round)
            for (std::size_t s = 0; s < rowCount; ++s)
                for (int k = 0; k < options.seeds; ++k)
                {
                    const bool isAuto = s == strategyCount;
                    int& spp = isAuto ? autoSpps[std::size_t(k)] : spps[s];
                    RenderRequest seededBase = base;
                    seededBase.settings.seed += std::uint32_t(k);
                    AutoChoice& choice = choices[index][std::size_t(k)];
                    if (isAuto && round == 0)
                    {
                        // The pilot's budget is a share of the equal time, the render what is left of it.
                        PilotBudget budget = options.pilotBudget;
                        budget.renderSeconds = options.equalTimeMs * 1e-3;
                        choice = chooseStrategy(*e.engine, seededBase, options.autoCandidates, budget);
                        if (choice.cancelled)
                            return false;
                    }
                    const Strategy strategy = isAuto ? choice.chosen : options.strategies[s];
                    const std::string label = isAuto ? autoLabel(options.strategies, choice.chosen) : labels[s];
                    const double budgetMs =
                        isAuto ? std::max(options.equalTimeMs - choice.pilotMs, 0.01 * options.equalTimeMs)
                               : options.equalTimeMs;
                    RenderRequest request = strategy.request(base, std::max(spp, 1));
                    request.settings.seed += std::uint32_t(k);
                    Measurement m = spp == 0 ? renderForBudget(*e.engine, seededBase, strategy, budgetMs, reference.image)
                                             : measure(*e.engine, request, &reference.image);
                    if (m.cancelled)
                        return false;
                    measureFlip(options, round, reference, m);
                    spp = m.spp;
                    if (isAuto)
                        chargePilot(m, choice);
                    const std::uint32_t seed = request.settings.seed;
                    log.done(fmt::format("{} {}, seed {}, round {}: {} spp in {:.1f} ms, {} {:.3g}", toString(e.kind),
                                         label, seed, round, m.spp, m.ms(), displayName(options.metric),
                                         metricValue(m.error, options.metric)));
                    if (csv)
                        csv->append(csvRow(scene.id, e, strategy, label, m, reference, seed, round));
                    if (round == 0)
                        images.add(e.kind, strategy.name(), label, m, seed);
                    seeded[index][s].add(std::size_t(k), std::move(m));
                }
    }
    // The tiles in the engines' order, each its strategy's first render.
    std::vector<EqualTimeTile> tiles;
    std::vector<const SeededRow*> rows; // in the tiles' order
    for (std::size_t e = 0; e < engines.size(); ++e)
        for (std::size_t s = 0; s < seeded[e].size(); ++s)
        {
            const bool isAuto = s == strategyCount;
            const Strategy strategy = isAuto ? choices[e].front().chosen : options.strategies[s];
            tiles.push_back({engines[e].kind, isAuto ? autoLabel(options.strategies, strategy) : labels[s], strategy,
                             seeded[e][s].first()});
            rows.push_back(&seeded[e][s]);
        }
    // Efficiency ratios against the most efficient strategy (the lowest mean metric^k x s), with their interval
    // over the seeds: one whose interval holds 1 is no different from the best.
    const ErrorMetric metric = options.metric;
    std::size_t best = 0;
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (meanInterval(rows[i]->costs(metric)).mean < meanInterval(rows[best]->costs(metric)).mean)
            best = i;
    std::printf("\n%s: %dx%d, each strategy for %.0f ms%s; %s\n", scene.id.c_str(), base.settings.width,
                base.settings.height(), options.equalTimeMs,
                options.seeds > 1 ? fmt::format(", {} seeds (mean and 95 % interval)", options.seeds).c_str() : "",
                againstReference(reference, options.metric).c_str());
    const std::string efficiency = efficiencyPower(metric) == 1
                                       ? fmt::format("1/({} s)", displayName(metric))
                                       : fmt::format("1/({}^2 s)", displayName(metric));
    std::printf("%-8s %-36s %8s %10s %11s %14s %s\n", "engine", "strategy", "spp", "ms", displayName(metric),
                efficiency.c_str(), options.seeds > 1 ? "  efficiency / best" : "");
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const SeededRow& row = *rows[i];
        const Interval shown = row.metric(metric);
        std::string line = fmt::format("{:<8} {:<36} {:>8} {:>10.1f} {:>11.3g} {:>14.4g}", toString(tiles[i].engine),
                                       tiles[i].label, row.first().spp, row.ms(), shown.mean,
                                       1.0 / meanInterval(row.costs(metric)).mean);
        if (options.seeds > 1)
        {
            // The efficiency ratio e_i / e_best is the ratio of the best's metric^k x s to this one's.
            line += fmt::format("  {} ±{:.2g}; ", displayName(metric), 0.5 * (shown.hi - shown.lo));
            if (i == best)
                line += "1 (best)";
            else
            {
                const Interval r = ratioInterval(rows[best]->costs(metric), row.costs(metric));
                line += fmt::format("{:.3f} [{:.3f}, {:.3f}]{}", r.mean, r.lo, r.hi,
                                    r.contains(1.0) ? " (no different)" : "");
            }
        }
        std::printf("%s\n", line.c_str());
    }
    for (std::size_t e = 0; e < (autoRow ? choices.size() : 0); ++e)
        for (std::size_t k = 0; k < choices[e].size(); ++k)
        {
            const AutoChoice& c = choices[e][k];
            std::printf("auto, %s engine, seed %u: %s, by a pilot of %.1f ms on the engine's clock (%.2f s on the "
                        "host's) over %zu candidates at %dx%d, %d spp each\n",
                        toString(engines[e].kind), base.settings.seed + unsigned(k), c.chosen.name().c_str(), c.pilotMs,
                        c.pilotWallSeconds, c.rows.size(), c.width, c.height, c.spp);
        }
    if (!options.grid.empty())
    {
        writeEqualTimeGrid(options.grid,
                           {scene.id, devices, options.equalTimeMs, reference.spp},
                           reference.image, tiles);
        std::printf("wrote %s\n", options.grid.c_str());
    }
    std::vector<double> relMses;
    for (const SeededRow* row : rows)
        relMses.push_back(row->relMse().mean);
    warnNearReferenceNoise(reference, relMses);
    return true;
}
} // namespace

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

void checkComparison(const CompareOptions& options)
{
    if (options.strategies.empty())
        throw UsageError("--compare has no strategy to render");
    checkOutputPath(options.csv, "--csv", {".csv"});
    checkOutputPath(options.plot, "--plot", {".png"});
    checkOutputPath(options.json, "--table", {".json"});
    checkOutputPath(options.grid, "--output", {".png"});
    if (!options.plot.empty() && options.csv.empty())
        throw UsageError("--plot draws the rows of --csv: give --csv FILE.csv too");
    if (!options.grid.empty() && !(options.equalTimeMs > 0.0))
        throw UsageError("--output draws --equal-time's figure: give --equal-time MS too (the ladder writes --csv, "
                         "--plot and --table)");
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
        scriptPath("equal_time_grid.py");
        requireMatplotlib("--equal-time");
    }
}

int runComparison(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  const std::function<std::unique_ptr<RenderEngine>(EngineKind)>& makeEngine)
{
    checkComparison(options);
    ImageFolder images(options.images, scene.id, base.settings.width, base.settings.height());
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
            engines.push_back({kind, std::move(engine)});
        }
        catch (const DeviceError& e)
        {
            spdlog::warn("{} engine left out: {}", toString(kind), e.what());
        }
    }
    if (engines.empty())
        throw DeviceError("no engine could start");

    InterruptScope interrupt;
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
        spdlog::warn("comparison cancelled{}", csv ? fmt::format(": {} keeps the rows finished before", options.csv)
                                                   : std::string(": nothing written"));
        return 130;
    }
    if (!options.plot.empty())
    {
        drawFigure(options.plot, scriptPath("plot_convergence.py"), {options.csv, toString(options.metric)});
        std::printf("wrote %s\n", options.plot.c_str());
    }
    return 0;
}
} // namespace rt::compare
