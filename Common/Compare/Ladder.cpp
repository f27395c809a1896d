#include "Compare/Ladder.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cluster/Job.h"
#include "IO/AtomicFile.h"

namespace rt::compare
{
namespace
{
std::size_t rowCountOf(const CompareOptions& options)
{
    return options.strategies.size() + (options.autoCandidates.empty() ? 0 : 1); // the auto row last
}
} // namespace

std::vector<RowJob> ladderJobs(const CompareOptions& options, const std::vector<EngineUnderTest>& engines,
                               bool everyImage)
{
    std::vector<RowJob> jobs;
    for (const std::size_t e : measurementOrder(engines))
        for (int round = 0; round < options.rounds; ++round)
            for (std::size_t s = 0; s < rowCountOf(options); ++s)
                for (std::size_t row = 0; row < options.spps.size(); ++row)
                    for (int k = 0; k < options.seeds; ++k)
                        jobs.push_back({.engine = e,
                                        .strategy = s,
                                        .spp = row,
                                        .seed = k,
                                        .round = round,
                                        .keepImage = round == 0 && (k == 0 || everyImage)});
    return jobs;
}

LadderRunner::LadderRunner(const RenderRequest& base, const CompareOptions& options,
                           std::vector<EngineUnderTest>& engines, const Reference& reference)
    : m_base(base), m_options(options), m_engines(engines), m_reference(reference), m_warm(engines.size(), false),
      m_choices(engines.size(), std::vector<std::vector<AutoChoice>>(
                                    options.spps.size(), std::vector<AutoChoice>(std::size_t(options.seeds))))
{
}

LadderRender LadderRunner::run(const RowJob& job)
{
    RenderEngine& engine = *m_engines[job.engine].engine;
    if (!m_warm[job.engine])
    {
        warmUpStrategies(engine, m_base, m_options.strategies);
        m_warm[job.engine] = true;
    }
    const bool isAuto = job.strategy == m_options.strategies.size();
    const int spp = m_options.spps[job.spp];
    RenderRequest request = isAuto ? m_base : m_options.strategies[job.strategy].request(m_base, spp);
    request.settings.spp = spp;
    request.settings.seed += std::uint32_t(job.seed);
    LadderRender done;
    AutoChoice& choice = m_choices[job.engine][job.spp][std::size_t(job.seed)];
    if (isAuto && job.round == 0)
    {
        choice = chooseStrategy(engine, request, m_options.autoCandidates, m_options.pilotBudget);
        if (choice.cancelled)
        {
            done.measurement.cancelled = true;
            return done;
        }
        done.choice = choice;
    }
    const Strategy strategy = isAuto ? choice.chosen : m_options.strategies[job.strategy];
    request.settings = strategy.applyTo(request.settings);
    done.measurement = measure(engine, request, &m_reference.image);
    if (done.measurement.cancelled)
        return done;
    if (isAuto)
        chargePilot(done.measurement, choice);
    measureFlip(m_options, job.round, m_reference, done.measurement);
    return done;
}

LadderTable::LadderTable(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                         const std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
                         ImageFolder& images)
    : m_scene(scene), m_base(base), m_options(options), m_engines(engines), m_reference(reference), m_csv(csv),
      m_images(images), m_labels(distinctLabels(options.strategies)),
      m_runs(engines.size(), std::vector<std::vector<SeededRow>>(rowCountOf(options),
                                                                 std::vector<SeededRow>(options.spps.size()))),
      m_choices(engines.size(), std::vector<std::vector<AutoChoice>>(
                                    options.spps.size(), std::vector<AutoChoice>(std::size_t(options.seeds)))),
      m_log(engines.size() * rowCountOf(options) * options.spps.size() * std::size_t(options.seeds) *
            std::size_t(options.rounds))
{
}

void LadderTable::record(const RowJob& job, Measurement m, const std::optional<AutoChoice>& choice,
                         const std::string& device, int rank)
{
    const bool isAuto = job.strategy == m_options.strategies.size();
    AutoChoice& filed = m_choices[job.engine][job.spp][std::size_t(job.seed)];
    if (choice)
        filed = *choice;
    const Strategy strategy = isAuto ? filed.chosen : m_options.strategies[job.strategy];
    const std::string label = isAuto ? autoLabel(m_options.strategies, filed.chosen) : m_labels[job.strategy];
    const EngineKind kind = m_engines[job.engine].kind;
    const std::uint32_t seed = m_base.settings.seed + std::uint32_t(job.seed);
    const std::string where = cluster::job().distributed() ? fmt::format(", rank {}", rank) : std::string();
    m_log.done(fmt::format("{} {}, {} spp, seed {}, round {}{}: {:.1f} ms, {} {:.3g}", toString(kind), label, m.spp,
                           seed, job.round, where, m.ms(), displayName(m_options.metric),
                           metricValue(m.error, m_options.metric)));
    if (m_csv)
        m_csv->append(csvRow(m_scene.id, kind, device, strategy, label, m, m_reference, seed, job.round, rank));
    if (job.round == 0)
        m_images.add(kind, strategy.name(), label, m, seed);
    m_byRank[rank].first += 1;
    m_byRank[rank].second += m.wallMs * 1e-3;
    m_runs[job.engine][job.strategy][job.spp].set(std::size_t(job.seed), job.round, std::move(m));
}

void LadderTable::print()
{
    const std::size_t strategyCount = m_options.strategies.size();
    const std::size_t rowCount = rowCountOf(m_options);
    const RenderSettings& b = m_base.settings;
    nlohmann::json json = tableHead(m_scene, m_base, m_options, m_engines, m_reference);
    if (cluster::job().distributed())
        json["ranks"] = cluster::job().size(); // each row's renders came from any of them (the CSV names which)
    json["rows"] = nlohmann::json::array();

    const bool ratio = m_engines.size() > 1 && m_engines.back().kind == EngineKind::Gpu;
    for (std::size_t s = 0; s < rowCount; ++s)
    {
        const bool isAuto = s == strategyCount;
        std::string strategyText;
        if (isAuto)
        {
            strategyText = "--strategy auto, the pilot's time included; chosen";
            for (std::size_t e = 0; e < m_engines.size(); ++e)
                for (std::size_t row = 0; row < m_options.spps.size(); ++row)
                    strategyText += fmt::format("{} {} at {} spp: {}", e + row == 0 ? "" : ",", toString(m_engines[e].kind),
                                                m_options.spps[row],
                                                autoLabel(m_options.strategies, m_choices[e][row].front().chosen).substr(6));
        }
        else
            strategyText = describeStrategy(m_options.strategies[s].applyTo(b));
        std::printf("\n%s: %dx%d, depth %d, %s; %s\n", m_scene.id.c_str(), b.width, b.height(), b.depth,
                    strategyText.c_str(), againstReference(m_reference, m_options.metric).c_str());
        std::string header = fmt::format("{:>6}", "spp");
        for (const EngineUnderTest& e : m_engines)
            header += fmt::format(" | {:>9} {:>9}{}{}", fmt::format("{} ms", toString(e.kind)),
                                  displayName(m_options.metric),
                                  m_options.seeds > 1 ? fmt::format(" {:<9}", "±95%") : std::string(),
                                  m_options.rounds > 1 ? fmt::format(" {:>6}", "range%") : std::string());
        if (ratio)
            header += fmt::format(" | {:>10} | {:>11}", "CPU/GPU", "relMSE C-G");
        std::printf("%s\n%s\n", header.c_str(), std::string(header.size(), '-').c_str());
        for (std::size_t row = 0; row < m_options.spps.size(); ++row)
        {
            std::string line = fmt::format("{:>6}", m_runs.front()[s][row].first().spp);
            nlohmann::json jrow;
            jrow["spp"] = m_runs.front()[s][row].first().spp;
            jrow["strategy"] = isAuto ? std::string("auto") : m_options.strategies[s].name();
            const SeededRow* gpu = nullptr;
            const SeededRow* cpu = nullptr; // the fastest CPU engine of the row
            for (std::size_t e = 0; e < m_engines.size(); ++e)
            {
                const SeededRow& seeded = m_runs[e][s][row];
                const Measurement& m = seeded.first();
                const Interval relMse = seeded.relMse();
                const Interval shown = seeded.metric(m_options.metric);
                line += fmt::format(" | {:>9.1f} {:>9.2e}{}", seeded.ms(), shown.mean, plusMinus(shown));
                if (m_options.rounds > 1)
                    line += fmt::format(" {:>6.1f}", 100.0 * seeded.spread());
                nlohmann::json& j = jrow[toString(m_engines[e].kind)];
                j = {{"render_ms", seeded.wallMs()},
                     {"gpu_ms", seeded.gpuMs()},
                     {"mpaths_per_second", m.mpathsPerSecond},
                     {"mse", m.error.mse},
                     {"relmse", relMse.mean},
                     {"trimmed_relmse", seeded.metric(ErrorMetric::TrimmedRelMse).mean},
                     {"mape", seeded.metric(ErrorMetric::Mape).mean},
                     {"rmse", m.error.rmse}};
                if (m_options.metric == ErrorMetric::Flip)
                    j["flip"] = shown.mean;
                if (m_options.rounds > 1)
                {
                    j["rounds"] = m_options.rounds;
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
                if (m_options.seeds > 1)
                {
                    j["seeds"] = m_options.seeds;
                    j["relmse_ci95"] = {relMse.lo, relMse.hi};
                    j["relmse_seeds"] = seeded.values([](const Measurement& x) { return x.error.relMse; });
                    if (m_options.metric != ErrorMetric::RelMse)
                        j[fmt::format("{}_ci95", toString(m_options.metric))] = {shown.lo, shown.hi};
                    j["mse"] = meanInterval(seeded.values([](const Measurement& x) { return x.error.mse; })).mean;
                    j["rmse"] = meanInterval(seeded.values([](const Measurement& x) { return x.error.rmse; })).mean;
                }
                if (isAuto)
                {
                    j["strategy_choice"] = nlohmann::json::array();
                    for (const AutoChoice& c : m_choices[e][row])
                        j["strategy_choice"].push_back(c.toJson());
                }
                if (m_engines[e].kind == EngineKind::Gpu)
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
    for (const auto& engineRuns : m_runs)
        for (const auto& strategyRuns : engineRuns)
            for (const SeededRow& row : strategyRuns)
                relMses.push_back(row.relMse().mean);
    warnNearReferenceNoise(m_reference, relMses);
    if (!m_options.json.empty())
        writeFileAtomically(m_options.json, json.dump(2) + "\n");
    if (cluster::job().distributed())
    {
        std::string shares;
        for (const auto& [rank, work] : m_byRank)
            shares += fmt::format("{}{}: {} renders, {:.1f} s", shares.empty() ? "" : "; ", cluster::job().name(rank),
                                  work.first, work.second);
        spdlog::info("the renders by rank: {}", shares);
    }
}

bool runLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
               std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
               ImageFolder& images)
{
    LadderTable table(scene, base, options, engines, reference, csv, images);
    LadderRunner runner(base, options, engines, reference);
    for (const RowJob& job : ladderJobs(options, engines, images.enabled()))
    {
        LadderRender done = runner.run(job);
        if (done.measurement.cancelled)
            return false;
        table.record(job, std::move(done.measurement), done.choice, engines[job.engine].engine->deviceName(), 0);
    }
    table.print();
    return true;
}
} // namespace rt::compare
