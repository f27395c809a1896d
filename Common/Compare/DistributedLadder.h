// The ladder of Compare.h over the ranks of an MPI job (docs/SCALING.md): root hands the reference's two halves,
// then every render of the ladder (Ladder.h's jobs), to whichever rank is free, itself included
// (Cluster/TaskPool.h); every rank has made the same engines. Each render's figures come back to root, which files
// them as they come (the CSV row names the rank), and prints the tables of a one-process run once all have
// come. A rank's failure ends the job with one error line and no CSV; Ctrl-C keeps the CSV's rows.
#pragma once

#include <vector>

#include "Compare/ComparisonRun.h"
#include "Compare/ImageFolder.h"
#include "Scene/Scene.h"

namespace rt::compare
{
/// Runs on every rank of the job (collective), under the caller's InterruptScope; `images` is root's (disabled
/// elsewhere). Returns the process status: 0, or the failed job's status; a cancelled job leaves with 130
/// (Job::leave). Throws rt::Error subclasses for this rank's own failures (guardedMain ends the job then).
int runDistributedLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                         std::vector<EngineUnderTest>& engines, ImageFolder& images);
} // namespace rt::compare
