#include "Image/Flip.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
namespace flip
{
namespace
{
constexpr double kPiD = 3.14159265358979323846;

using Mat3d = std::array<std::array<double, 3>, 3>;

/// XYZ of chromaticity (x, y) at luminance Y = 1.
std::array<double, 3> xyzOfChromaticity(double x, double y)
{
    return {x / y, 1.0, (1.0 - x - y) / y};
}

Mat3d inverse(const Mat3d& m)
{
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3d r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            // Cofactor of m[j][i] (the adjugate is the transposed cofactor matrix).
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            r[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
        }
    return r;
}

/// The sRGB to XYZ matrix: columns are the primaries' XYZ (IEC 61966-2-1: R (0.64, 0.33), G (0.30, 0.60),
/// B (0.15, 0.06)), scaled so that RGB (1, 1, 1) is the D65 white. D65's chromaticity is CIE 15's five-digit
/// (0.31271, 0.32902), which NVIDIA's FLIP uses too; sRGB's four-digit (0.3127, 0.3290) moves FLIP's mean on
/// the test pair by about 1e-6 and single pixels by up to 2e-5 (FlipTest.cpp).
Mat3d computeRgbToXyz()
{
    const std::array<std::array<double, 3>, 3> primaries = {
        xyzOfChromaticity(0.64, 0.33), xyzOfChromaticity(0.30, 0.60), xyzOfChromaticity(0.15, 0.06)};
    const std::array<double, 3> white = xyzOfChromaticity(0.31271, 0.32902);
    Mat3d p{};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            p[row][col] = primaries[col][row];
    const Mat3d pInv = inverse(p);
    Mat3d m{};
    for (int col = 0; col < 3; ++col)
    {
        const double scale = pInv[col][0] * white[0] + pInv[col][1] * white[1] + pInv[col][2] * white[2];
        for (int row = 0; row < 3; ++row)
            m[row][col] = p[row][col] * scale;
    }
    return m;
}

struct ColorMatrices
{
    mat3 rgbToXyz; // glm: column-major, m[col][row]
    mat3 xyzToRgb;
    vec3 white; // rgbToXyz (1, 1, 1)
    vec3 invWhite;
};

const ColorMatrices& colorMatrices()
{
    static const ColorMatrices matrices = []
    {
        const Mat3d m = computeRgbToXyz();
        const Mat3d mInv = inverse(m);
        ColorMatrices c;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
            {
                c.rgbToXyz[col][row] = float(m[row][col]);
                c.xyzToRgb[col][row] = float(mInv[row][col]);
            }
        const double wx = m[0][0] + m[0][1] + m[0][2], wy = m[1][0] + m[1][1] + m[1][2],
                     wz = m[2][0] + m[2][1] + m[2][2];
        c.white = vec3(float(wx), float(wy), float(wz));
        c.invWhite = vec3(float(1.0 / wx), float(1.0 / wy), float(1.0 / wz));
        return c;
    }();
    return matrices;
}

/// The CIELab companding function f(t) of a white-relative coordinate.
float labF(float t)
{
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

/// One term of a CSF in the image plane, as a separable factor: sqrt(a sqrt(pi / b)) e^(-pi^2 x^2 / b), so
/// that the product of the factors along x and y is the 2D term a sqrt(pi / b) e^(-pi^2 (x^2 + y^2) / b).
double csfFactor(double xDegrees, double a, double b)
{
    return std::sqrt(a * std::sqrt(kPiD / b)) * std::exp(-kPiD * kPiD * xDegrees * xDegrees / b);
}
} // namespace

vec3 linearRgbToXyz(const vec3& rgb)
{
    return colorMatrices().rgbToXyz * rgb;
}
vec3 xyzToLinearRgb(const vec3& xyz)
{
    return colorMatrices().xyzToRgb * xyz;
}
vec3 referenceWhite()
{
    return colorMatrices().white;
}

vec3 xyzToYCxCz(const vec3& xyz)
{
    const vec3 n = xyz * colorMatrices().invWhite;
    return vec3(116.0f * n.y - 16.0f, 500.0f * (n.x - n.y), 200.0f * (n.y - n.z));
}

vec3 yCxCzToXyz(const vec3& yCxCz)
{
    const float y = (yCxCz.x + 16.0f) / 116.0f;
    const float x = y + yCxCz.y / 500.0f;
    const float z = y - yCxCz.z / 200.0f;
    return vec3(x, y, z) * colorMatrices().white;
}

vec3 xyzToLab(const vec3& xyz)
{
    const vec3 n = xyz * colorMatrices().invWhite;
    const float fx = labF(n.x), fy = labF(n.y), fz = labF(n.z);
    return vec3(116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz));
}

vec3 huntAdjust(const vec3& lab)
{
    return vec3(lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z);
}

float hyab(const vec3& lab1, const vec3& lab2)
{
    const float da = lab1.y - lab2.y, db = lab1.z - lab2.z;
    return std::abs(lab1.x - lab2.x) + std::sqrt(da * da + db * db);
}

double maxColorDifference()
{
    static const double cmax = []
    {
        const vec3 green = huntAdjust(xyzToLab(linearRgbToXyz(vec3(0.0f, 1.0f, 0.0f))));
        const vec3 blue = huntAdjust(xyzToLab(linearRgbToXyz(vec3(0.0f, 0.0f, 1.0f))));
        return std::pow(double(hyab(green, blue)), kQc);
    }();
    return cmax;
}

float remapColorDifference(float hyabDistance)
{
    const double cmax = maxColorDifference();
    const double knee = kPc * cmax;
    const double d = std::pow(double(hyabDistance), kQc);
    const double e = d < knee ? d * (kPt / knee) : kPt + (d - knee) / (cmax - knee) * (1.0 - kPt);
    return float(e);
}

SpatialFilters spatialFilters(double pixelsPerDegree)
{
    const double bMax = std::max({kCsfAchromatic.b1, kCsfAchromatic.b2, kCsfRedGreen.b1, kCsfRedGreen.b2,
                                  kCsfBlueYellow.b1, kCsfBlueYellow.b2});
    SpatialFilters f;
    f.radius = int(std::ceil(3.0 * std::sqrt(bMax / (2.0 * kPiD * kPiD)) * pixelsPerDegree));
    const int width = 2 * f.radius + 1;
    std::vector<double> a(width), rg(width), by1(width), by2(width);
    double sumA = 0.0, sumRg = 0.0, sumBy1 = 0.0, sumBy2 = 0.0;
    for (int i = 0; i < width; ++i)
    {
        const double x = double(i - f.radius) / pixelsPerDegree; // degrees
        // The achromatic and red-green filters have one term each (a2 = 0); their scale cancels in the
        // normalisation, so the 1D factor is just the term's Gaussian.
        a[i] = std::exp(-kPiD * kPiD * x * x / kCsfAchromatic.b1);
        rg[i] = std::exp(-kPiD * kPiD * x * x / kCsfRedGreen.b1);
        by1[i] = csfFactor(x, kCsfBlueYellow.a1, kCsfBlueYellow.b1);
        by2[i] = csfFactor(x, kCsfBlueYellow.a2, kCsfBlueYellow.b2);
        sumA += a[i];
        sumRg += rg[i];
        sumBy1 += by1[i];
        sumBy2 += by2[i];
    }
    // The 2D blue-yellow filter by1 x by1 + by2 x by2 sums to sumBy1^2 + sumBy2^2: dividing both 1D factors
    // by the square root of that makes it sum to 1.
    const double byNorm = std::sqrt(sumBy1 * sumBy1 + sumBy2 * sumBy2);
    for (int i = 0; i < width; ++i)
    {
        f.achromatic.push_back(float(a[i] / sumA));
        f.redGreen.push_back(float(rg[i] / sumRg));
        f.blueYellow1.push_back(float(by1[i] / byNorm));
        f.blueYellow2.push_back(float(by2[i] / byNorm));
    }
    return f;
}

FeatureFilters featureFilters(double pixelsPerDegree)
{
    const double sigma = 0.5 * kFeatureWidth * pixelsPerDegree; // pixels
    FeatureFilters f;
    f.radius = int(std::ceil(3.0 * sigma));
    const int width = 2 * f.radius + 1;
    std::vector<double> g(width), dg(width), ddg(width);
    double sumG = 0.0, dgPos = 0.0, dgNeg = 0.0, ddgPos = 0.0, ddgNeg = 0.0;
    for (int i = 0; i < width; ++i)
    {
        const double x = double(i - f.radius);
        g[i] = std::exp(-x * x / (2.0 * sigma * sigma));
        dg[i] = -x / (sigma * sigma) * g[i];
        ddg[i] = (x * x / (sigma * sigma) - 1.0) / (sigma * sigma) * g[i];
        sumG += g[i];
        (dg[i] > 0.0 ? dgPos : dgNeg) += dg[i];
        (ddg[i] > 0.0 ? ddgPos : ddgNeg) += ddg[i];
    }
    for (int i = 0; i < width; ++i)
    {
        f.gaussian.push_back(float(g[i] / sumG));
        f.firstDerivative.push_back(float(dg[i] > 0.0 ? dg[i] / dgPos : dg[i] / -dgNeg));
        f.secondDerivative.push_back(float(ddg[i] > 0.0 ? ddg[i] / ddgPos : ddg[i] / -ddgNeg));
    }
    return f;
}
} // namespace flip

