#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "HostThreads.h"

namespace rt
{
namespace
{
TEST(HostThreads, EveryPartRunsOnceAndErrorsReachTheCaller)
{
    std::vector<std::atomic<int>> runs(5);
    runInParallel(5, [&](int part) { ++runs[static_cast<std::size_t>(part)]; });
    for (const auto& r : runs)
        EXPECT_EQ(r.load(), 1);
    EXPECT_THROW(runInParallel(3, [](int part) {
                     if (part == 1)
                         throw std::runtime_error("part 1");
                 }),
                 std::runtime_error);
    EXPECT_GE(usableCores(), 1);
}
} // namespace
} // namespace rt
