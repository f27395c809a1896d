#include "Cluster/Job.h"

#include <algorithm>
#include <cstdlib>

#include <spdlog/fmt/fmt.h>

#include "Cluster/Launch.h"

namespace rt::cluster
{
std::string Job::name(int r) const
{
    return fmt::format("rank {} ({})", r, host(r));
}

Job& job()
{
    static Job theJob;
    return theJob;
}

int launchedRanks()
{
    // Open MPI's launcher sets it in every process it starts (PMIx's own variables come with it).
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    return size ? std::max(1, std::atoi(size)) : 1;
}
} // namespace rt::cluster