namespace
{
/// One channel of an image, row-major.
using Plane = std::vector<float>;

/// Convolves every row with `kernel` (taps -r..r), repeating the edge pixels outside the image.
void convolveRows(const Plane& src, Plane& dst, int width, int height, const std::vector<float>& kernel)
{
    const int r = int(kernel.size()) / 2;
    dst.assign(src.size(), 0.0f);
    for (int y = 0; y < height; ++y)
    {
        const float* in = src.data() + std::size_t(y) * width;
        float* out = dst.data() + std::size_t(y) * width;
        for (int x = 0; x < width; ++x)
        {
            float sum = 0.0f;
            if (x >= r && x + r < width)
                for (int k = -r; k <= r; ++k)
                    sum += kernel[k + r] * in[x + k];
            else
                for (int k = -r; k <= r; ++k)
                    sum += kernel[k + r] * in[std::clamp(x + k, 0, width - 1)];
            out[x] = sum;
        }
    }
}

/// Convolves every column with `kernel`, repeating the edge rows outside the image; a row at a time, so that
/// the inner loop runs along contiguous memory.
void convolveColumns(const Plane& src, Plane& dst, int width, int height, const std::vector<float>& kernel)
{
    const int r = int(kernel.size()) / 2;
    dst.assign(src.size(), 0.0f);
    for (int y = 0; y < height; ++y)
    {
        float* out = dst.data() + std::size_t(y) * width;
        for (int k = -r; k <= r; ++k)
        {
            const float w = kernel[k + r];
            const float* in = src.data() + std::size_t(std::clamp(y + k, 0, height - 1)) * width;
            for (int x = 0; x < width; ++x)
                out[x] += w * in[x];
        }
    }
}

float clamp01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
} // NaN -> 0

