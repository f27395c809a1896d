#include "Compare/DistributedLadder.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/Interrupt.h"
#include "Cluster/Job.h"
#include "Cluster/SplitRender.h"
#include "Cluster/TaskPool.h"
#include "Compare/Compare.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/Ladder.h"
#include "Compare/RowJob.h"
#include "Error.h"

namespace rt::compare
{
namespace
{
using cluster::PartEnd;

/// A wait on the job's messages with Ctrl-C (mpirun's SIGTERM) routed to the part's control, which ends it.
template <typename Wait>
auto interruptible(RenderControl& control, Wait&& wait)
{
    InterruptScope::route(&control);
    if (InterruptScope::interrupted())
        control.requestCancel();
    auto result = wait();
    InterruptScope::route(nullptr);
    return result;
}

/// Root's side: the reference (given, cached, or its halves handed out), then the ladder's renders handed out
/// and filed. False when the part was cancelled (Ctrl-C, a Stop, another rank's end).
bool leadLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                std::vector<EngineUnderTest>& engines, ImageFolder& images, cluster::TaskPool& pool,
                RenderControl& control, std::unique_ptr<ConvergenceCsv>& csv, std::optional<LadderTable>& table,
                std::optional<Reference>& reference)
{
    EngineUnderTest& last = engines.back();
    reference = givenReference(scene, base, options, last.kind);
    if (!reference)
    {
        std::fprintf(stderr, "reference: rendering 2 x %d spp on the %s engine, its halves on the first free ranks...\n",
                     referenceHalf(base, options, 0).settings.spp, toString(last.kind));
        std::array<std::optional<Measurement>, 2> halves;
        for (int h = 0; h < 2; ++h)
            pool.add(nlohmann::json(RowJob{.half = h}).dump());
        while (const auto task = interruptible(control, [&] { return pool.next(); }))
        {
            Measurement m = measure(*last.engine, referenceHalf(base, options, int(task->index)), nullptr);
            if (m.cancelled)
                return false;
            halves[task->index] = std::move(m);
        }
        if (!interruptible(control, [&] { return pool.drain(); }))
            return false;
        for (cluster::TaskPool::Result& r : pool.takeResults())
        {
            std::string device;
            halves[r.task] = unpackMeasurement(r.bytes, device);
        }
        reference = finishReference(scene, base, options, last.kind, *halves[0], *halves[1]);
    }
    if (!pool.share(packReference(*reference)))
        return false;
    images.addReference(reference->image, reference->description, reference->spp, reference->ownRelMse);
    if (!options.csv.empty())
        csv = std::make_unique<ConvergenceCsv>(options.csv);
    table.emplace(scene, base, options, engines, *reference, csv.get(), images);
    LadderRunner runner(base, options, engines, *reference);
    const std::vector<RowJob> jobs = ladderJobs(options, engines, images.enabled());
    std::size_t first = 0; // the task index of jobs[0] (after the reference's halves, where there were any)
    for (std::size_t j = 0; j < jobs.size(); ++j)
    {
        const std::size_t index = pool.add(nlohmann::json(jobs[j]).dump());
        if (j == 0)
            first = index;
    }
    const auto fileResults = [&] {
        for (cluster::TaskPool::Result& r : pool.takeResults())
        {
            std::string device;
            Measurement m = unpackMeasurement(r.bytes, device);
            table->record(jobs[r.task - first], std::move(m), std::nullopt, device, r.rank);
        }
    };
    while (true)
    {
        // Root files the others' renders between its own, not inside their timed batches.
        fileResults();
        const auto task = interruptible(control, [&] { return pool.next(); });
        if (!task)
            break;
        const RowJob& job = jobs[task->index - first];
        LadderRender done = runner.run(job);
        if (done.measurement.cancelled)
            return false;
        table->record(job, std::move(done.measurement), std::nullopt, engines[job.engine].engine->deviceName(), 0);
    }
    if (!interruptible(control, [&] { return pool.drain(); }))
        return false;
    fileResults();
    return true;
}

/// Another rank's side: the tasks root hands it, until none is left. False when the part was cancelled.
bool followLadder(const RenderRequest& base, const CompareOptions& options, std::vector<EngineUnderTest>& engines,
                  cluster::TaskPool& pool, RenderControl& control)
{
    std::optional<Reference> reference;
    std::optional<LadderRunner> runner;
    pool.onShare([&](const std::string& bytes) {
        reference = unpackReference(bytes);
        runner.emplace(base, options, engines, *reference);
    });
    while (const auto task = interruptible(control, [&] { return pool.next(); }))
    {
        const RowJob job = nlohmann::json::parse(task->description).get<RowJob>();
        if (job.half >= 0)
        {
            EngineUnderTest& last = engines.back();
            const Measurement m = measure(*last.engine, referenceHalf(base, options, job.half), nullptr);
            if (m.cancelled)
                return false;
            if (!pool.sendResult(task->index, packMeasurement(m, true, last.engine->deviceName())))
                return false;
            continue;
        }
        if (!runner)
            throw Error("MPI: a render of the ladder came before its reference");
        LadderRender done = runner->run(job);
        if (done.measurement.cancelled)
            return false;
        if (!pool.sendResult(task->index, packMeasurement(done.measurement, job.keepImage,
                                                          engines[job.engine].engine->deviceName())))
            return false;
    }
    return !control.cancelRequested();
}
} // namespace

