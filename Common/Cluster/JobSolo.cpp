// A build without MPI: every process is a job of one rank.
#include <cstdlib>

#include <spdlog/fmt/fmt.h>

#include "Cluster/Job.h"
#include "Cluster/Launch.h"
#include "Error.h"

namespace rt::cluster
{
bool built()
{
    return false;
}

JobScope::JobScope()
{
    if (launchedRanks() > 1)
        throw UsageError(
            fmt::format("mpirun started {} copies of a program built without MPI, each of which would "
                        "render the whole image: build with Debian's libopenmpi-dev installed "
                        "(docs/SCALING.md), or run one process",
                        launchedRanks()));
}

JobScope::~JobScope() = default;

void Job::send(int, Tag, const std::string&)
{
    throw UsageError("a job of one rank has no other rank to message");
}
bool Job::sendWhile(int, Tag, std::string, const std::function<bool()>&)
{
    throw UsageError("a job of one rank has no other rank to message");
}
std::optional<Message> Job::poll()
{
    return std::nullopt;
}
void Job::broadcast(std::string&) {}
void Job::abandon(int exitCode)
{
    std::_Exit(exitCode);
}
void Job::leave(int exitCode)
{
    std::_Exit(exitCode);
}
std::vector<std::string> Job::gather(const std::string& bytes)
{
    return {bytes};
}
void Job::sumToRoot(std::vector<double>&) {}
} // namespace rt::cluster