/// The image in YCxCz, one plane a channel, after clamping its linear RGB to [0, 1].
std::array<Plane, 3> toYCxCz(const Image& image)
{
    std::array<Plane, 3> planes;
    for (Plane& p : planes)
        p.resize(image.pixelCount());
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
    {
        const vec3& c = image.data()[i];
        const vec3 v = flip::xyzToYCxCz(flip::linearRgbToXyz(vec3(clamp01(c.x), clamp01(c.y), clamp01(c.z))));
        planes[0][i] = v.x;
        planes[1][i] = v.y;
        planes[2][i] = v.z;
    }
    return planes;
}

/// The colour pipeline for one image: each YCxCz channel filtered by its CSF, back to linear RGB clamped to
/// [0, 1], then to Hunt-adjusted CIELab. Returns the three Lab planes.
std::array<Plane, 3> filteredHuntLab(const std::array<Plane, 3>& yCxCz, int width, int height,
                                     const flip::SpatialFilters& filters)
{
    Plane tmp, y, cx, cz1, cz2;
    convolveRows(yCxCz[0], tmp, width, height, filters.achromatic);
    convolveColumns(tmp, y, width, height, filters.achromatic);
    convolveRows(yCxCz[1], tmp, width, height, filters.redGreen);
    convolveColumns(tmp, cx, width, height, filters.redGreen);
    convolveRows(yCxCz[2], tmp, width, height, filters.blueYellow1);
    convolveColumns(tmp, cz1, width, height, filters.blueYellow1);
    convolveRows(yCxCz[2], tmp, width, height, filters.blueYellow2);
    convolveColumns(tmp, cz2, width, height, filters.blueYellow2);

    std::array<Plane, 3> lab;
    for (Plane& p : lab)
        p.resize(y.size());
    for (std::size_t i = 0; i < y.size(); ++i)
    {
        const vec3 rgb = flip::xyzToLinearRgb(flip::yCxCzToXyz(vec3(y[i], cx[i], cz1[i] + cz2[i])));
        const vec3 v = flip::huntAdjust(
            flip::xyzToLab(flip::linearRgbToXyz(vec3(clamp01(rgb.x), clamp01(rgb.y), clamp01(rgb.z)))));
        lab[0][i] = v.x;
        lab[1][i] = v.y;
        lab[2][i] = v.z;
    }
    return lab;
}

