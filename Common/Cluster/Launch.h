// How the process was started, read from the environment before MPI is touched.
#pragma once

namespace rt::cluster
{
/// The ranks mpirun started, 1 when it did not start this process.
int launchedRanks();
} // namespace rt::cluster
