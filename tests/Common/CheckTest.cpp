// Check.h and Format.h: a failed RT_CHECK prints one line naming the expression and its values and aborts,
// RT_DCHECK vanishes in Release (its arguments unevaluated), and the fmt formatters of Common's types print
// exactly what the messages promise.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "Check.h"
#include "Format.h"
#include "Math/Aabb.h"
#include "Math/Math.h"
#include "Render/RenderSettings.h"

namespace rt
{
namespace
{
// Death tests fork; "threadsafe" re-executes the binary for the child, so threads other tests left
// behind cannot deadlock it.
class CheckDeathTest : public testing::Test
{
protected:
    void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(CheckDeathTest, FailedComparisonPrintsFileExpressionAndBothValues)
{
    EXPECT_DEATH(RT_CHECK_EQ(2 + 2, 5),
                 "CheckTest\\.cpp:[0-9]+: check failed: 2 \\+ 2 == 5 with 2 \\+ 2 = 4, 5 = 5");
}

TEST_F(CheckDeathTest, FailedConditionPrintsTheExpression)
{
    const int depth = 0;
    EXPECT_DEATH(RT_CHECK(depth > 0), "critical: .*CheckTest\\.cpp:[0-9]+: check failed: depth > 0");
}

TEST_F(CheckDeathTest, EveryComparisonFails)
{
    EXPECT_DEATH(RT_CHECK_NE(3, 3), "3 != 3 with 3 = 3, 3 = 3");
    EXPECT_DEATH(RT_CHECK_LT(3, 3), "3 < 3 with");
    EXPECT_DEATH(RT_CHECK_LE(4, 3), "4 <= 3 with");
    EXPECT_DEATH(RT_CHECK_GT(3, 3), "3 > 3 with");
    EXPECT_DEATH(RT_CHECK_GE(2.5f, 3.0f), "2\\.5f >= 3\\.0f with 2\\.5f = 2\\.5, 3\\.0f = 3");
}

TEST_F(CheckDeathTest, IntegersCompareByValueWhateverTheirSignedness)
{
    const int index = -1;
    const std::size_t size = 3;
    RT_CHECK_LT(index, size); // -1 < 3, although -1 converted to size_t is not
    EXPECT_DEATH(RT_CHECK_GE(index, size), "index >= size with index = -1, size = 3");
}

TEST_F(CheckDeathTest, CommonTypesAndPointersPrint)
{
    const vec3 a(1.0f, 2.5f, -3.0f);
    EXPECT_DEATH(RT_CHECK_EQ(a, vec3(0.0f)),
                 "a == vec3\\(0\\.0f\\) with a = \\(1, 2\\.5, -3\\), .* = \\(0, 0, 0\\)");
    EXPECT_DEATH(RT_CHECK_EQ(EngineKind::Gpu, EngineKind::Multi), "= gpu, .* = multi");
    const int value = 1;
    const int* pointer = &value;
    EXPECT_DEATH(RT_CHECK_EQ(pointer, nullptr), "pointer = 0x[0-9a-f]+, nullptr = 0x0");
}

#ifndef NDEBUG
TEST_F(CheckDeathTest, DebugChecksAbortInDebugBuilds)
{
    EXPECT_DEATH(RT_DCHECK(false), "check failed: false");
    EXPECT_DEATH(RT_DCHECK_EQ(1, 2), "1 == 2 with 1 = 1, 2 = 2");
}
#endif

TEST(Check, PassingChecksDoNothingAndEvaluateTheirArgumentsOnce)
{
    int calls = 0;
    RT_CHECK(++calls == 1);
    RT_CHECK_EQ(++calls, 2);
    RT_CHECK_NE(++calls, 0);
    RT_CHECK_LT(++calls, 5);
    RT_CHECK_LE(++calls, 5);
    RT_CHECK_GT(++calls, 5);
    RT_CHECK_GE(++calls, 7);
    EXPECT_EQ(calls, 7);
    RT_CHECK_EQ(std::string("abc"), "abc");
}

TEST(Check, DebugChecksFollowNdebug)
{
    int calls = 0;
    RT_DCHECK(++calls == 1);
    RT_DCHECK_EQ(++calls, 2);
    RT_DCHECK_GE(++calls, 3);
#ifdef NDEBUG
    EXPECT_EQ(RT_DCHECK_IS_ON, 0);
    EXPECT_EQ(calls, 0) << "RT_DCHECK evaluated its arguments in a Release build";
    RT_DCHECK(false); // must not abort
    RT_DCHECK_EQ(1, 2);
#else
    EXPECT_EQ(RT_DCHECK_IS_ON, 1);
    EXPECT_EQ(calls, 3);
#endif
}

TEST(Format, Vectors)
{
    EXPECT_EQ(fmt::format("{}", vec3(1.0f, 2.5f, -3.0f)), "(1, 2.5, -3)");
    EXPECT_EQ(fmt::format("{}", vec2(0.125f, 1e-3f)), "(0.125, 0.001)");
    EXPECT_EQ(fmt::format("{}", vec4(1.0f, 2.0f, 3.0f, 4.0f)), "(1, 2, 3, 4)");
    EXPECT_EQ(fmt::format("{:.2f}", vec3(1.0f, 2.5f, -3.0f)), "(1.00, 2.50, -3.00)");
    EXPECT_EQ(fmt::format("{}", ivec2(-4, 7)), "(-4, 7)");
}

TEST(Format, Aabb)
{
    EXPECT_EQ(fmt::format("{}", Aabb(vec3(1.0f, 2.0f, 3.0f), vec3(0.0f, -1.0f, 0.5f))),
              "[(0, -1, 0.5) .. (1, 2, 3)]");
    EXPECT_EQ(fmt::format("{:.1f}", Aabb(vec3(0.0f), vec3(1.0f))), "[(0.0, 0.0, 0.0) .. (1.0, 1.0, 1.0)]");
    EXPECT_EQ(fmt::format("{}", Aabb()), "[(inf, inf, inf) .. (-inf, -inf, -inf)]");
}

TEST(Format, Enums)
{
    EXPECT_EQ(fmt::format("{}", EngineKind::Single), "single");
    EXPECT_EQ(fmt::format("{}", EngineKind::Multi), "multi");
    EXPECT_EQ(fmt::format("{}", EngineKind::Gpu), "gpu");
    EXPECT_EQ(fmt::format("[{:>6}]", EngineKind::Gpu), "[   gpu]");
    EXPECT_EQ(fmt::format("{}", PixelSampling::Stratified), "stratified");
    EXPECT_EQ(fmt::format("{}", PixelSampling::Accumulate), "accumulate");
    EXPECT_EQ(fmt::format("{}", Estimator::BsdfOnly), "bsdf");
    EXPECT_EQ(fmt::format("{}", Estimator::Mixture), "mixture");
}

TEST(Format, RenderSettings)
{
    RenderSettings s;
    s.spp = 16;
    EXPECT_EQ(fmt::format("{}", s),
              "spp 16, depth 50, width 600, aspect 1, estimator nee-mis, light-sampler projected, light-selection bvh, "
              "sampling random, russian-roulette sqrt, unidirectional-light on, seed 0 (600x600)");

    s.spp = 10;
    s.depth = 8;
    s.width = 400;
    s.aspect = 16.0f / 9.0f;
    s.sampling = PixelSampling::Stratified;
    s.estimator = Estimator::BsdfOnly;
    s.unidirectionalLight = false;
    s.seed = 7;
    EXPECT_EQ(fmt::format("{}", s),
              "spp 10, depth 8, width 400, aspect 1.7777778, estimator bsdf, sampling stratified, russian-roulette sqrt, "
              "unidirectional-light off, seed 7 (400x225)");

    s.estimator = Estimator::RestirDi;
    s.restirBiased = true;
    EXPECT_EQ(fmt::format("{}", s),
              "spp 10, depth 8, width 400, aspect 1.7777778, estimator restir-di, light-sampler projected, "
              "light-selection bvh, restir-candidates 32, restir-spatial 5, restir-radius 30, restir-biased on, "
              "restir-temporal-cap 20, sampling stratified, russian-roulette sqrt, unidirectional-light off, seed 7 "
              "(400x225)");
}
} // namespace
} // namespace rt
