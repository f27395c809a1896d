// The ladder of sample counts (Compare.h): every engine x strategy x spp x seed, timed in rounds, against the
// reference. Its renders are a list of jobs (RowJob.h) that one process runs in order (runLadder) or the ranks of
// an MPI job share (DistributedComparison.h); a table files each render as it comes, in any order, and prints
// the tables and the JSON once all have come.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "Compare/AutoStrategy.h"
#include "Compare/ComparisonRun.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/ImageFolder.h"
#include "Compare/RowJob.h"
#include "Compare/SeededRow.h"
#include "Scene/Scene.h"

namespace rt::compare
{
/// The ladder's renders in the order one process runs them: engine by engine (measurementOrder: each engine's rows
/// back to back after its warm-up, as row by row interleaving with 16-thread CPU renders cost an H100 2-3x:
/// docs/notebook/PERFORMANCE.md), then round by round (every row once, then every row again, so that a drift of
/// the clocks spreads over all of them), strategy (the auto row last), spp and seed. A job keeps its image when
/// it is round 0's and the first seed's, or when `everyImage` (--images).
std::vector<RowJob> ladderJobs(const CompareOptions& options, const std::vector<EngineUnderTest>& engines,
                               bool everyImage);

/// A render of the ladder as this process ran it.
struct LadderRender
{
    Measurement measurement;
    std::optional<AutoChoice> choice; // the auto row's pilot, at its round 0
};

/// Runs ladder jobs on this process's engines: an engine's strategies warmed up before its first job, the auto
/// row's pilot at round 0 (its later rounds reuse the choice: they must run here after it).
class LadderRunner
{
public:
    LadderRunner(const RenderRequest& base, const CompareOptions& options, std::vector<EngineUnderTest>& engines,
                 const Reference& reference);
    /// The render of `job`; its measurement is cancelled when Ctrl-C (or a job's Stop) stopped it.
    LadderRender run(const RowJob& job);

private:
    const RenderRequest& m_base;
    const CompareOptions& m_options;
    std::vector<EngineUnderTest>& m_engines;
    const Reference& m_reference;
    std::vector<bool> m_warm; // per engine
    std::vector<std::vector<std::vector<AutoChoice>>> m_choices; // [engine][spp][seed]
};

/// The ladder's figures, filed render by render, and its tables.
class LadderTable
{
public:
    LadderTable(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                const std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
                ImageFolder& images);
    /// Files the render of `job` by `device` at rank `rank`: a progress line, its CSV row and, at round 0, its
    /// image in --images. The auto row's `choice` comes with its round 0, before its later rounds.
    void record(const RowJob& job, Measurement m, const std::optional<AutoChoice>& choice, const std::string& device,
                int rank);
    /// The tables on stdout and the JSON (--table), once every job of ladderJobs has been filed.
    void print();

private:
    const Scene& m_scene;
    const RenderRequest& m_base;
    const CompareOptions& m_options;
    const std::vector<EngineUnderTest>& m_engines;
    const Reference& m_reference;
    ConvergenceCsv* m_csv;
    ImageFolder& m_images;
    std::vector<std::string> m_labels;
    std::vector<std::vector<std::vector<SeededRow>>> m_runs; // [engine][strategy][spp]
    std::vector<std::vector<std::vector<AutoChoice>>> m_choices; // [engine][spp][seed]
    RunLog m_log;
    std::map<int, std::pair<int, double>> m_byRank; // rank: renders, their wall seconds
};

/// The ladder on one process: every job of ladderJobs in order, then the tables. False when Ctrl-C stopped it.
bool runLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
               std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
               ImageFolder& images);
} // namespace rt::compare
