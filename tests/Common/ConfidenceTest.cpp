// --compare's confidence intervals (Compare/Confidence.h): the t quantiles against Student's published table,
// the incomplete beta function at its closed forms, and the intervals' coverage over many synthetic
// experiments of known truth (issue 39: 93-97 % for a 95 % interval).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "Compare/Confidence.h"

namespace rt::compare
{
namespace
{
TEST(Confidence, IncompleteBetaMeetsItsClosedForms)
{
    for (const double x : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0})
    {
        EXPECT_NEAR(incompleteBeta(x, 1.0, 1.0), x, 1e-12) << x;               // uniform
        EXPECT_NEAR(incompleteBeta(x, 3.0, 1.0), x * x * x, 1e-12) << x;       // I_x(a, 1) = x^a
        EXPECT_NEAR(incompleteBeta(x, 1.0, 2.0), 1.0 - (1.0 - x) * (1.0 - x), 1e-12) << x;
    }
    for (const double a : {0.5, 2.0, 7.5, 40.0})
        EXPECT_NEAR(incompleteBeta(0.5, a, a), 0.5, 1e-12) << a; // symmetric about one half
}

TEST(Confidence, StudentQuantilesMatchThePublishedTable)
{
    // Two-sided 95 % (p = 0.975) and 99 % (p = 0.995) critical values, e.g. Abramowitz & Stegun table 26.10.
    const struct
    {
        int dof;
        double t975, t995;
    } table[] = {{1, 12.7062, 63.6567}, {2, 4.3027, 9.9248}, {3, 3.1824, 5.8409}, {5, 2.5706, 4.0321},
                 {9, 2.2622, 3.2498},  {10, 2.2281, 3.1693}, {30, 2.0423, 2.7500}, {120, 1.9799, 2.6174}};
    for (const auto& row : table)
    {
        EXPECT_NEAR(studentTQuantile(0.975, row.dof), row.t975, 1e-4) << row.dof;
        EXPECT_NEAR(studentTQuantile(0.995, row.dof), row.t995, 1e-4) << row.dof;
        EXPECT_NEAR(studentTQuantile(0.025, row.dof), -row.t975, 1e-4) << row.dof;
    }
    EXPECT_NEAR(studentTQuantile(0.975, 100000), 1.95996, 1e-4) << "the normal's limit";
}

TEST(Confidence, OneValueHasNoSpreadAndNoneIsEmpty)
{
    const Interval one = meanInterval({0.25});
    EXPECT_EQ(one.mean, 0.25);
    EXPECT_EQ(one.lo, 0.25);
    EXPECT_EQ(one.hi, 0.25);
    EXPECT_EQ(meanInterval({}).count, 0);
    const Interval r = ratioInterval({2.0}, {4.0});
    EXPECT_EQ(r.mean, 0.5);
    EXPECT_EQ(r.lo, 0.5);
    EXPECT_TRUE(std::isnan(ratioInterval({1.0}, {}).mean));
}

/// The fraction of `runs` experiments whose 95 % interval holds the truth; `experiment` returns whether its
/// interval did.
template <class Experiment>
double coverage(int runs, Experiment&& experiment)
{
    int covered = 0;
    for (int i = 0; i < runs; ++i)
        covered += experiment() ? 1 : 0;
    return double(covered) / runs;
}

// 2000 experiments: the coverage's own standard error is 0.5 %, so 93-97 % is four of them either side of 95 %.
constexpr int kExperiments = 2000;

TEST(ConfidenceCoverage, MeanIntervalOfNormalSeeds)
{
    // relMSE over seeds: a sum over many pixels, near normal. 8 seeds of mean 1e-3, spread 30 %.
    std::mt19937_64 rng(39);
    std::normal_distribution<double> relMse(1e-3, 3e-4);
    const double c = coverage(kExperiments, [&] {
        std::vector<double> seeds(8);
        for (double& v : seeds)
            v = relMse(rng);
        return meanInterval(seeds).contains(1e-3);
    });
    EXPECT_GE(c, 0.93);
    EXPECT_LE(c, 0.97);
}

TEST(ConfidenceCoverage, MeanIntervalOfSkewedSeeds)
{
    // A heavier right tail (gamma of shape 20: skewness 0.45), as relMSE has from fireflies; 10 seeds.
    std::mt19937_64 rng(40);
    std::gamma_distribution<double> relMse(20.0, 1e-4); // mean 2e-3
    const double c = coverage(kExperiments, [&] {
        std::vector<double> seeds(10);
        for (double& v : seeds)
            v = relMse(rng);
        return meanInterval(seeds).contains(2e-3);
    });
    EXPECT_GE(c, 0.93);
    EXPECT_LE(c, 0.97);
}

TEST(ConfidenceCoverage, RatioIntervalOfTwoStrategies)
{
    // Two strategies' relMSE x time over 8 seeds each, true means 3e-3 and 1e-3: their ratio is 3.
    std::mt19937_64 rng(41);
    std::normal_distribution<double> a(3e-3, 6e-4), b(1e-3, 2.5e-4);
    const double c = coverage(kExperiments, [&] {
        std::vector<double> x(8), y(8);
        for (double& v : x)
            v = a(rng);
        for (double& v : y)
            v = b(rng);
        return ratioInterval(x, y).contains(3.0);
    });
    EXPECT_GE(c, 0.93);
    EXPECT_LE(c, 0.97);
}
} // namespace
} // namespace rt::compare