/// The feature pipeline for one image: from its achromatic channel as luminance relative to white,
/// (Y + 16) / 116 in [0, 1], the magnitudes of the edge (first-derivative) and point (second-derivative)
/// responses, each the length of its (x, y) pair.
struct FeatureMagnitudes
{
    Plane edge, point;
};
FeatureMagnitudes featureMagnitudes(const Plane& yChannel, int width, int height,
                                    const flip::FeatureFilters& f)
{
    Plane lum(yChannel.size());
    for (std::size_t i = 0; i < lum.size(); ++i)
        lum[i] = (yChannel[i] + 16.0f) / 116.0f;
    Plane g, d1, d2; // rows filtered by the Gaussian, its first and its second derivative
    convolveRows(lum, g, width, height, f.gaussian);
    convolveRows(lum, d1, width, height, f.firstDerivative);
    convolveRows(lum, d2, width, height, f.secondDerivative);
    Plane dx, ddx, dy, ddy;
    convolveColumns(d1, dx, width, height, f.gaussian);
    convolveColumns(d2, ddx, width, height, f.gaussian);
    convolveColumns(g, dy, width, height, f.firstDerivative);
    convolveColumns(g, ddy, width, height, f.secondDerivative);
    FeatureMagnitudes m;
    m.edge.resize(lum.size());
    m.point.resize(lum.size());
    for (std::size_t i = 0; i < lum.size(); ++i)
    {
        m.edge[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
        m.point[i] = std::sqrt(ddx[i] * ddx[i] + ddy[i] * ddy[i]);
    }
    return m;
}

void checkSizes(const Image& test, const Image& reference, const char* what)
{
    if (test.width() != reference.width() || test.height() != reference.height())
        throw UsageError(fmt::format("cannot compute {} of a {}x{} image against a {}x{} reference", what,
                                     test.width(), test.height(), reference.width(), reference.height()));
    if (reference.empty())
        throw UsageError(fmt::format("cannot compute {} of an empty image", what));
}

void checkPixelsPerDegree(double ppd)
{
    if (!(ppd > 0.0) || !std::isfinite(ppd))
        throw UsageError(fmt::format("FLIP's pixels per degree must be positive, not {}", ppd));
}

/// LDR-FLIP without the argument checks.
FlipErrorMap ldrFlipUnchecked(const Image& test, const Image& reference, double ppd)
{
    const int w = reference.width(), h = reference.height();
    const flip::SpatialFilters spatial = flip::spatialFilters(ppd);
    const flip::FeatureFilters features = flip::featureFilters(ppd);

    const std::array<Plane, 3> refYCxCz = toYCxCz(reference);
    const std::array<Plane, 3> testYCxCz = toYCxCz(test);

    FlipErrorMap map;
    map.width = w;
    map.height = h;
    map.values.resize(reference.pixelCount());
    {
        const std::array<Plane, 3> refLab = filteredHuntLab(refYCxCz, w, h, spatial);
        const std::array<Plane, 3> testLab = filteredHuntLab(testYCxCz, w, h, spatial);
        for (std::size_t i = 0; i < map.values.size(); ++i)
            map.values[i] =
                flip::remapColorDifference(flip::hyab(vec3(refLab[0][i], refLab[1][i], refLab[2][i]),
                                                      vec3(testLab[0][i], testLab[1][i], testLab[2][i])));
    }
    const FeatureMagnitudes refFeatures = featureMagnitudes(refYCxCz[0], w, h, features);
    const FeatureMagnitudes testFeatures = featureMagnitudes(testYCxCz[0], w, h, features);
    const float invSqrt2 = float(1.0 / std::sqrt(2.0));
    for (std::size_t i = 0; i < map.values.size(); ++i)
    {
        const float edge = std::abs(refFeatures.edge[i] - testFeatures.edge[i]);
        const float point = std::abs(refFeatures.point[i] - testFeatures.point[i]);
        const float featureError = std::pow(invSqrt2 * std::max(edge, point), float(flip::kQf));
        map.values[i] = std::pow(map.values[i], 1.0f - featureError);
    }
    return map;
}

/// x_max: the input at which flipToneMap reaches 0.85, the larger root of f(x) = 0.85 written as a quadratic:
/// with u = 0.6 x, u (2.51 u + 0.03) = 0.85 (u (2.43 u + 0.59) + 0.14).
double toneMapperInputAt085()
{
    const double t = 0.85;
    const double a = 2.51 - t * 2.43, b = 0.03 - t * 0.59, c = -t * 0.14;
    const double u = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    return u / 0.6;
}
} // namespace

double flipPixelsPerDegree(double viewingDistance, double monitorWidth, double pixelsAcross)
{
    return viewingDistance * (pixelsAcross / monitorWidth) * (flip::kPiD / 180.0);
}

