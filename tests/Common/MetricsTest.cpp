// Image/Metrics.h: the error metrics against a reference (research notes §5), checked on images whose errors
// are known exactly (dyadic values: every difference and square is exact in float and double).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "Error.h"
#include "Image/Metrics.h"

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
    EXPECT_DOUBLE_EQ(m.relMse, rel);
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

TEST(Metrics, SizeMismatchIsAUsageError)
{
    EXPECT_THROW(compareImages(Image(4, 3), Image(3, 4)), UsageError);
    EXPECT_THROW(compareImages(Image(4, 3), Image(4, 2)), UsageError);
}
} // namespace
} // namespace rt
