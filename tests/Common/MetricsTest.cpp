// Image/Metrics.h: the error metrics against a reference (research notes §5), checked on images whose errors
// are known exactly (dyadic values: every difference and square is exact in float and double).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "Error.h"
#include "Image/Metrics.h"
#include "Random/Pcg.h"

namespace rt
{
namespace
{
/// A 4 x 3 reference with a different value in every channel, all multiples of 1/8.
Image reference()
{
    Image r(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            r.at(x, y) = vec3(0.125f * float(x + 4 * y), 0.25f * float(y), 2.0f - 0.125f * float(x));
    return r;
}

TEST(Metrics, IdenticalImagesHaveNoError)
{
    const ErrorMetrics m = compareImages(reference(), reference());
    EXPECT_EQ(m.mse, 0.0);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_EQ(m.relMse, 0.0);
    EXPECT_EQ(m.psnr, std::numeric_limits<double>::infinity());
}

TEST(Metrics, ConstantOffsetGivesItsSquare)
{
    // test = reference + delta everywhere: mse = delta^2, rmse = delta, psnr = 10 log10(1 / delta^2), and
    // relMse = mean over pixels and channels of delta^2 / (R^2 + 0.01), computed here from the definition.
    const double delta = 0.0625;
    const Image r = reference();
    Image t = r;
    for (vec3& p : t.pixels())
        p += vec3(float(delta));
    double rel = 0.0;
    for (const vec3& p : r.pixels())
        for (int c = 0; c < 3; ++c)
            rel += delta * delta / (double(p[c]) * p[c] + 1e-2);
    rel /= 3.0 * double(r.pixelCount());

    const ErrorMetrics m = compareImages(t, r);
    EXPECT_DOUBLE_EQ(m.mse, delta * delta);
    EXPECT_DOUBLE_EQ(m.rmse, delta);
    EXPECT_NEAR(m.relMse, rel, 1e-14 * rel); // summed per pixel first: the order of the sum differs
    EXPECT_NEAR(m.psnr, 10.0 * std::log10(1.0 / (delta * delta)), 1e-12);
    EXPECT_EQ(kRelMseEpsilon, 1e-2);
    // The relative error divides by the reference, not the test image: swapping them changes it.
    EXPECT_NE(compareImages(r, t).relMse, m.relMse);
    EXPECT_DOUBLE_EQ(compareImages(r, t).mse, m.mse);
}

TEST(Metrics, RelMseUsesTheGivenEpsilon)
{
    // A single pixel: R = 0.5, test 1.0, epsilon 0.75: (0.5)^2 / (0.25 + 0.75) = 0.25 exactly.
    Image r(1, 1), t(1, 1);
    r.at(0, 0) = vec3(0.5f);
    t.at(0, 0) = vec3(1.0f);
    EXPECT_DOUBLE_EQ(compareImages(t, r, 0.75).relMse, 0.25);
}

TEST(Metrics, MapeIsTheMeanAbsoluteRelativeError)
{
    // Two pixels: R = (0.5, 0, 1), (2, 0.25, 0.75); test adds (0.25, -0.5, 0), (-1, 0, 0.25). MAPE, by hand:
    // (0.25/0.51 + 0.5/0.01 + 0 + 1/2.01 + 0 + 0.25/0.76) / 6.
    Image r(2, 1), t(2, 1);
    r.at(0, 0) = vec3(0.5f, 0.0f, 1.0f);
    r.at(1, 0) = vec3(2.0f, 0.25f, 0.75f);
    t.at(0, 0) = r.at(0, 0) + vec3(0.25f, -0.5f, 0.0f);
    t.at(1, 0) = r.at(1, 0) + vec3(-1.0f, 0.0f, 0.25f);
    const double expected = (0.25 / 0.51 + 0.5 / 0.01 + 1.0 / 2.01 + 0.25 / 0.76) / 6.0;
    EXPECT_NEAR(compareImages(t, r).mape, expected, 1e-12);
    EXPECT_EQ(compareImages(r, r).mape, 0.0);
}

TEST(Metrics, TrimmedRelMseDropsTheWorstThousandth)
{
    // 2000 pixels with relMSE 0 but for two fireflies and one small error: 0.1 % of 2000 is 2 pixels, so both
    // fireflies go and the small error stays, over the 1998 pixels kept.
    Image r(50, 40), t(50, 40);
    for (vec3& p : r.pixels())
        p = vec3(0.5f);
    t = r;
    t.at(3, 4) = vec3(100.0f);
    t.at(30, 20) = vec3(50.0f, 0.5f, 0.5f);
    t.at(7, 7) = vec3(0.75f, 0.5f, 0.5f); // relMSE of the pixel: 0.0625 / 0.26 over its 3 channels
    const ErrorMetrics m = compareImages(t, r);
    EXPECT_NEAR(m.trimmedRelMse, (0.0625 / 0.26) / (3.0 * 1998.0), 1e-15);
    EXPECT_GT(m.relMse, 1000.0 * m.trimmedRelMse); // the untrimmed one is the fireflies'
    // Below 1000 pixels nothing is trimmed.
    Image small(10, 10), smallTest(10, 10);
    smallTest.at(2, 3) = vec3(1.0f);
    EXPECT_DOUBLE_EQ(compareImages(smallTest, small).trimmedRelMse, compareImages(smallTest, small).relMse);
}

TEST(Metrics, EfficiencyPowersMakeEveryMetricScaleLikeVariance)
{
    EXPECT_EQ(efficiencyPower(ErrorMetric::RelMse), 1);
    EXPECT_EQ(efficiencyPower(ErrorMetric::TrimmedRelMse), 1);
    EXPECT_EQ(efficiencyPower(ErrorMetric::Mape), 2);
    EXPECT_EQ(efficiencyPower(ErrorMetric::Flip), 2);
    // Independent uniform noise of width s on a constant image: relMSE ~ s^2, MAPE ~ s, so
    // relMSE / MAPE^2 stays put when s is quartered (4x the samples would halve s: 16x the samples here).
    Rng rng(pcgHash(7));
    Image r(200, 200), a(200, 200), b(200, 200);
    for (std::size_t i = 0; i < r.pixelCount(); ++i)
    {
        r.data()[i] = vec3(1.0f);
        const vec3 noise(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
        a.data()[i] = vec3(1.0f) + 0.2f * noise;
        b.data()[i] = vec3(1.0f) + 0.05f * noise;
    }
    const ErrorMetrics ma = compareImages(a, r), mb = compareImages(b, r);
    EXPECT_NEAR(ma.relMse / (ma.mape * ma.mape), mb.relMse / (mb.mape * mb.mape), 1e-4);
    EXPECT_NEAR(ma.relMse / mb.relMse, 16.0, 1e-3);
}

TEST(Metrics, SizeMismatchIsAUsageError)
{
    EXPECT_THROW(compareImages(Image(4, 3), Image(3, 4)), UsageError);
    EXPECT_THROW(compareImages(Image(4, 3), Image(4, 2)), UsageError);
    EXPECT_THROW(combineReferenceHalves(Image(4, 3), Image(4, 2)), UsageError);
}

TEST(Metrics, ReferenceHalvesGiveTheirMeanAndItsOwnError)
{
    // One pixel: halves 1 and 0.5, mean 0.75, epsilon 0.4375: (0.5)^2 / 4 / (0.5625 + 0.4375) = 0.0625.
    Image a(1, 1), b(1, 1);
    a.at(0, 0) = vec3(1.0f);
    b.at(0, 0) = vec3(0.5f);
    const TwoHalfReference r = combineReferenceHalves(a, b, 0.4375);
    EXPECT_EQ(r.mean.at(0, 0), vec3(0.75f));
    EXPECT_DOUBLE_EQ(r.ownRelMse, 0.0625);
}

/// Normal deviates by Box-Muller from the generator's uniforms.
double normal(Rng& rng)
{
    const double u1 = 1.0 - double(rng.nextFloat()), u2 = rng.nextFloat();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

TEST(Metrics, ReferenceOwnErrorIsWhatItAddsToATestsRelMse)
{
    // Statistical, fixed seed: a truth T (0.05-2 per channel), two halves and a test image of independent
    // Gaussian noise of standard deviation 0.05 T (a reference's few percent; the estimate holds to first order
    // in the noise over the normalisation). The estimate from the halves must match the mean's actual squared
    // error against T, and a test's relMSE against the mean must be its own error plus that estimate, each
    // within 3 % over 300,000 channels (the sums' relative standard deviation is under 0.5 %; a factor 1/2
    // instead of 1/4 in the estimate is off by 100 % in the first and 33 % in the second).
    const int width = 500, height = 200;
    Image truth(width, height), a(width, height), b(width, height), test(width, height);
    Rng rng(2026);
    for (std::size_t i = 0; i < truth.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
        {
            const double t = 0.05 + 1.95 * double(rng.nextFloat());
            truth.data()[i][c] = float(t);
            a.data()[i][c] = float(t + 0.05 * t * normal(rng));
            b.data()[i][c] = float(t + 0.05 * t * normal(rng));
            test.data()[i][c] = float(t + 0.05 * t * normal(rng));
        }
    const TwoHalfReference r = combineReferenceHalves(a, b);
    double meanError = 0.0, testError = 0.0;
    for (std::size_t i = 0; i < truth.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
        {
            const double m = r.mean.data()[i][c], t = truth.data()[i][c], x = test.data()[i][c];
            const double norm = m * m + kRelMseEpsilon;
            meanError += (m - t) * (m - t) / norm;
            testError += (x - t) * (x - t) / norm;
        }
    const double n = 3.0 * double(truth.pixelCount());
    meanError /= n;
    testError /= n;
    EXPECT_NEAR(r.ownRelMse / meanError, 1.0, 0.03) << r.ownRelMse << " estimated, " << meanError << " actual";
    const double measured = compareImages(test, r.mean).relMse;
    EXPECT_NEAR(measured / (testError + r.ownRelMse), 1.0, 0.03)
        << measured << " measured, " << testError << " of the test alone, " << r.ownRelMse << " of the reference";
}
} // namespace
} // namespace rt
