// restir-di's reservoir (Shared/Restir.h): weighted reservoir sampling keeps each candidate with probability
// in proportion to its weight (chi-square), and resampled importance sampling with its contribution weight is
// unbiased for a known integral whatever the target (Bitterli et al. 2020, §3; Talbot et al. 2005).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "Shared/Random.h"
#include "Shared/Restir.h"
#include "Support/ChiSquare.h"

namespace rt::test
{
namespace
{
using shader::Reservoir;

TEST(Reservoir, KeepsEachCandidateInProportionToItsWeight)
{
    const std::vector<float> weights{0.5f, 0.0f, 2.0f, 1.0f, 0.25f, 4.0f, 0.0f, 1.25f};
    double total = 0.0;
    for (float w : weights)
        total += w;
    constexpr int kTrials = 200000;
    std::vector<double> observed(weights.size(), 0.0);
    shader::Rng rng = shader::rngForSample(11u, 0u, 0u);
    for (int t = 0; t < kTrials; ++t)
    {
        Reservoir r = shader::emptyReservoir();
        float weightSum = 0.0f;
        for (std::size_t i = 0; i < weights.size(); ++i)
            shader::offerCandidate(r, weightSum, std::uint32_t(i), vec3(float(i)), 1.0f, weights[i], shader::nextFloat(rng));
        ASSERT_NE(r.light, shader::kNoIndex);
        observed[r.light] += 1.0;
        EXPECT_FLOAT_EQ(weightSum, float(total));
    }
    std::vector<double> expected;
    for (float w : weights)
        expected.push_back(kTrials * w / total);
    const ChiSquareResult chi = chiSquareTest(observed, expected);
    EXPECT_TRUE(chi.passed) << chi.message;
}

TEST(Reservoir, NothingIsChosenFromZeroOrNanWeights)
{
    Reservoir r = shader::emptyReservoir();
    float weightSum = 0.0f;
    EXPECT_FALSE(shader::offerCandidate(r, weightSum, 3u, vec3(1.0f), 1.0f, 0.0f, 0.0f));
    EXPECT_FALSE(shader::offerCandidate(r, weightSum, 3u, vec3(1.0f), 1.0f, std::nanf(""), 0.0f));
    EXPECT_EQ(r.light, shader::kNoIndex);
    EXPECT_EQ(shader::contributionWeight(weightSum, r.target, 8.0f), 0.0f);
}

// RIS of g(x) = x^2 on [0, 1] from M uniform candidates with target p-hat(x) = x + 0.1: E[g(y) W] = 1/3 for
// every M, and its variance falls below plain Monte Carlo's as M grows (p-hat follows g).
TEST(Reservoir, ResampledImportanceSamplingIsUnbiased)
{
    constexpr int kTrials = 200000;
    double plainVariance = 0.0;
    for (int m : {1, 4, 32})
    {
        shader::Rng rng = shader::rngForSample(7u, std::uint32_t(m), 0u);
        double sum = 0.0, sumSq = 0.0;
        for (int t = 0; t < kTrials; ++t)
        {
            Reservoir r = shader::emptyReservoir();
            float weightSum = 0.0f;
            for (int k = 0; k < m; ++k)
            {
                const float x = shader::nextFloat(rng);
                const float target = x + 0.1f;
                shader::offerCandidate(r, weightSum, 0u, vec3(x, 0.0f, 0.0f), target, target / 1.0f, shader::nextFloat(rng));
            }
            const double w = shader::contributionWeight(weightSum, r.target, float(m));
            const double estimate = double(r.point.x) * r.point.x * w;
            sum += estimate;
            sumSq += estimate * estimate;
        }
        const double mean = sum / kTrials;
        const double variance = sumSq / kTrials - mean * mean;
        EXPECT_NEAR(mean, 1.0 / 3.0, 4.0 * std::sqrt(variance / kTrials)) << "M = " << m;
        if (m == 1)
            plainVariance = variance;
        else
            EXPECT_LT(variance, plainVariance) << "M = " << m;
    }
}
// The same RIS with restir-di's stratified candidates (stratifiedCandidateNumber: x_k = (k + xi) / M, one xi for
// all): each x_k is uniform on its stratum only, the candidates are dependent, and the weights still take the pooled
// density p = 1 (GRIS's balance heuristic over the strata). E[g(y) W] = 1/3, with less variance than independent
// candidates at the same M.
TEST(Reservoir, ResampledImportanceSamplingOfStratifiedCandidatesIsUnbiased)
{
    constexpr int kTrials = 200000;
    for (int m : {1, 4, 32})
    {
        double mean[2] = {}, variance[2] = {};
        for (int stratified = 0; stratified < 2; ++stratified)
        {
            shader::Rng rng = shader::rngForSample(11u, std::uint32_t(m), std::uint32_t(stratified));
            double sum = 0.0, sumSq = 0.0;
            for (int t = 0; t < kTrials; ++t)
            {
                Reservoir r = shader::emptyReservoir();
                float weightSum = 0.0f;
                const float xi = shader::nextFloat(rng);
                for (int k = 0; k < m; ++k)
                {
                    const float x = stratified ? shader::stratifiedCandidateNumber(std::uint32_t(k), std::uint32_t(m), xi)
                                               : shader::nextFloat(rng);
                    const float target = x + 0.1f;
                    shader::offerCandidate(r, weightSum, 0u, vec3(x, 0.0f, 0.0f), target, target, shader::nextFloat(rng));
                }
                const double w = shader::contributionWeight(weightSum, r.target, float(m));
                const double estimate = double(r.point.x) * r.point.x * w;
                sum += estimate;
                sumSq += estimate * estimate;
            }
            mean[stratified] = sum / kTrials;
            variance[stratified] = sumSq / kTrials - mean[stratified] * mean[stratified];
        }
        EXPECT_NEAR(mean[1], 1.0 / 3.0, 4.0 * std::sqrt(variance[1] / kTrials)) << "M = " << m;
        if (m > 1)
            EXPECT_LT(variance[1], variance[0]) << "M = " << m << ": the strata did not lower the variance";
    }
}

// Pairwise MIS (Shared/Restir.h): for any point x, the canonical input's weight and the k neighbours' weights sum to
// 1 whatever the counts and targets, wherever the canonical target is positive (its domain holds every x the
// integrand reaches); a neighbour whose target is 0 at x (x outside its domain) gets weight 0. Unbiasedness rests
// on exactly this.
TEST(Reservoir, PairwiseMisWeightsSumToOneOverTheInputsWhoseDomainHoldsThePoint)
{
    shader::Rng rng = shader::rngForSample(3u, 0u, 0u);
    for (int trial = 0; trial < 10000; ++trial)
    {
        const int k = 1 + int(shader::nextFloat(rng) * 8.0f);
        const float canonicalCount = 1.0f + 640.0f * shader::nextFloat(rng);
        const float canonicalTarget = 1e-3f + 100.0f * shader::nextFloat(rng) * shader::nextFloat(rng);
        double sum = 0.0;
        for (int i = 0; i < k; ++i)
        {
            const float count = 1.0f + 640.0f * shader::nextFloat(rng);
            // A third of the neighbours cannot produce x: their target (with visibility) is 0 there.
            const float target = shader::nextFloat(rng) < 0.33f ? 0.0f : 100.0f * shader::nextFloat(rng);
            const float mi = shader::pairwiseNeighbourMis(float(k), count, target, canonicalCount, canonicalTarget);
            if (target == 0.0f)
            {
                EXPECT_EQ(mi, 0.0f);
            }
            sum += mi;
            sum += shader::pairwiseCanonicalTerm(float(k), canonicalCount, canonicalTarget, count, target);
        }
        ASSERT_NEAR(sum, 1.0, 1e-5) << "trial " << trial << ", k " << k;
    }
}
} // namespace
} // namespace rt::test