int runDistributedLadder(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                         std::vector<EngineUnderTest>& engines, ImageFolder& images)
{
    cluster::Job& job = cluster::job();
    RenderControl control; // the part's: a Stop, or on root another rank's end, cancels it
    cluster::SplitRender part(job, control, false);
    std::unique_ptr<ConvergenceCsv> csv;
    std::optional<LadderTable> table;
    std::optional<Reference> reference;
    PartEnd mine;
    try
    {
        cluster::TaskPool pool(job, part, control);
        // Every render serves the job's messages before each batch, and stops when the part is cancelled.
        BatchHookScope hook([&] {
            pool.serve();
            return !control.cancelRequested();
        });
        bool finished = job.root()
                            ? leadLadder(scene, base, options, engines, images, pool, control, csv, table, reference)
                            : followLadder(base, options, engines, pool, control);
        if (job.root())
            finished = interruptible(control, [&] { return pool.close(); }) && finished;
        mine.status = finished ? PartEnd::Status::Finished : PartEnd::Status::Cancelled;
    }
    catch (const Error& e)
    {
        // This part's own failure ends it here, where the Ends root has already taken are known.
        mine = {.status = PartEnd::Status::Failed, .message = e.what(), .exitCode = e.exitCode()};
    }
    catch (const std::exception& e)
    {
        mine = {.status = PartEnd::Status::Failed, .message = e.what(), .exitCode = 1};
    }
    // mpirun's SIGTERM (Ctrl-C, or a rank died) tells root's end not to wait for a silent rank beyond a moment.
    const cluster::Verdict verdict = interruptible(control, [&] { return part.end(mine); });
    if (verdict.status == PartEnd::Status::Failed)
    {
        // No partial outputs from a failed job (Ctrl-C's keep their rows and images).
        if (csv)
        {
            csv.reset();
            std::error_code ignored;
            std::filesystem::remove(options.csv, ignored);
        }
        images.discard();
        return cluster::endFailedJob(job, verdict);
    }
    if (verdict.status == PartEnd::Status::Cancelled)
    {
        if (job.root())
            spdlog::warn("comparison cancelled{}", keptOnCancel(options, csv != nullptr, images.enabled()));
        // mpirun, ending the job, no longer lets MPI_Finalize finish: exit before its SIGKILL.
        job.leave(130);
    }
    if (!job.root())
        return 0;
    table->print();
    drawFigures(options, images);
    return 0;
}
} // namespace rt::compare
