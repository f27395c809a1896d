// The shares of an MPI job's ranks (Cluster/SplitRender.h) and the job of a process mpirun did not start.
#include <gtest/gtest.h>

#include "Cluster/Job.h"
#include "Cluster/SplitRender.h"

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

TEST(Job, AProcessMpirunDidNotStartIsAJobOfOne)
{
    const Job& j = job();
    EXPECT_EQ(j.size(), 1);
    EXPECT_EQ(j.rank(), 0);
    EXPECT_TRUE(j.root());
    EXPECT_FALSE(j.distributed());
    EXPECT_FALSE(SplitRender::endAfterError(job(), "boom", 1).has_value()) << "no job to end";
}
} // namespace
} // namespace rt::cluster
