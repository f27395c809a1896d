// Confidence intervals for --compare's repeated seeds (--seeds N): each seed's render is an independent
// estimate, so a figure is reported as the mean over the seeds with the Student-t interval of that mean, and a
// ratio of two strategies' efficiencies with the interval of the ratio (the delta method on its logarithm).
// Student 1908; the t quantile by bisection on its distribution function, written with the regularised
// incomplete beta function (Press et al., Numerical Recipes 3rd ed., §6.4 and §6.14).
#pragma once

#include <vector>

namespace rt::compare
{
/// A mean and its two-sided confidence interval; lo == hi == mean when there was one value.
struct Interval
{
    double mean = 0.0;
    double lo = 0.0;
    double hi = 0.0;
    int count = 0;

    bool contains(double x) const { return lo <= x && x <= hi; }
};

/// Regularised incomplete beta function I_x(a, b), a, b > 0, x in [0, 1].
double incompleteBeta(double x, double a, double b);

/// The p-quantile (0 < p < 1) of Student's t distribution with `degreesOfFreedom` >= 1.
double studentTQuantile(double p, int degreesOfFreedom);

/// The mean of `values` and its `level` (e.g. 0.95) Student-t interval, mean +- t s / sqrt(n). Empty values
/// give count 0 and zeros.
Interval meanInterval(const std::vector<double>& values, double level = 0.95);

/// The ratio mean(numerator) / mean(denominator) of two independent sets of positive values, with its `level`
/// interval: exp(log ratio +- t sqrt(s_a^2 / (n_a a^2) + s_b^2 / (n_b b^2))), t of min(n_a, n_b) - 1 degrees of
/// freedom (conservative against Welch's). One value on either side gives lo == hi == the ratio.
Interval ratioInterval(const std::vector<double>& numerator, const std::vector<double>& denominator,
                       double level = 0.95);
} // namespace rt::compare
