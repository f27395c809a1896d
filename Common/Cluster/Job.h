// The MPI job a process belongs to (Open MPI's mpirun is the only launcher; docs/SCALING.md), as the headless
// runs see it: its ranks, the host of each, and the few messages a split render needs. A process that mpirun
// did not start, or a build without MPI, is a job of one rank, and every program behaves as it always has.
//
// Threading: every call comes from the thread that made the JobScope (MPI_THREAD_FUNNELED): the render
// driver's loop, which is the main thread of both apps' headless runs. Signal handlers and worker threads
// never call in.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rt::cluster
{
/// What a message between ranks is for (its MPI tag).
enum class Tag : int
{
    Progress = 1, // rank -> root: camera paths traced so far (decimal text)
    End = 2,      // rank -> root: how the rank's part ended (JSON: SplitRender.cpp)
    Stop = 3,     // root -> rank: stop the part now (another rank failed or was cancelled)
    Ask = 4,      // rank -> root: free for a task (Cluster/TaskPool.h)
    Task = 5,     // root -> rank: a task to run (its description), or none left (empty)
    Result = 6,   // rank -> root: what a task gave (its index, a line, then its bytes)
    Share = 7,    // root -> rank: data every task needs (a comparison's reference image)
};

struct Message
{
    int from = -1;
    Tag tag = Tag::Progress;
    std::string bytes;
};

class Job
{
  public:
    int rank() const { return m_rank; }
    int size() const { return m_size; }
    /// This rank's index among the ranks of its host (picks the host's GPU: docs/SCALING.md).
    int localRank() const { return m_localRank; }
    bool distributed() const { return m_size > 1; }
    bool root() const { return m_rank == 0; }
    /// The host rank `r` runs on (gathered when the job starts).
    const std::string& host(int r) const { return m_hosts.at(static_cast<std::size_t>(r)); }
    /// "rank 1 (node7)": how messages name a rank.
    std::string name(int r) const;

    /// Sends `bytes` to rank `to` (small messages: returns at once). Throws rt::Error on an MPI failure.
    void send(int to, Tag tag, const std::string& bytes);
    /// Sends `bytes` to rank `to` however large, without waiting on a rank that no longer receives (one that failed
    /// and waits for the verdict): while the send is under way, `whileWaiting` runs (it takes this rank's messages)
    /// and says whether to wait on. When it says no, the send is abandoned and false returned: the job is ending,
    /// and ends without MPI_Finalize (abandonedSends). Throws rt::Error on an MPI failure.
    bool sendWhile(int to, Tag tag, std::string bytes, const std::function<bool()>& whileWaiting);
    /// Whether a send was abandoned: MPI_Finalize could wait for it, so the process leaves instead.
    bool abandonedSends() const { return !m_abandoned.empty(); }
    /// The next message that has arrived from any rank, if one has; never blocks.
    std::optional<Message> poll();
    /// Root's `bytes` on every rank (collective: every rank calls it).
    void broadcast(std::string& bytes);
    /// Ends the whole job now with `exitCode` (MPI_Abort: mpirun kills every rank), for a rank that fails where the
    /// others wait for it in a collective (the reduction after the verdict).
    [[noreturn]] void abandon(int exitCode);
    /// Exits now with `exitCode`, without MPI_Finalize: for a job mpirun is ending (Ctrl-C, a rank died),
    /// whose ranks would otherwise wait in MPI_Finalize for mpirun's SIGKILL.
    [[noreturn]] void leave(int exitCode);
    /// Every rank's `bytes`, in rank order, on root; empty elsewhere (collective).
    std::vector<std::string> gather(const std::string& bytes);
    /// Every rank's `values` summed in double, element by element, into root's `values` (MPI_Reduce;
    /// collective, every rank passes as many values). Other ranks' vectors are left as they were.
    void sumToRoot(std::vector<double>& values);

    Job(const Job&) = delete;
    Job& operator=(const Job&) = delete;

  private:
    friend class JobScope;
    friend Job& job();
    Job() = default;
    int m_rank = 0;
    int m_size = 1;
    int m_localRank = 0;
    std::vector<std::string> m_hosts{std::string("localhost")};
    bool m_joined = false; // MPI initialised by this process
    std::vector<std::string> m_abandoned; // the buffers of abandoned sends, which MPI may still read
};

/// The job of this process: the one a JobScope joined, or a job of one rank.
Job& job();

/// Joins mpirun's job for the scope's life (MPI_Init_thread ... MPI_Finalize) when the process was started by
/// mpirun, else leaves job() a job of one. Make one at the top of main, before any thread. Throws UsageError
/// when mpirun started several copies of a program built without MPI (each would render the whole image).
class JobScope
{
  public:
    JobScope();
    ~JobScope();
    JobScope(const JobScope&) = delete;
    JobScope& operator=(const JobScope&) = delete;
};

/// Whether this build can join an MPI job.
bool built();
} // namespace rt::cluster
