// The shares of an MPI job's ranks (Cluster/SplitRender.h), the job of a process mpirun did not start, and a task
// pool on it (root alone runs every task; the ranks' side is tests/Cli/mpi_compare.sh's).
#include <gtest/gtest.h>

#include "Cluster/Job.h"
#include "Cluster/SplitRender.h"
#include "Cluster/TaskPool.h"

namespace rt::cluster
{
namespace
{
TEST(SampleShares, ConsecutiveRunsThatCoverTheFrameOnce)
{
    for (std::uint32_t total : {1u, 2u, 7u, 64u, 65537u, 16777216u})
        for (int ranks : {1, 2, 3, 4, 5, 8, 100})
        {
            std::uint32_t next = 0;
            std::uint32_t least = total;
            std::uint32_t most = 0;
            for (int r = 0; r < ranks; ++r)
            {
                const FramePart p = shareOf(total, r, ranks);
                ASSERT_TRUE(p.samples.has_value());
                EXPECT_EQ(p.firstSample, next) << total << " over " << ranks << ", rank " << r;
                next += *p.samples;
                least = std::min(least, *p.samples);
                most = std::max(most, *p.samples);
                if (r > 0)
                {
                    EXPECT_LE(*p.samples, *shareOf(total, r - 1, ranks).samples)
                        << "the first ranks take one more";
                }
            }
            EXPECT_EQ(next, total) << total << " over " << ranks;
            EXPECT_LE(most - least, 1u) << total << " over " << ranks;
        }
}

std::string nameOf(int r)
{
    return "rank " + std::to_string(r) + " (h)";
}

PartEnd finished(int rank)
{
    return {.status = PartEnd::Status::Finished, .stats = {{"rank", rank}}};
}

PartEnd failed(const std::string& message, int exitCode)
{
    return {.status = PartEnd::Status::Failed, .message = message, .exitCode = exitCode};
}

TEST(JobVerdict, EveryRankFinishedGivesEveryRanksStatsInRankOrder)
{
    const Verdict v = judgeEnds({finished(0), finished(1), finished(2)}, nameOf);
    EXPECT_EQ(v.status, PartEnd::Status::Finished);
    EXPECT_EQ(v.exitCode, 0);
    ASSERT_EQ(v.ranks.size(), 3u);
    for (int r = 0; r < 3; ++r)
        EXPECT_EQ(v.ranks[static_cast<std::size_t>(r)].at("rank"), r);
}

TEST(JobVerdict, ARanksErrorNamesItAndOutranksTheCancelsItCaused)
{
    const PartEnd cancelled{.status = PartEnd::Status::Cancelled};
    const Verdict v = judgeEnds({cancelled, failed("no such scene", 2), cancelled}, nameOf);
    EXPECT_EQ(v.status, PartEnd::Status::Failed);
    EXPECT_EQ(v.exitCode, 2);
    EXPECT_EQ(v.message, "rank 1 (h): no such scene");
    EXPECT_FALSE(v.silentRank);
}

TEST(JobVerdict, AnErrorEveryRankHadIsSaidOnceWithoutARank)
{
    const Verdict v = judgeEnds({failed("--spp must be positive", 2), failed("--spp must be positive", 2)}, nameOf);
    EXPECT_EQ(v.message, "--spp must be positive");
    EXPECT_EQ(v.exitCode, 2);
}

TEST(JobVerdict, ASilentRankIsNamedUnlessAnotherRankFailed)
{
    const PartEnd cancelled{.status = PartEnd::Status::Cancelled};
    const Verdict silent = judgeEnds({cancelled, std::nullopt, cancelled}, nameOf);
    EXPECT_EQ(silent.status, PartEnd::Status::Failed);
    EXPECT_TRUE(silent.silentRank) << "the job cannot end in step: it is abandoned";
    EXPECT_NE(silent.message.find("rank 1 (h) sent no word"), std::string::npos) << silent.message;
    EXPECT_NE(silent.exitCode, 0);

    // A rank still in its batch when root gave up does not hide the error that stopped the job.
    const Verdict both = judgeEnds({cancelled, failed("device lost", 4), std::nullopt}, nameOf);
    EXPECT_EQ(both.message, "rank 1 (h): device lost");
    EXPECT_EQ(both.exitCode, 4);
    EXPECT_TRUE(both.silentRank);
}

TEST(JobVerdict, CancelledWhenARankWasAndNoneFailed)
{
    const Verdict v = judgeEnds({finished(0), {PartEnd{.status = PartEnd::Status::Cancelled}}}, nameOf);
    EXPECT_EQ(v.status, PartEnd::Status::Cancelled);
    EXPECT_EQ(v.exitCode, 130);
}

TEST(Job, AProcessMpirunDidNotStartIsAJobOfOne)
{
    const Job& j = job();
    EXPECT_EQ(j.size(), 1);
    EXPECT_EQ(j.rank(), 0);
    EXPECT_TRUE(j.root());
    EXPECT_FALSE(j.distributed());
    EXPECT_FALSE(SplitRender::endAfterError(job(), "boom", 1).has_value()) << "no job to end";
}
TEST(TaskPool, OnAJobOfOneRootRunsEveryTaskInTheOrderAdded)
{
    RenderControl control;
    SplitRender part(job(), control, false);
    TaskPool pool(job(), part, control);
    EXPECT_EQ(pool.add("a"), 0u);
    EXPECT_EQ(pool.add("b"), 1u);
    const std::optional<Task> first = pool.next();
    ASSERT_TRUE(first.has_value());
    EXPECT_EQ(first->index, 0u);
    EXPECT_EQ(first->description, "a");
    EXPECT_EQ(pool.add("c"), 2u) << "tasks added later join the queue's end";
    EXPECT_EQ(pool.next()->description, "b");
    EXPECT_EQ(pool.next()->description, "c");
    EXPECT_FALSE(pool.next().has_value()) << "the queue is empty";
    EXPECT_EQ(pool.outstanding(), 0u);
    EXPECT_TRUE(pool.drain());
    EXPECT_TRUE(pool.close()) << "no other rank to tell";
    EXPECT_TRUE(pool.takeResults().empty());
}

TEST(TaskPool, ACancelledPartTakesNoTaskAndClosesCancelled)
{
    RenderControl control;
    SplitRender part(job(), control, false);
    TaskPool pool(job(), part, control);
    pool.add("a");
    control.requestCancel();
    EXPECT_FALSE(pool.next().has_value());
    EXPECT_FALSE(pool.drain());
    EXPECT_FALSE(pool.close());
}
} // namespace
} // namespace rt::cluster
