// A headless render split over an MPI job's ranks (docs/SCALING.md): each rank traces a share of the camera
// samples of every pixel, consecutive indices of the per-sample random streams, so that the union is the
// sample set of one process rendering them all; root (rank 0) adds the shares' sums in double and alone
// writes the outputs, all or none.
//
// Around the render, the ranks exchange a few messages (Cluster/Job.h): before each batch a rank tells root
// its progress and looks for a Stop; at its end (finished, cancelled or failed, at any point after the job
// started) it sends root an End; root, having every End, broadcasts the verdict. A failure or a cancel
// anywhere makes root stop every other rank at its next batch, so the job ends within a batch. A rank that
// dies sends nothing: mpirun then sends every rank SIGTERM (a cancel here) and kills them a second later;
// root, cancelled and missing an End after kSilenceSeconds, names the silent rank in its error line before
// that.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Cluster/Job.h"
#include "Render/RenderControl.h"
#include "Render/RenderDriver.h"
#include "Render/RenderStats.h"

namespace rt::cluster
{
/// Camera samples [first, first + count) of every pixel that rank `rank` of `ranks` traces of a frame of
/// `total` per pixel: consecutive runs in rank order, the first `total % ranks` ranks taking one more. A rank
/// may get none (count 0) when `total` < `ranks`. Precondition: 0 <= rank < ranks.
FramePart shareOf(std::uint32_t total, int rank, int ranks);

/// How a rank's part of the job ended.
struct PartEnd
{
    enum class Status
    {
        Finished,
        Cancelled,
        Failed,
    };
    Status status = Status::Finished;
    std::string message;  // Failed: the error, without "error: "
    int exitCode = 0;     // Failed: the error's exit status
    nlohmann::json stats; // Finished: the rank's figures for the stats' "ranks" list (rankStats)
};

/// What every rank does once root has every End: write nothing and exit with `exitCode` unless all finished.
struct Verdict
{
    PartEnd::Status status = PartEnd::Status::Finished;
    std::string message; // Failed: "rank 1 (node7): <its error>" (no rank named when every rank failed alike)
    int exitCode = 0;
    nlohmann::json ranks;    // Finished: every rank's stats, in rank order
    bool silentRank = false; // Failed because a rank sent no End: the job cannot end in step (Job::leave)
};

/// Root's verdict from every rank's End (`ends[r]`; empty: rank r sent none in time), naming ranks with `nameOf`:
/// Failed when a rank failed (the first failing rank's error, unnamed when every rank failed alike) or, failing
/// none, when one is silent; else Cancelled when one was; else Finished, with every rank's stats.
Verdict judgeEnds(const std::vector<std::optional<PartEnd>>& ends, const std::function<std::string(int)>& nameOf);

/// Seconds root, cancelled, waits for a missing End before it reports the rank as silent (mpirun's SIGKILL
/// follows its SIGTERM by a second).
inline constexpr double kSilenceSeconds = 0.4;

/// The messages of one rank's part, on the render's thread. At most one part per process.
class SplitRender
{
  public:
    /// Starts this rank's part of the job; `control` is the render's (cancelled by a Stop, and on root
    /// counting the other ranks' progress, which the ranks send before each batch when `progress`).
    SplitRender(Job& job, RenderControl& control, bool progress = true);
    SplitRender(const SplitRender&) = delete;
    SplitRender& operator=(const SplitRender&) = delete;

    /// FramePart::beforeBatch: on a rank, sends root its progress and cancels on a Stop; on root, takes in
    /// the others' progress and Ends (stopping everyone once one failed or was cancelled).
    void beforeBatch();
    /// Ends this rank's part with `mine` and returns the verdict (every rank; blocks until root has every
    /// End). Messages of other tags that arrive meanwhile are dropped.
    Verdict end(const PartEnd& mine);

    /// Where the messages of tags other than Progress, End and Stop go when beforeBatch polls (a TaskPool's);
    /// empty: dropped.
    void setOtherMessages(std::function<void(const Message&)> handler) { m_others = std::move(handler); }

    /// Ends this process's part of the job with a failure, when an error escaped before its end (guardedMain:
    /// a scene that does not load on this rank, a device lost): sends the End a part would have, or, on root,
    /// stops the others and collects theirs. Returns the verdict; nothing when the job is one process or this
    /// process's part has already ended.
    static std::optional<Verdict> endAfterError(Job& job, const std::string& message, int exitCode);

  private:
    void stopOthers();
    void take(const Message& m);

    Job& m_job;
    RenderControl& m_control;
    bool m_sendProgress = true;
    std::function<void(const Message&)> m_others;
    std::vector<std::uint64_t> m_progress; // root: each rank's paths traced
    std::vector<std::optional<PartEnd>> m_ends; // root: each rank's End, once it came
    bool m_stopped = false; // root: Stop sent to the others
    bool m_cancelledByJob = false; // root: its own part cancelled because another rank failed or was cancelled
};

/// The end of this rank's run when its job failed: root prints the job's one error line ("error: ..." on stderr); a
/// job with a rank that went silent cannot end in step, and this rank leaves at once (Job::leave). Returns the exit
/// status.
int endFailedJob(Job& job, const Verdict& verdict);

/// A rank's figures for the stats' "ranks" list: its host, device, samples and times.
nlohmann::json rankStats(const Job& job, const FramePart& share, const RenderStats& stats);
} // namespace rt::cluster
