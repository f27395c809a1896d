#include "Compare/Confidence.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt::compare
{
namespace
{
/// The continued fraction of I_x(a, b) by the modified Lentz method (Numerical Recipes §6.4, betacf).
double betaContinuedFraction(double x, double a, double b)
{
    constexpr double tiny = 1e-300;
    const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
    double c = 1.0;
    double d = 1.0 - qab * x / qap;
    d = 1.0 / (std::fabs(d) < tiny ? tiny : d);
    double h = d;
    for (int m = 1; m <= 300; ++m)
    {
        const double m2 = 2.0 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        d = 1.0 / (std::fabs(d) < tiny ? tiny : d);
        c = 1.0 + aa / c;
        c = std::fabs(c) < tiny ? tiny : c;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        d = 1.0 / (std::fabs(d) < tiny ? tiny : d);
        c = 1.0 + aa / c;
        c = std::fabs(c) < tiny ? tiny : c;
        const double step = d * c;
        h *= step;
        if (std::fabs(step - 1.0) < 1e-15)
            break;
    }
    return h;
}

/// P(T <= t) for Student's t with nu degrees of freedom.
double studentTCdf(double t, double nu)
{
    const double tail = 0.5 * incompleteBeta(nu / (nu + t * t), 0.5 * nu, 0.5);
    return t >= 0.0 ? 1.0 - tail : tail;
}

struct Moments
{
    double mean = 0.0;
    double variance = 0.0; // of one value (n - 1 in the denominator); 0 for one value
    int count = 0;
};

Moments momentsOf(const std::vector<double>& values)
{
    Moments m;
    m.count = static_cast<int>(values.size());
    if (m.count == 0)
        return m;
    for (const double v : values)
        m.mean += v;
    m.mean /= m.count;
    if (m.count > 1)
    {
        for (const double v : values)
            m.variance += (v - m.mean) * (v - m.mean);
        m.variance /= m.count - 1;
    }
    return m;
}
} // namespace

double incompleteBeta(double x, double a, double b)
{
    if (x <= 0.0)
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    const double front =
        std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
    // The continued fraction converges fast for x < (a + 1) / (a + b + 2); the symmetry I_x(a, b) =
    // 1 - I_{1-x}(b, a) covers the rest.
    if (x < (a + 1.0) / (a + b + 2.0))
        return front * betaContinuedFraction(x, a, b) / a;
    return 1.0 - front * betaContinuedFraction(1.0 - x, b, a) / b;
}

double studentTQuantile(double p, int degreesOfFreedom)
{
    const double nu = std::max(1, degreesOfFreedom);
    if (p == 0.5)
        return 0.0;
    if (p < 0.5)
        return -studentTQuantile(1.0 - p, degreesOfFreedom);
    double lo = 0.0, hi = 1.0;
    while (studentTCdf(hi, nu) < p && hi < 1e12)
        hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (studentTCdf(mid, nu) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

Interval meanInterval(const std::vector<double>& values, double level)
{
    const Moments m = momentsOf(values);
    Interval out{m.mean, m.mean, m.mean, m.count};
    if (m.count < 2)
        return out;
    const double half = studentTQuantile(0.5 + 0.5 * level, m.count - 1) * std::sqrt(m.variance / m.count);
    out.lo = m.mean - half;
    out.hi = m.mean + half;
    return out;
}

Interval ratioInterval(const std::vector<double>& numerator, const std::vector<double>& denominator, double level)
{
    const Moments a = momentsOf(numerator);
    const Moments b = momentsOf(denominator);
    if (a.count == 0 || b.count == 0 || !(a.mean > 0.0) || !(b.mean > 0.0))
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                std::numeric_limits<double>::quiet_NaN(), 0};
    const double ratio = a.mean / b.mean;
    const int count = std::min(a.count, b.count);
    Interval out{ratio, ratio, ratio, count};
    if (count < 2)
        return out;
    const double logSd = std::sqrt(a.variance / (a.count * a.mean * a.mean) + b.variance / (b.count * b.mean * b.mean));
    const double half = studentTQuantile(0.5 + 0.5 * level, count - 1) * logSd;
    out.lo = ratio * std::exp(-half);
    out.hi = ratio * std::exp(half);
    return out;
}
} // namespace rt::compare
