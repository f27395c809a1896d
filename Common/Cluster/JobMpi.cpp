// The MPI job (Open MPI): MPI_Init_thread at the JobScope, the hosts gathered once, the messages of Job.h.
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <thread>

#include <spdlog/fmt/fmt.h>

#include "Cluster/Job.h"
#include "Cluster/Launch.h"
#include "Error.h"

namespace rt::cluster
{
namespace
{
// The job's own communicator, so that no library's messages on MPI_COMM_WORLD meet ours.
MPI_Comm g_comm = MPI_COMM_NULL;

void check(int status, const char* what)
{
    if (status == MPI_SUCCESS)
        return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(status, text, &length);
    throw Error(fmt::format("MPI: {} failed: {}", what, std::string(text, static_cast<std::size_t>(length))));
}

int count(std::size_t n, const char* what)
{
    if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw Error(fmt::format("MPI: {} of {} elements is more than one message can hold", what, n));
    return static_cast<int>(n);
}
} // namespace

bool built()
{
    return true;
}

JobScope::JobScope()
{
    if (launchedRanks() <= 1)
        return; // not started by mpirun: no MPI at all, as in a build without it
    int provided = 0;
    // Errors come back as codes (MPI_ERRORS_RETURN below), so that a rank's failure is an error line, not an
    // abort.
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw Error("MPI_Init_thread failed: is this process started by Open MPI's mpirun?");
    if (provided < MPI_THREAD_FUNNELED)
        throw Error("this MPI library gives no thread support (MPI_THREAD_FUNNELED): the engines render on threads");
    Job& j = job();
    j.m_joined = true;
    check(MPI_Comm_dup(MPI_COMM_WORLD, &g_comm), "MPI_Comm_dup");
    MPI_Comm_set_errhandler(g_comm, MPI_ERRORS_RETURN);
    MPI_Comm_rank(g_comm, &j.m_rank);
    MPI_Comm_size(g_comm, &j.m_size);
    MPI_Comm local = MPI_COMM_NULL;
    check(MPI_Comm_split_type(g_comm, MPI_COMM_TYPE_SHARED, j.m_rank, MPI_INFO_NULL, &local),
          "MPI_Comm_split_type");
    MPI_Comm_rank(local, &j.m_localRank);
    MPI_Comm_free(&local);

    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    std::vector<char> all(static_cast<std::size_t>(j.m_size) * MPI_MAX_PROCESSOR_NAME);
    check(MPI_Allgather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR,
                        g_comm),
          "MPI_Allgather (hosts)");
    j.m_hosts.clear();
    for (int r = 0; r < j.m_size; ++r)
        j.m_hosts.emplace_back(all.data() + static_cast<std::size_t>(r) * MPI_MAX_PROCESSOR_NAME);
}

JobScope::~JobScope()
{
    Job& j = job();
    if (!j.m_joined)
        return;
    MPI_Comm_free(&g_comm);
    MPI_Finalize();
    j.m_joined = false;
}

void Job::send(int to, Tag tag, const std::string& bytes)
{
    check(
        MPI_Send(bytes.data(), count(bytes.size(), "a message"), MPI_CHAR, to, static_cast<int>(tag), g_comm),
        "MPI_Send");
}

bool Job::sendWhile(int to, Tag tag, std::string bytes, const std::function<bool()>& whileWaiting)
{
    MPI_Request request = MPI_REQUEST_NULL;
    check(MPI_Isend(bytes.data(), count(bytes.size(), "a message"), MPI_CHAR, to, static_cast<int>(tag), g_comm,
                    &request),
          "MPI_Isend");
    while (true)
    {
        int done = 0;
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
        if (done)
            return true;
        if (!whileWaiting())
        {
            // The receiver is gone or failed: MPI keeps the request (and reads the buffer) until it completes.
            MPI_Request_free(&request);
            m_abandoned.push_back(std::move(bytes));
            return false;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

std::optional<Message> Job::poll()
{
    if (!m_joined)
        return std::nullopt;
    int arrived = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, g_comm, &arrived, &status), "MPI_Iprobe");
    if (!arrived)
        return std::nullopt;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    Message m{.from = status.MPI_SOURCE,
              .tag = static_cast<Tag>(status.MPI_TAG),
              .bytes = std::string(static_cast<std::size_t>(length), '\0')};
    check(MPI_Recv(m.bytes.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, g_comm,
                   MPI_STATUS_IGNORE),
          "MPI_Recv");
    return m;
}

void Job::broadcast(std::string& bytes)
{
    if (!m_joined)
        return;
    unsigned long long length = bytes.size();
    check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, g_comm), "MPI_Bcast");
    bytes.resize(static_cast<std::size_t>(length));
    check(MPI_Bcast(bytes.data(), count(bytes.size(), "a broadcast"), MPI_CHAR, 0, g_comm), "MPI_Bcast");
}

void Job::abandon(int exitCode)
{
    std::fflush(stdout);
    std::fflush(stderr);
    if (m_joined)
        MPI_Abort(g_comm, exitCode);
    std::_Exit(exitCode);
}

void Job::leave(int exitCode)
{
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(exitCode);
}

std::vector<std::string> Job::gather(const std::string& bytes)
{
    if (!m_joined)
        return {bytes};
    const int length = count(bytes.size(), "a text");
    std::vector<int> lengths(static_cast<std::size_t>(m_size));
    check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, g_comm), "MPI_Gather");
    std::vector<int> offsets(lengths.size(), 0);
    for (std::size_t r = 1; r < lengths.size(); ++r)
        offsets[r] = offsets[r - 1] + lengths[r - 1];
    std::string all(m_rank == 0 ? static_cast<std::size_t>(offsets.back() + lengths.back()) : 0, '\0');
    check(MPI_Gatherv(bytes.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                      g_comm),
          "MPI_Gatherv");
    if (m_rank != 0)
        return {};
    std::vector<std::string> parts;
    for (std::size_t r = 0; r < lengths.size(); ++r)
        parts.push_back(
            all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
    return parts;
}

void Job::sumToRoot(std::vector<double>& values)
{
    if (!m_joined)
        return;
    const int n = count(values.size(), "an image");
    check(MPI_Reduce(m_rank == 0 ? MPI_IN_PLACE : values.data(), values.data(), n, MPI_DOUBLE, MPI_SUM, 0,
                     g_comm),
          "MPI_Reduce (image)");
}
} // namespace rt::cluster
