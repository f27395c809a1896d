#include "Cluster/SplitRender.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <thread>

#include <spdlog/fmt/fmt.h>

#include "Check.h"
#include "Error.h"
#include "PrintableLine.h"

namespace rt::cluster
{
// How Ends and verdicts travel between ranks.
NLOHMANN_JSON_SERIALIZE_ENUM(PartEnd::Status, {{PartEnd::Status::Finished, "finished"},
                                               {PartEnd::Status::Cancelled, "cancelled"},
                                               {PartEnd::Status::Failed, "failed"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PartEnd, status, message, exitCode, stats)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Verdict, status, message, exitCode, ranks, silentRank)

namespace
{
bool g_partEnded = false; // this process has ended its part (at most one per process)
} // namespace

FramePart shareOf(std::uint32_t total, int rank, int ranks)
{
    RT_CHECK(ranks >= 1 && rank >= 0 && rank < ranks);
    const auto n = static_cast<std::uint32_t>(ranks);
    const auto r = static_cast<std::uint32_t>(rank);
    const std::uint32_t base = total / n;
    const std::uint32_t extra = total % n;
    FramePart part;
    part.firstSample = r * base + std::min(r, extra);
    part.samples = base + (r < extra ? 1u : 0u);
    return part;
}

Verdict judgeEnds(const std::vector<std::optional<PartEnd>>& ends, const std::function<std::string(int)>& nameOf)
{
    Verdict v;
    std::vector<int> failed;
    std::optional<int> silent;
    const int ranks = static_cast<int>(ends.size());
    for (int r = 0; r < ranks; ++r)
    {
        const std::optional<PartEnd>& e = ends[static_cast<std::size_t>(r)];
        if (!e && !silent)
            silent = r;
        else if (e && e->status == PartEnd::Status::Failed)
            failed.push_back(r);
    }
    // A rank's own error explains the job's end better than a rank that did not answer in time.
    if (silent && failed.empty())
    {
        v.status = PartEnd::Status::Failed;
        v.exitCode = 1;
        v.silentRank = true;
        v.message = fmt::format("{} sent no word within {:.1f} s of mpirun's stop (it died, or its batch was still "
                                "running): nothing written",
                                nameOf(*silent), kSilenceSeconds);
        return v;
    }
    if (!failed.empty())
    {
        const PartEnd& first = *ends[static_cast<std::size_t>(failed.front())];
        bool alike = static_cast<int>(failed.size()) == ranks;
        for (int r : failed)
            alike = alike && ends[static_cast<std::size_t>(r)]->message == first.message;
        v.status = PartEnd::Status::Failed;
        v.exitCode = first.exitCode == 0 ? 1 : first.exitCode;
        v.message = alike ? first.message : nameOf(failed.front()) + ": " + first.message;
        v.silentRank = silent.has_value();
        return v;
    }
    for (const std::optional<PartEnd>& e : ends)
        if (e->status == PartEnd::Status::Cancelled)
        {
            v.status = PartEnd::Status::Cancelled;
            v.exitCode = 130;
            return v;
        }
    v.ranks = nlohmann::json::array();
    for (const std::optional<PartEnd>& e : ends)
        v.ranks.push_back(e->stats);
    return v;
}

SplitRender::SplitRender(Job& job, RenderControl& control, bool progress)
    : m_job(job), m_control(control), m_sendProgress(progress)
{
    if (m_job.root())
    {
        m_progress.assign(static_cast<std::size_t>(m_job.size()), 0);
        m_ends.resize(static_cast<std::size_t>(m_job.size()));
    }
}

std::optional<Verdict> SplitRender::endAfterError(Job& job, const std::string& message, int exitCode)
{
    if (!job.distributed() || g_partEnded)
        return std::nullopt;
    RenderControl unused;
    SplitRender part(job, unused);
    return part.end({.status = PartEnd::Status::Failed, .message = message, .exitCode = exitCode});
}

void SplitRender::stopOthers()
{
    if (m_stopped)
        return;
    m_stopped = true;
    for (int r = 1; r < m_job.size(); ++r)
        if (!m_ends[static_cast<std::size_t>(r)])
            m_job.send(r, Tag::Stop, {});
}

void SplitRender::take(const Message& m)
{
    const auto from = static_cast<std::size_t>(m.from);
    if (m.tag == Tag::Progress)
    {
        m_progress[from] = std::stoull(m.bytes);
        std::uint64_t others = 0;
        for (std::size_t r = 1; r < m_progress.size(); ++r)
            others += m_progress[r];
        m_control.setDoneElsewhere(others);
    }
    else if (m.tag == Tag::End)
    {
        m_ends[from] = nlohmann::json::parse(m.bytes).get<PartEnd>();
        if (m_ends[from]->status != PartEnd::Status::Finished)
        {
            stopOthers();
            m_cancelledByJob = true;
            m_control.requestCancel(); // root's own part too: the job writes nothing now
        }
    }
    else if (m_others)
        m_others(m);
}

void SplitRender::beforeBatch()
{
    if (!m_job.root())
    {
        if (m_sendProgress)
            m_job.send(0, Tag::Progress, std::to_string(m_control.done()));
        while (const std::optional<Message> m = m_job.poll())
            if (m->tag == Tag::Stop)
                m_control.requestCancel();
            else if (m_others)
                m_others(*m);
        return;
    }
    while (const std::optional<Message> m = m_job.poll())
        take(*m);
}

Verdict SplitRender::end(const PartEnd& mine)
{
    RT_CHECK(!g_partEnded);
    g_partEnded = true;
    m_others = nullptr;
    std::string verdict;
    if (!m_job.root())
    {
        m_job.send(0, Tag::End, nlohmann::json(mine).dump());
        m_job.broadcast(verdict);
        return nlohmann::json::parse(verdict).get<Verdict>();
    }
    m_ends[0] = mine;
    if (mine.status != PartEnd::Status::Finished)
        stopOthers();
    using Clock = std::chrono::steady_clock;
    std::optional<Clock::time_point> signalled; // when root saw a cancel it did not cause: Ctrl-C or a rank's death
    const auto missing = [&]
    {
        for (const std::optional<PartEnd>& e : m_ends)
            if (!e)
                return true;
        return false;
    };
    while (missing())
    {
        if (const std::optional<Message> m = m_job.poll())
        {
            take(*m);
            continue;
        }
        // mpirun's SIGTERM (Ctrl-C, or a rank died), before or after root's part ended: the others answer within a
        // batch, or are gone and mpirun's SIGKILL follows in a second.
        if (!signalled && m_control.cancelRequested() && !m_cancelledByJob)
            signalled = Clock::now();
        if (signalled && std::chrono::duration<double>(Clock::now() - *signalled).count() > kSilenceSeconds)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    const Verdict v = judgeEnds(m_ends, [&](int r) { return m_job.name(r); });
    if (!missing())
    {
        verdict = nlohmann::json(v).dump();
        m_job.broadcast(verdict);
    }
    return v;
}

int endFailedJob(Job& job, const Verdict& verdict)
{
    if (job.root())
        std::fprintf(stderr, "error: %s\n", printableLine(verdict.message).c_str());
    // A silent rank is judged only after a stop root did not cause (mpirun's SIGTERM, or Ctrl-C): the job is
    // already ending, and no collective can end it in step. Root leaves rather than waiting in MPI_Abort for
    // mpirun's SIGKILL: mpirun forwards nothing while it waits to kill, and a rank it killed has lost its error line
    // under load (tests/Cli/mpi_compare.sh, "a killed rank"); a rank that exited leaves the line in its pipe.
    if (verdict.silentRank || job.abandonedSends())
        job.leave(verdict.exitCode);
    return verdict.exitCode;
}

nlohmann::json rankStats(const Job& job, const FramePart& share, const RenderStats& stats)
{
    nlohmann::json j = {{"rank", job.rank()},
                        {"host", job.host(job.rank())},
                        {"device", stats.device},
                        {"first_sample", share.firstSample},
                        {"samples", share.samples.value_or(0)},
                        {"build_seconds", stats.buildSeconds},
                        {"render_seconds", stats.renderSeconds},
                        {"paths", stats.paths},
                        {"nan_samples", stats.nanSamples},
                        {"inf_samples", stats.infSamples},
                        {"threads_used", stats.threadsUsed}};
    if (stats.gpuSeconds >= 0.0)
        j["gpu_seconds"] = stats.gpuSeconds;
    if (stats.raysCounted)
    {
        j["rays"] = toJson(stats.rays, stats.renderSeconds);
        j["light_samples"] = toJson(stats.lightSamples);
    }
    return j;
}
} // namespace rt::cluster