double FlipErrorMap::mean() const
{
    double sum = 0.0;
    for (float v : values)
        sum += v;
    return values.empty() ? 0.0 : sum / double(values.size());
}

FlipErrorMap ldrFlip(const Image& test, const Image& reference, const FlipOptions& options)
{
    checkSizes(test, reference, "LDR-FLIP");
    checkPixelsPerDegree(options.pixelsPerDegree);
    return ldrFlipUnchecked(test, reference, options.pixelsPerDegree);
}

double meanLdrFlip(const Image& test, const Image& reference, const FlipOptions& options)
{
    return ldrFlip(test, reference, options).mean();
}

double FlipExposures::at(int i) const
{
    return count <= 1 ? start : start + double(i) * (stop - start) / double(count - 1);
}

float flipToneMap(float x)
{
    const float u = 0.6f * x;
    return u * (2.51f * u + 0.03f) / (u * (2.43f * u + 0.59f) + 0.14f);
}

FlipExposures flipAutomaticExposures(const Image& reference)
{
    if (reference.empty())
        throw UsageError("cannot choose HDR-FLIP's exposures for an empty reference");
    std::vector<float> lum(reference.pixelCount());
    for (std::size_t i = 0; i < lum.size(); ++i)
        lum[i] = luminance(reference.data()[i]);
    const float maxLum = *std::max_element(lum.begin(), lum.end());
    const std::size_t mid = lum.size() / 2;
    std::nth_element(lum.begin(), lum.begin() + std::ptrdiff_t(mid), lum.end());
    const float medianLum = lum[mid];
    if (!(medianLum > 0.0f) || !std::isfinite(maxLum))
        throw UsageError(
            fmt::format("HDR-FLIP's automatic exposures need a reference whose median and maximum "
                        "luminance are positive and finite (they are {} and {}): give the start and "
                        "stop exposures",
                        medianLum, maxLum));
    const double xMax = toneMapperInputAt085();
    FlipExposures e;
    e.start = std::log2(xMax / double(maxLum));
    e.stop = std::log2(xMax / double(medianLum));
    e.count = int(std::max(2.0, std::ceil(e.stop - e.start)));
    return e;
}

HdrFlipResult hdrFlip(const Image& test, const Image& reference, const HdrFlipOptions& options)
{
    checkSizes(test, reference, "HDR-FLIP");
    checkPixelsPerDegree(options.pixelsPerDegree);
    if (options.exposureCount < 0)
        throw UsageError(
            fmt::format("HDR-FLIP's exposure count must be at least 1, not {}", options.exposureCount));
    FlipExposures e;
    if (!options.startExposure || !options.stopExposure)
    {
        const FlipExposures automatic = flipAutomaticExposures(reference);
        e.start = options.startExposure.value_or(automatic.start);
        e.stop = options.stopExposure.value_or(automatic.stop);
    }
    else
    {
        e.start = *options.startExposure;
        e.stop = *options.stopExposure;
    }
    if (!(e.start <= e.stop) || !std::isfinite(e.start) || !std::isfinite(e.stop))
        throw UsageError(fmt::format(
            "HDR-FLIP's start exposure ({}) must be finite and not above its stop ({})", e.start, e.stop));
    e.count =
        options.exposureCount > 0 ? options.exposureCount : int(std::max(2.0, std::ceil(e.stop - e.start)));

    HdrFlipResult result;
    result.exposures = e;
    result.error.width = reference.width();
    result.error.height = reference.height();
    result.error.values.assign(reference.pixelCount(), 0.0f);
    Image exposedRef(reference.width(), reference.height()), exposedTest(test.width(), test.height());
    for (int i = 0; i < e.count; ++i)
    {
        const float scale = float(std::exp2(e.at(i)));
        for (std::size_t p = 0; p < reference.pixelCount(); ++p)
            for (int c = 0; c < 3; ++c)
            {
                exposedRef.data()[p][c] = flipToneMap(scale * reference.data()[p][c]);
                exposedTest.data()[p][c] = flipToneMap(scale * test.data()[p][c]);
            }
        // ldrFlip clamps the tone-mapped values to [0, 1].
        const FlipErrorMap map = ldrFlipUnchecked(exposedTest, exposedRef, options.pixelsPerDegree);
        for (std::size_t p = 0; p < map.values.size(); ++p)
            result.error.values[p] = std::max(result.error.values[p], map.values[p]);
    }
    return result;
}

double meanHdrFlip(const Image& test, const Image& reference, const HdrFlipOptions& options)
{
    return hdrFlip(test, reference, options).error.mean();
}
} // namespace rt
