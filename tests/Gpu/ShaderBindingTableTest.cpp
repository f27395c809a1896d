// SBT layout arithmetic for the two drivers the project targets: queried values, never assumed ones.
#include <gtest/gtest.h>

#include "RayTracing/ShaderBindingTable.h"

namespace rt::gpu
{
namespace
{
void expectValid(const SbtLayout& l, std::uint32_t handleSize, std::uint32_t handleAlignment,
                 std::uint32_t baseAlignment, std::uint32_t missCount, std::uint32_t hitCount)
{
    for (const SbtLayout::Region* r : {&l.raygen, &l.miss, &l.hit})
    {
        EXPECT_EQ(r->offset % baseAlignment, 0u);
        EXPECT_EQ(r->stride % handleAlignment, 0u);
        EXPECT_GE(r->stride, handleSize);
    }
    EXPECT_EQ(l.raygen.size, l.raygen.stride); // VUID-vkCmdTraceRaysKHR-size-04023
    EXPECT_GE(l.miss.size, missCount * l.miss.stride);
    EXPECT_GE(l.hit.size, hitCount * l.hit.stride);
    EXPECT_GE(l.miss.offset, l.raygen.offset + l.raygen.size);
    EXPECT_GE(l.hit.offset, l.miss.offset + l.miss.size);
    EXPECT_EQ(l.totalSize, l.hit.offset + l.hit.size);
}

TEST(ShaderBindingTable, LavapipeLayout)
{
    const SbtLayout l = computeSbtLayout(32, 16, 32, 1, 3);
    expectValid(l, 32, 16, 32, 1, 3);
    EXPECT_EQ(l.miss.offset, 32u);
    EXPECT_EQ(l.hit.offset, 64u);
    EXPECT_EQ(l.hit.stride, 32u);
    EXPECT_EQ(l.totalSize, 160u);
}

TEST(ShaderBindingTable, NvidiaLayoutUses64ByteRegionAlignment)
{
    const SbtLayout l = computeSbtLayout(32, 32, 64, 1, 3);
    expectValid(l, 32, 32, 64, 1, 3);
    EXPECT_EQ(l.raygen.stride, 64u);
    EXPECT_EQ(l.miss.offset, 64u);
    EXPECT_EQ(l.hit.offset, 128u);
    EXPECT_EQ(l.hit.stride, 32u);
}

TEST(ShaderBindingTable, HandleLargerThanAlignment)
{
    expectValid(computeSbtLayout(48, 16, 64, 2, 5), 48, 16, 64, 2, 5);
}
} // namespace
} // namespace rt::gpu
