#include "Compare/EqualTimeRun.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "Compare/EqualTime.h"
#include "Compare/SeededRow.h"
#include "IO/AtomicFile.h"

namespace rt::compare
{
namespace
{
/// --table of an equal-time comparison: the settings, the reference and each row in the tiles' order (engine,
/// strategy, spp, times, error and efficiency; over seeds their means, intervals and values, the efficiency
/// against the best's); the auto row also each seed's pilot, as --stats records it (strategy_choice).
nlohmann::json equalTimeJson(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                             const std::vector<EngineUnderTest>& engines, const Reference& reference,
                             const std::vector<EqualTimeTile>& tiles, const std::vector<const SeededRow*>& rows,
                             std::size_t best, const std::vector<std::vector<AutoChoice>>* choices)
{
    nlohmann::json json = tableHead(scene, base, options, engines, reference);
    json["equal_time_ms"] = options.equalTimeMs;
    json["seeds"] = options.seeds;
    json["rounds"] = options.rounds;
    const std::size_t perEngine = rows.size() / std::max<std::size_t>(engines.size(), 1);
    json["rows"] = nlohmann::json::array();
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const SeededRow& row = *rows[i];
        const bool isAuto = choices && i % perEngine == perEngine - 1;
        const Interval shown = row.metric(options.metric);
        const Interval relMse = row.relMse();
        nlohmann::json j = {{"engine", toString(tiles[i].engine)},
                            {"strategy", isAuto ? std::string("auto") : tiles[i].strategy.name()},
                            {"label", tiles[i].label},
                            {"spp", row.first().spp},
                            {"ms", row.ms()},
                            {"render_ms", row.wallMs()},
                            {"gpu_ms", row.gpuMs()},
                            {"relmse", relMse.mean},
                            {"efficiency", 1.0 / meanInterval(row.costs(options.metric)).mean},
                            {"best", i == best}};
        if (options.metric != ErrorMetric::RelMse)
            j[toString(options.metric)] = shown.mean;
        if (options.seeds > 1)
        {
            j["relmse_ci95"] = {relMse.lo, relMse.hi};
            if (options.metric != ErrorMetric::RelMse)
                j[fmt::format("{}_ci95", toString(options.metric))] = {shown.lo, shown.hi};
            j["relmse_seeds"] = row.values([](const Measurement& x) { return x.error.relMse; });
            j["spp_seeds"] = row.values([](const Measurement& x) { return double(x.spp); });
            if (i != best)
            {
                const Interval r = ratioInterval(rows[best]->costs(options.metric), row.costs(options.metric));
                j["efficiency_over_best"] = r.mean;
                j["efficiency_over_best_ci95"] = {r.lo, r.hi};
            }
        }
        if (isAuto)
        {
            j["strategy_choice"] = nlohmann::json::array();
            for (const AutoChoice& c : (*choices)[i / perEngine])
                j["strategy_choice"].push_back(c.toJson());
        }
        json["rows"].push_back(std::move(j));
    }
    return json;
}
} // namespace

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
        // Seeds outside rows: every row renders seed k before any renders seed k + 1, so that a drift of the
        // machine's speed over the run (±10 % between blocks of rows on the CI kind's 2 cores) falls on every row
        // alike instead of on whichever row's block it met.
        for (int round = 0; round < options.rounds; ++round)
            for (int k = 0; k < options.seeds; ++k)
                for (std::size_t s = 0; s < rowCount; ++s)
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
                    // The auto row renders what it chose at the spp the budget gave that strategy's own row, where
                    // one has measured it, and pays the pilot on top: what `--strategy auto --spp N` costs a user.
                    // Sized by a budget of its own, less the pilot, its spp varied by seed with the calibration's
                    // noise (rect-light-closeup on 2 cores: 449-589 spp against the own row's 615), and Sobol's
                    // error falls faster than 1/spp: the same strategy measured up to 0.86x itself.
                    if (isAuto && spp == 0)
                        if (const auto row = std::find(options.strategies.begin(), options.strategies.end(), strategy);
                            row != options.strategies.end())
                            spp = spps[std::size_t(row - options.strategies.begin())];
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
                        csv->append(csvRow(scene.id, e.kind, e.engine->deviceName(), strategy, label, m, reference, seed, round, 0));
                    if (round == 0)
                        images.add(e.kind, strategy.name(), label, m, seed);
                    seeded[index][s].set(std::size_t(k), round, std::move(m));
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
                        "host's, %.2f s of it preparing the candidates) over %zu candidates at %dx%d, %d spp each\n",
                        toString(engines[e].kind), base.settings.seed + unsigned(k), c.chosen.name().c_str(), c.pilotMs,
                        c.pilotWallSeconds, c.prepareSeconds, c.rows.size(), c.width, c.height, c.spp);
        }
    if (!options.json.empty())
        writeFileAtomically(options.json, equalTimeJson(scene, base, options, engines, reference, tiles, rows, best,
                                                        autoRow ? &choices : nullptr)
                                                  .dump(2) +
                                              "\n");
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
} // namespace rt::compare
