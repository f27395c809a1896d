#include <gtest/gtest.h>

#include "Engine/RenderLimits.h"

namespace rt::gpu
{
namespace
{
const TargetLimits kLavapipe{"llvmpipe", 16384, 23'500'000'000ull, 2'147'483'648ull, 1ull << 30};
const TargetLimits kH100{"NVIDIA H100", 32768, 85'000'000'000ull, 85'000'000'000ull, 1ull << 30};

TEST(RenderLimits, OrdinarySizesFit)
{
    EXPECT_FALSE(checkTargetLimits(1920, 1080, kLavapipe));
    EXPECT_FALSE(checkTargetLimits(8192, 8192, kH100));
}

TEST(RenderLimits, AbsurdSizeNamesDimensionAndMemory)
{
    const auto problem = checkTargetLimits(60000, 60000, kLavapipe);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("image 60000x60000 exceeds maxImageDimension2D 16384 of device 'llvmpipe'"),
              std::string::npos)
        << *problem;
    EXPECT_NE(problem->find("needs 115.2 GB of device memory; device 'llvmpipe' has 23.5 GB"), std::string::npos)
        << *problem;
    EXPECT_EQ(problem->find('\n'), std::string::npos) << "one line";
}

TEST(RenderLimits, SingleAllocationLimit)
{
    const auto problem = checkTargetLimits(16384, 16384, kLavapipe); // 4.3 GB in one image
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("maxMemoryAllocationSize"), std::string::npos) << *problem;
}

TEST(RenderLimits, RayDispatchInvocationLimit)
{
    TargetLimits limits = kH100;
    limits.maxRayDispatchInvocations = 1u << 20;
    const auto problem = checkTargetLimits(2048, 1024, limits);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("maxRayDispatchInvocationCount"), std::string::npos) << *problem;
}

TEST(RenderLimits, TooWideForTheDeviceButSmallInMemory)
{
    const auto problem = checkTargetLimits(40000, 10, kH100);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("maxImageDimension2D 32768"), std::string::npos) << *problem;
}
} // namespace
} // namespace rt::gpu
