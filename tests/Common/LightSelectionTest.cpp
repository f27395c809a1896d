// NEE's light selection (Shared/LightSelection.h) and the alias table it draws from (Sampling/LightPower.h):
// the table reproduces its weights exactly, selection follows them (chi-square), lights of zero power are
// never picked, and power is area times emitted luminance.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "Random/Pcg.h"
#include "Render/RenderSettings.h"
#include "Sampling/LightPower.h"
#include "Scenes/Catalogue.h"
#include "Shared/LightSelection.h"
#include "Support/ChiSquare.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
/// The probability each light gets from the table, summed over its slots: slot i gives i with probability
/// threshold_i / n and its alias with (1 - threshold_i) / n.
std::vector<double> tableProbabilities(const std::vector<AliasEntry>& table)
{
    std::vector<double> p(table.size(), 0.0);
    const double n = double(table.size());
    for (std::size_t i = 0; i < table.size(); ++i)
    {
        p[i] += double(table[i].threshold) / n;
        p[table[i].alias] += (1.0 - double(table[i].threshold)) / n;
    }
    return p;
}

TEST(AliasTable, ReproducesItsWeights)
{
    const std::vector<std::vector<double>> cases = {
        {1.0},
        {1.0, 1.0, 1.0},
        {5.0, 1.0, 0.0, 3.0},
        {1e-6, 1.0, 1e6, 2.0, 7.5},
        {0.0, 0.0, 0.0}, // all zero: uniform
    };
    for (const auto& weights : cases)
    {
        const auto table = makeAliasTable(weights);
        ASSERT_EQ(table.size(), weights.size());
        const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
        const auto p = tableProbabilities(table);
        for (std::size_t i = 0; i < weights.size(); ++i)
        {
            const double expected = total > 0.0 ? weights[i] / total : 1.0 / double(weights.size());
            EXPECT_NEAR(p[i], expected, 1e-6) << "light " << i;
            EXPECT_NEAR(table[i].pmf, expected, 1e-7 + 1e-6 * expected) << "light " << i;
            EXPECT_LT(table[i].alias, weights.size());
            EXPECT_GE(table[i].threshold, 0.0f);
            EXPECT_LE(table[i].threshold, 1.0f);
        }
    }
}

TEST(AliasTable, SelectionFollowsThePmfAndNeverPicksAZeroWeight)
{
    const std::vector<double> weights = {3.0, 0.0, 1.0, 10.0, 0.5, 2.5, 0.0, 6.0};
    const auto table = makeAliasTable(weights);
    const int n = int(weights.size());
    constexpr long kSamples = 1'000'000;
    const auto h = test::histogram(n, kSamples, 42, [&](Rng& rng) {
        float pmf = 0.0f;
        const auto light = shader::selectLight(table.data(), nullptr, LightSelection::Power, rng.nextFloat(), n,
                                               vec3(0.0f), vec3(0.0f), false, pmf);
        EXPECT_EQ(pmf, table[light].pmf);
        EXPECT_EQ(shader::lightSelectionPmf(table.data(), nullptr, nullptr, LightSelection::Power, light, n,
                                            vec3(0.0f), vec3(0.0f), false),
                  pmf);
        return int(light);
    });
    EXPECT_EQ(h.counts[1], 0.0);
    EXPECT_EQ(h.counts[6], 0.0);
    std::vector<double> expected;
    for (const AliasEntry& e : table)
        expected.push_back(double(e.pmf) * kSamples);
    const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(LightSelection, UniformGivesEveryLightOneOverN)
{
    const std::vector<AliasEntry> none;
    for (const float u : {0.0f, 0.3f, 0.999999f})
    {
        float pmf = 0.0f;
        const auto light = shader::selectLight(none.data(), nullptr, LightSelection::Uniform, u, 7, vec3(0.0f),
                                               vec3(0.0f), false, pmf);
        EXPECT_EQ(light, std::uint32_t(u * 7.0f));
        EXPECT_FLOAT_EQ(pmf, 1.0f / 7.0f);
    }
}

TEST(LightPower, IsAreaTimesEmittedLuminance)
{
    // cornell-box-lights: nine 355 x 10 strips of radiance 15, then three spheres of radius 50.
    const Scene scene = makeScene("cornell-box-lights");
    const auto powers = emitterPowers(scene);
    ASSERT_EQ(powers.size(), 12u);
    for (int i = 0; i < 9; ++i)
        EXPECT_NEAR(powers[i], 3550.0 * 15.0, 1e-6 * 3550.0 * 15.0);
    const double sphereArea = 4.0 * 3.14159265358979 * 2500.0;
    EXPECT_NEAR(powers[9], sphereArea * luminance(vec3(20.0f, 0.7f, 0.7f)), 1e-5 * powers[9]);
    const auto table = lightAliasTable(scene);
    EXPECT_NEAR(table[9].pmf / table[0].pmf, powers[9] / powers[0], 1e-5);
}
} // namespace
} // namespace rt
