#include "Support/ChiSquare.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace rt::test
{
namespace
{
double gammaPSeries(double a, double x)
{
    double sum = 1.0 / a, term = sum;
    for (int n = 1; n < 10000; ++n)
    {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-15)
            break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double gammaQContinuedFraction(double a, double x)
{
    // Modified Lentz's method.
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i)
    {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny)
            d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15)
            break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
} // namespace

double gammaQ(double a, double x)
{
    if (x <= 0.0)
        return 1.0;
    return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                              int tests)
{
    ChiSquareResult r;
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });

    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (std::size_t i : order)
    {
        if (expected[i] == 0.0)
        {
            if (observed[i] > 0.0)
            {
                std::ostringstream s;
                s << "cell " << i << " has expectation 0 but " << observed[i] << " samples";
                r.message = s.str();
                return r;
            }
            continue;
        }
        pooledObserved += observed[i];
        pooledExpected += expected[i];
        if (pooledExpected < 5.0)
            continue; // pool with the next cell
        const double d = pooledObserved - pooledExpected;
        r.statistic += d * d / pooledExpected;
        ++cells;
        pooledObserved = pooledExpected = 0.0;
    }
    if (pooledExpected > 0.0)
    {
        const double d = pooledObserved - pooledExpected;
        r.statistic += d * d / pooledExpected;
        ++cells;
    }
    r.degreesOfFreedom = cells - 1;
    if (r.degreesOfFreedom < 1)
    {
        r.message = "fewer than two cells after pooling";
        return r;
    }
    r.pValue = gammaQ(0.5 * r.degreesOfFreedom, 0.5 * r.statistic);
    const double threshold = 1.0 - std::pow(1.0 - alpha, 1.0 / tests);
    r.passed = std::isfinite(r.pValue) && r.pValue >= threshold;
    std::ostringstream s;
    s << "chi2 = " << r.statistic << " with " << r.degreesOfFreedom << " dof, p = " << r.pValue
      << " (reject below " << threshold << ")";
    r.message = s.str();
    return r;
}

} // namespace rt::test
