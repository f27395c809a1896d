// Pearson's chi-square goodness-of-fit test for sampling routines over a 2-D histogram, after Mitsuba 3's
// ChiSquareTest (research notes §2.1): cells below 5 expected samples are pooled in ascending order of
// expectation, the p-value comes from the regularised incomplete gamma function, and a test of `tests`
// configurations at overall significance alpha rejects at the Šidák-corrected 1 - (1 - alpha)^(1/tests).
#pragma once

#include <string>
#include <vector>

namespace rt::test
{
struct ChiSquareResult
{
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 0.0;
    bool passed = false;
    std::string message; // why it failed, for the assertion message
};

/// Upper regularised incomplete gamma Q(a, x) = Γ(a, x) / Γ(a) (series below a + 1, continued fraction
/// above; Press et al., Numerical Recipes §6.2).
double gammaQ(double a, double x);

/// `observed` and `expected` are cell counts of the same histogram (expected sums to the sample count).
/// A cell with expectation 0 and observations fails the test outright.
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double alpha = 0.01, int tests = 1);

} // namespace rt::test
