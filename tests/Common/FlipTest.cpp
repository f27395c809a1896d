// Image/Flip.h: FLIP's pieces against values worked by hand, its properties (no error between identical
// images, more error with more noise, HDR-FLIP's indifference to the overall exposure), and its means on a
// real image pair against NVIDIA's reference implementation (tests/Data/flip/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include <stb_image.h>

#include "Error.h"
#include "Image/Flip.h"
#include "Image/ImageIO.h"
#include "Random/Pcg.h"

// The folder of the test pair; by default tests/Data/flip beside this file's folder.
#ifndef RT_FLIP_TEST_DATA
#define RT_FLIP_TEST_DATA ""
#endif

namespace rt
{
namespace
{
std::filesystem::path dataDir()
{
    const std::string configured = RT_FLIP_TEST_DATA;
    if (!configured.empty())
        return configured;
    return std::filesystem::path(__FILE__).parent_path().parent_path() / "Data" / "flip";
}

/// An 8-bit sRGB PNG decoded to the linear values a display shows (what LDR-FLIP compares).
Image loadPng(const std::string& name)
{
    const std::filesystem::path path = dataDir() / name;
    int w = 0, h = 0, channels = 0;
    stbi_uc* bytes = stbi_load(path.string().c_str(), &w, &h, &channels, 3);
    if (!bytes)
    {
        ADD_FAILURE() << "cannot read " << path;
        return Image();
    }
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        image.data()[i] = vec3(srgb8ToLinear(bytes[3 * i]), srgb8ToLinear(bytes[3 * i + 1]),
                               srgb8ToLinear(bytes[3 * i + 2]));
    stbi_image_free(bytes);
    return image;
}

/// An HDR image made from a display image: pixel (x, y) scaled by 2^k, k = floor(10 (x + y) / (w + h)) - 3,
/// in diagonal bands from 1/8 to 64. Scaling by a power of two is exact, so every implementation gets the
/// same floats.
Image bandedHdr(const Image& display)
{
    Image hdr(display.width(), display.height());
    for (int y = 0; y < display.height(); ++y)
        for (int x = 0; x < display.width(); ++x)
        {
            const int k = (x + y) * 10 / (display.width() + display.height()) - 3;
            const vec3 v = display.at(x, y);
            hdr.at(x, y) = vec3(std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k));
        }
    return hdr;
}

/// A smooth synthetic 64 x 48 image with edges: colour ramps and a bright disc.
Image syntheticImage()
{
    Image image(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
        {
            const float dx = float(x) - 40.0f, dy = float(y) - 20.0f;
            const bool disc = dx * dx + dy * dy < 100.0f;
            image.at(x, y) = disc ? vec3(0.9f, 0.8f, 0.2f) : vec3(float(x) / 63.0f, float(y) / 47.0f, 0.3f);
        }
    return image;
}

/// One standard normal value per channel of every pixel, from a seeded PCG stream (Box-Muller).
std::vector<vec3> normalField(std::size_t count, std::uint32_t seed)
{
    SceneRandom random(seed);
    std::vector<vec3> field(count);
    for (vec3& v : field)
        for (int c = 0; c < 3; ++c)
        {
            const float u1 = std::max(random.uniform(), 1e-7f);
            const float u2 = random.uniform();
            v[c] = std::sqrt(-2.0f * std::log(u1)) * std::cos(2.0f * kPi * u2);
        }
    return field;
}

void expectVecNear(const vec3& actual, const vec3& expected, float tolerance)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// ---- The pieces, against values worked by hand ----

TEST(FlipColor, ReferenceWhiteIsD65)
{
    // D65 at (x, y) = (0.31271, 0.32902): X = x / y = 0.9504285, Z = (1 - x - y) / y = 1.0889004.
    expectVecNear(flip::referenceWhite(), vec3(0.9504285f, 1.0f, 1.0889004f), 1e-6f);
    // The luminance row of the matrix is the Rec. 709 luminance weights to four digits.
    const vec3 lumRow(flip::linearRgbToXyz(vec3(1, 0, 0)).y, flip::linearRgbToXyz(vec3(0, 1, 0)).y,
                      flip::linearRgbToXyz(vec3(0, 0, 1)).y);
    expectVecNear(lumRow, vec3(0.2126f, 0.7152f, 0.0722f), 1e-4f);
}

TEST(FlipColor, WhiteAndBlackInYCxCz)
{
    // Y = 116 Y/Yn - 16: white 100, black -16, and no chroma for either.
    expectVecNear(flip::xyzToYCxCz(flip::linearRgbToXyz(vec3(1.0f))), vec3(100.0f, 0.0f, 0.0f), 1e-4f);
    expectVecNear(flip::xyzToYCxCz(flip::linearRgbToXyz(vec3(0.0f))), vec3(-16.0f, 0.0f, 0.0f), 1e-6f);
    // Grey 0.25 is linear in YCxCz (unlike CIELab): Y = 116 * 0.25 - 16 = 13.
    expectVecNear(flip::xyzToYCxCz(flip::linearRgbToXyz(vec3(0.25f))), vec3(13.0f, 0.0f, 0.0f), 1e-4f);
}

TEST(FlipColor, RoundTrips)
{
    for (const vec3 rgb : {vec3(0.2f, 0.5f, 0.9f), vec3(1.0f, 0.0f, 0.0f), vec3(0.01f, 0.7f, 0.3f)})
    {
        expectVecNear(flip::xyzToLinearRgb(flip::linearRgbToXyz(rgb)), rgb, 1e-6f);
        const vec3 xyz = flip::linearRgbToXyz(rgb);
        expectVecNear(flip::yCxCzToXyz(flip::xyzToYCxCz(xyz)), xyz, 1e-6f);
    }
}

TEST(FlipColor, LabOfGreys)
{
    // L = 116 (Y/Yn)^(1/3) - 16 above (6/29)^3, 116 (Y/Yn) / (3 (6/29)^2) + 16 - 16 below.
    expectVecNear(flip::xyzToLab(flip::linearRgbToXyz(vec3(1.0f))), vec3(100.0f, 0.0f, 0.0f), 1e-4f);
    expectVecNear(flip::xyzToLab(flip::linearRgbToXyz(vec3(0.125f))), vec3(42.0f, 0.0f, 0.0f),
                  1e-3f); // 116/2-16
    // 0.001 < (6/29)^3 = 0.008856: L = 116 * 0.001 * 841 / 108 = 0.903296.
    expectVecNear(flip::xyzToLab(flip::linearRgbToXyz(vec3(0.001f))), vec3(0.903296f, 0.0f, 0.0f), 1e-4f);
}

TEST(FlipColor, HuntAndHyab)
{
    expectVecNear(flip::huntAdjust(vec3(50.0f, 20.0f, -10.0f)), vec3(50.0f, 10.0f, -5.0f), 1e-6f);
    // |50 - 40| + ||(10, -5) - (13, -1)|| = 10 + 5.
    EXPECT_FLOAT_EQ(flip::hyab(vec3(50.0f, 10.0f, -5.0f), vec3(40.0f, 13.0f, -1.0f)), 15.0f);
    EXPECT_FLOAT_EQ(flip::hyab(vec3(30.0f, 1.0f, 2.0f), vec3(30.0f, 1.0f, 2.0f)), 0.0f);
}

TEST(FlipColor, MaxDifferenceIsGreenToBlue)
{
    // Worked from the matrix in double precision (a separate script): green Lab (87.7362, -86.1787, 83.1826),
    // Hunt (87.7362, -75.6099, 72.9812); blue Lab (32.2982, 79.1936, -107.8586), Hunt (32.2982, 25.5781,
    // -34.8364). HyAB = 55.4380 + sqrt(101.1880^2 + 107.8176^2) = 55.4380 + 147.8636 = 203.3017, and
    // 203.3017^0.7 = 41.2761.
    EXPECT_NEAR(flip::maxColorDifference(), 41.2761, 1e-3);
}

TEST(FlipColor, RemappingHitsItsKnots)
{
    const double cmax = flip::maxColorDifference();
    // A HyAB distance whose qc-th power is pc cmax maps to pt; cmax itself to 1; none to 0.
    EXPECT_NEAR(flip::remapColorDifference(float(std::pow(flip::kPc * cmax, 1.0 / flip::kQc))), flip::kPt,
                1e-5);
    EXPECT_NEAR(flip::remapColorDifference(float(std::pow(cmax, 1.0 / flip::kQc))), 1.0, 1e-5);
    EXPECT_EQ(flip::remapColorDifference(0.0f), 0.0f);
    // Halfway up the first segment: d = pc cmax / 2 gives pt / 2.
    EXPECT_NEAR(flip::remapColorDifference(float(std::pow(0.5 * flip::kPc * cmax, 1.0 / flip::kQc))),
                0.5 * flip::kPt, 1e-5);
}

TEST(FlipFilters, SpatialFiltersSumToOne)
{
    const flip::SpatialFilters f = flip::spatialFilters(kFlipDefaultPixelsPerDegree);
    // ceil(3 sqrt(0.04 / (2 pi^2)) 67.0206) = ceil(3 * 0.0450158 * 67.0206) = ceil(9.0510) = 10.
    EXPECT_EQ(f.radius, 10);
    for (const std::vector<float>* k : {&f.achromatic, &f.redGreen, &f.blueYellow1, &f.blueYellow2})
        ASSERT_EQ(k->size(), 21u);
    const auto sum = [](const std::vector<float>& k) { return std::accumulate(k.begin(), k.end(), 0.0); };
    // Each 2D filter is the outer product of its 1D factors (a sum of two for blue-yellow).
    EXPECT_NEAR(sum(f.achromatic) * sum(f.achromatic), 1.0, 1e-6);
    EXPECT_NEAR(sum(f.redGreen) * sum(f.redGreen), 1.0, 1e-6);
    EXPECT_NEAR(sum(f.blueYellow1) * sum(f.blueYellow1) + sum(f.blueYellow2) * sum(f.blueYellow2), 1.0, 1e-6);
    for (int i = 0; i < 10; ++i)
        EXPECT_EQ(f.blueYellow1[i], f.blueYellow1[20 - i]);
    // The achromatic filter is a Gaussian of standard deviation sqrt(b1 / (2 pi^2)) = 0.015430 degrees
    // = 1.0342 pixels: its tap at 1 pixel over its centre tap is e^(-1 / (2 * 1.0342^2)) = 0.6266.
    EXPECT_NEAR(f.achromatic[11] / f.achromatic[10], std::exp(-kPi * kPi / (0.0047 * 67.0206 * 67.0206)),
                1e-5);
    EXPECT_NEAR(f.achromatic[11] / f.achromatic[10], 0.6266, 1e-3);
    // At 30 pixels per degree: ceil(3 * 0.0450158 * 30) = ceil(4.051) = 5.
    EXPECT_EQ(flip::spatialFilters(30.0).radius, 5);
}

TEST(FlipFilters, FeatureFiltersAreNormalised)
{
    const flip::FeatureFilters f = flip::featureFilters(kFlipDefaultPixelsPerDegree);
    // sigma = 0.5 * 0.082 * 67.0206 = 2.7478 pixels; radius ceil(3 sigma) = ceil(8.2435) = 9.
    EXPECT_EQ(f.radius, 9);
    ASSERT_EQ(f.gaussian.size(), 19u);
    double g = 0.0, dPos = 0.0, dNeg = 0.0, ddPos = 0.0, ddNeg = 0.0;
    for (int i = 0; i < 19; ++i)
    {
        g += f.gaussian[i];
        (f.firstDerivative[i] > 0.0f ? dPos : dNeg) += f.firstDerivative[i];
        (f.secondDerivative[i] > 0.0f ? ddPos : ddNeg) += f.secondDerivative[i];
        EXPECT_EQ(f.firstDerivative[i], -f.firstDerivative[18 - i]);
        EXPECT_EQ(f.secondDerivative[i], f.secondDerivative[18 - i]);
    }
    EXPECT_NEAR(g, 1.0, 1e-6);
    EXPECT_NEAR(dPos, 1.0, 1e-6);
    EXPECT_NEAR(dNeg, -1.0, 1e-6);
    EXPECT_NEAR(ddPos, 1.0, 1e-6);
    EXPECT_NEAR(ddNeg, -1.0, 1e-6);
    // The first derivative is positive left of the centre (it is -x g(x)); the second negative at the centre.
    EXPECT_GT(f.firstDerivative[8], 0.0f);
    EXPECT_LT(f.secondDerivative[9], 0.0f);
}

TEST(FlipToneMap, AcesFitAndTheExposureRule)
{
    EXPECT_EQ(flipToneMap(0.0f), 0.0f);
    // f(0.6 x) = 0.85: with u = 0.6 x, (2.51 - 0.85 * 2.43) u^2 + (0.03 - 0.85 * 0.59) u - 0.85 * 0.14 = 0,
    // u = (0.4715 + sqrt(0.4715^2 + 4 * 0.4445 * 0.119)) / (2 * 0.4445) = 1.271323, x = 2.118872.
    EXPECT_NEAR(flipToneMap(2.118872f), 0.85f, 1e-5f);
    // One grey level everywhere (luminance 1): start = stop = log2(2.118872 / 1), count max(2, 0) = 2.
    Image grey(4, 4);
    for (vec3& p : grey.pixels())
        p = vec3(1.0f);
    const FlipExposures e = flipAutomaticExposures(grey);
    EXPECT_NEAR(e.start, std::log2(2.118872), 1e-5);
    EXPECT_NEAR(e.stop, std::log2(2.118872), 1e-5);
    EXPECT_EQ(e.count, 2);
    // Grey luminances 1, 2, 4, ... 2^14 and 3 * 2^14, in any order: the maximum 3 * 2^14, the median (element
    // 16 / 2 = 8 of the sorted ones) 2^8; start = log2(x_max / 3) - 14, stop = log2(x_max) - 8, so
    // stop - start = 6 + log2(3) = 7.585 and count = 8.
    Image ramp(4, 4);
    for (int i = 0; i < 15; ++i)
        ramp.pixels()[std::size_t(14 - i)] = vec3(std::ldexp(1.0f, i));
    ramp.pixels()[15] = vec3(3.0f * 16384.0f);
    const FlipExposures r = flipAutomaticExposures(ramp);
    EXPECT_NEAR(r.start, std::log2(2.118872 / 3.0) - 14.0, 1e-5);
    EXPECT_NEAR(r.stop, std::log2(2.118872) - 8.0, 1e-5);
    EXPECT_EQ(r.count, 8);
    EXPECT_NEAR(r.at(0), r.start, 1e-12);
    EXPECT_NEAR(r.at(7), r.stop, 1e-12);
    EXPECT_NEAR(r.at(1) - r.at(0), (r.stop - r.start) / 7.0, 1e-12);
}

// ---- Properties ----

TEST(Flip, IdenticalImagesHaveNoError)
{
    const Image image = loadPng("reference.png");
    ASSERT_FALSE(image.empty());
    const FlipErrorMap ldr = ldrFlip(image, image);
    ASSERT_EQ(ldr.values.size(), image.pixelCount());
    for (float v : ldr.values)
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(ldr.mean(), 0.0);
    const HdrFlipResult hdr = hdrFlip(bandedHdr(image), bandedHdr(image));
    for (float v : hdr.error.values)
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(meanLdrFlip(syntheticImage(), syntheticImage()), 0.0);
}

TEST(Flip, ErrorIsInUnitInterval)
{
    // Black against white, two flat fields: no features, so every pixel is the remapped colour difference.
    // HyAB = |100 - 0| = 100 and 100^0.7 = 25.119 is above pc cmax = 16.510, so the error is
    // 0.95 + 0.05 (25.119 - 16.510) / (41.276 - 16.510) = 0.9674.
    Image black(16, 16), white(16, 16);
    for (vec3& p : white.pixels())
        p = vec3(1.0f);
    const FlipErrorMap m = ldrFlip(black, white);
    const double d = std::pow(100.0, 0.7), cmax = flip::maxColorDifference(), knee = 0.4 * cmax;
    for (float v : m.values)
        ASSERT_NEAR(v, 0.95 + 0.05 * (d - knee) / (cmax - knee), 1e-4);
    // Out-of-range and NaN display values are clamped (NaN to 0), so the map stays in [0, 1].
    Image wild = syntheticImage();
    wild.at(3, 3) = vec3(std::nanf(""), 5.0f, -2.0f);
    for (float v : ldrFlip(wild, syntheticImage()).values)
    {
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
}

TEST(Flip, MoreNoiseMoreError)
{
    // One noise field, scaled up: the mean FLIP must grow with its standard deviation, LDR and HDR alike.
    const Image reference = loadPng("reference.png");
    ASSERT_FALSE(reference.empty());
    const std::vector<vec3> noise = normalField(reference.pixelCount(), 2024u);
    const Image hdrReference = bandedHdr(reference);
    double previousLdr = 0.0, previousHdr = 0.0;
    for (float sigma : {0.01f, 0.03f, 0.1f, 0.3f})
    {
        Image ldrTest = reference, hdrTest = hdrReference;
        for (std::size_t i = 0; i < reference.pixelCount(); ++i)
        {
            ldrTest.data()[i] = glm::clamp(reference.data()[i] + sigma * noise[i], 0.0f, 1.0f);
            hdrTest.data()[i] = glm::max(hdrReference.data()[i] * (1.0f + sigma * noise[i]), 0.0f);
        }
        const double ldr = meanLdrFlip(ldrTest, reference);
        const double hdr = meanHdrFlip(hdrTest, hdrReference);
        EXPECT_GT(ldr, previousLdr) << "sigma " << sigma;
        EXPECT_GT(hdr, previousHdr) << "sigma " << sigma;
        previousLdr = ldr;
        previousHdr = hdr;
    }
}

TEST(Flip, HdrIgnoresOverallExposure)
{
    // The automatic exposures follow the reference, so scaling both images by 2^5 shifts them by -5 stops and
    // leaves the tone-mapped pairs, and the map, as they were.
    const Image reference = bandedHdr(loadPng("reference.png"));
    const Image test = bandedHdr(loadPng("test.png"));
    ASSERT_FALSE(reference.empty());
    Image brighterRef = reference, brighterTest = test;
    for (vec3& p : brighterRef.pixels())
        p *= 32.0f;
    for (vec3& p : brighterTest.pixels())
        p *= 32.0f;
    const HdrFlipResult a = hdrFlip(test, reference);
    const HdrFlipResult b = hdrFlip(brighterTest, brighterRef);
    EXPECT_NEAR(b.exposures.start, a.exposures.start - 5.0, 1e-9);
    EXPECT_NEAR(b.exposures.stop, a.exposures.stop - 5.0, 1e-9);
    EXPECT_EQ(a.exposures.count, b.exposures.count);
    EXPECT_NEAR(a.error.mean(), b.error.mean(), 1e-6);
    // And HDR-FLIP is the maximum over its exposures: never below LDR-FLIP at its start exposure alone.
    HdrFlipOptions single;
    single.startExposure = single.stopExposure = a.exposures.start;
    single.exposureCount = 1;
    const HdrFlipResult one = hdrFlip(test, reference, single);
    for (std::size_t i = 0; i < one.error.values.size(); ++i)
        ASSERT_LE(one.error.values[i], a.error.values[i]);
    EXPECT_LT(one.error.mean(), a.error.mean());
}

// ---- Against NVIDIA's reference implementation ----

// Values from NVlabs/flip's FLIP.h (commit 1eb247c, v1.6) on the same inputs (tests/Data/flip/README.md):
// FLIP::evaluate on the linear images, the mean taken in double over its map. Ours differ by about 1e-8 in
// the mean and 1e-5 in single pixels (float arithmetic in a different order).
TEST(FlipReference, LdrMeanMatchesNvidia)
{
    const Image reference = loadPng("reference.png");
    const Image test = loadPng("test.png");
    ASSERT_EQ(reference.width(), 255);
    ASSERT_EQ(reference.height(), 191);
    const FlipErrorMap m = ldrFlip(test, reference);
    EXPECT_NEAR(m.mean(), 0.098744567, 1e-6);
    EXPECT_NEAR(m.at(0, 0), 0.0566897, 1e-4);
    EXPECT_NEAR(m.at(100, 50), 0.1519451, 1e-4);
    EXPECT_NEAR(m.at(200, 150), 0.0619892, 1e-4);
    EXPECT_NEAR(m.at(254, 190), 0.0917710, 1e-4);
    // 30 pixels per degree: smaller filters, more visible error.
    const FlipErrorMap m30 = ldrFlip(test, reference, FlipOptions{30.0});
    EXPECT_NEAR(m30.mean(), 0.136530995, 1e-6);
    EXPECT_NEAR(m30.at(100, 50), 0.2314902, 1e-4);
    EXPECT_NEAR(m30.at(200, 150), 0.1447817, 1e-4);
}

TEST(FlipReference, HdrMeanMatchesNvidia)
{
    const Image reference = bandedHdr(loadPng("reference.png"));
    const Image test = bandedHdr(loadPng("test.png"));
    const HdrFlipResult r = hdrFlip(test, reference);
    EXPECT_NEAR(r.exposures.start, -3.569060564, 1e-5); // NVIDIA computes it in float
    EXPECT_NEAR(r.exposures.stop, 3.858612537, 1e-5);
    EXPECT_EQ(r.exposures.count, 8);
    EXPECT_NEAR(r.error.mean(), 0.213362250, 1e-6);
    EXPECT_NEAR(r.error.at(0, 0), 0.0182987, 1e-4);
    EXPECT_NEAR(r.error.at(100, 50), 0.1649427, 1e-4);
    EXPECT_NEAR(r.error.at(200, 150), 0.1505149, 1e-4);
    EXPECT_NEAR(r.error.at(254, 190), 0.2142962, 1e-4);
}

// ---- Errors ----

TEST(Flip, RejectsBadArguments)
{
    const Image a(8, 8), b(8, 9);
    EXPECT_THROW(ldrFlip(a, b), UsageError);
    EXPECT_THROW(hdrFlip(a, b), UsageError);
    EXPECT_THROW(ldrFlip(Image(), Image()), UsageError);
    EXPECT_THROW(ldrFlip(a, a, FlipOptions{0.0}), UsageError);
    // An all-black reference has no median luminance to expose for...
    EXPECT_THROW(flipAutomaticExposures(a), UsageError);
    EXPECT_THROW(hdrFlip(a, a), UsageError);
    // ... unless the caller gives the exposures; then black against black is no error.
    HdrFlipOptions given;
    given.startExposure = -2.0;
    given.stopExposure = 2.0;
    EXPECT_EQ(meanHdrFlip(a, a, given), 0.0);
    given.startExposure = 3.0;
    EXPECT_THROW(hdrFlip(a, a, given), UsageError);
}
} // namespace
} // namespace rt
