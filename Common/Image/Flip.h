// FLIP, the image-difference evaluator of Andersson et al.: a per-pixel map in [0, 1] of how different a test
// image looks from a reference when a viewer flips between the two, and its mean. Written from the papers:
//
//   LDR-FLIP: P. Andersson, J. Nilsson, T. Akenine-Möller, M. Oskarsson, K. Åström, M. D. Fairchild,
//     "FLIP: A Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2),
//     15:1-15:23 (HPG 2020), doi:10.1145/3406183: the colour pipeline (spatial filtering by the contrast
//     sensitivity functions in YCxCz, the Hunt adjustment, HyAB and its remapping), the feature pipeline
//     (edge and point detection) and their combination, error = (colour error)^(1 - feature error).
//   HDR-FLIP: P. Andersson, J. Nilsson, P. Shirley, T. Akenine-Möller, "Visualizing Errors in Rendered High
//     Dynamic Range Images", Eurographics 2021 Short Papers, doi:10.2312/egs.20211015: tone-map both images
//     at a range of exposures chosen from the reference, take the per-pixel maximum of LDR-FLIP over them.
//
// Both images are linear RGB (rt::Image); the pipeline is float, single-threaded, with separable filters
// (P. Andersson's note "A Note on the Separability of the Filters Used in FLIP", 2022, in NVIDIA's
// repository, shows the separation is exact). Comments below name the paper's part a piece comes from.
// Cross-checked against NVIDIA's reference implementation (github.com/NVlabs/flip, BSD-3-Clause) on the
// images in tests/Data/flip/ (FlipTest.cpp). Pixels outside the image repeat the nearest edge pixel.
#pragma once

#include <optional>
#include <vector>

#include "Image/Image.h"

namespace rt
{
/// Pixels per degree of visual angle of an observer `viewingDistance` metres from a monitor `monitorWidth`
/// metres wide that shows `pixelsAcross` pixels across: d (r / w) pi / 180 (LDR-FLIP paper, its viewing
/// set-up).
double flipPixelsPerDegree(double viewingDistance, double monitorWidth, double pixelsAcross);

/// The papers' default observer: 0.7 m from a 0.7 m wide 4K (3840 pixels across) monitor, 67.02 pixels per
/// degree.
inline constexpr double kFlipDefaultPixelsPerDegree = 0.7 * (3840.0 / 0.7) * (3.14159265358979323846 / 180.0);

struct FlipOptions
{
    double pixelsPerDegree = kFlipDefaultPixelsPerDegree; // > 0; sizes every filter
};

/// One FLIP value per pixel, each in [0, 1] (0: no visible difference), row-major, row 0 at the top.
struct FlipErrorMap
{
    int width = 0;
    int height = 0;
    std::vector<float> values; // width * height

    float at(int x, int y) const { return values[std::size_t(y) * width + x]; }
    /// Mean over every pixel (accumulated in double); 0 for an empty map. The papers' summary number.
    double mean() const;
};

/// LDR-FLIP of two display images: each value of `test` and `reference` is the linear intensity in [0, 1]
/// that an sRGB display shows (an 8-bit PNG decoded with the sRGB curve; what writePng encodes). Values
/// outside [0, 1] are clamped, NaN counts as 0. The images are the display's pixels, so FLIP applies no sRGB
/// decoding of its own: the paper's sRGB input is decoded by the caller. Per pixel, the colour error e_c is
/// remapColorDifference of the HyAB distance between the two images' CSF-filtered (spatialFilters), Hunt-
/// adjusted CIELab colours; the feature error e_f = (max(|edge_r - edge_t|, |point_r - point_t|) / sqrt(2))^qf,
/// edge and point the lengths of the (x, y) responses of featureFilters to the relative luminance
/// (Y + 16) / 116 of YCxCz; and FLIP = e_c^(1 - e_f). Throws UsageError on a size mismatch or an empty
/// image, or if pixelsPerDegree is not positive.
FlipErrorMap ldrFlip(const Image& test, const Image& reference, const FlipOptions& options = {});
/// ldrFlip(...).mean().
double meanLdrFlip(const Image& test, const Image& reference, const FlipOptions& options = {});

/// The exposures (stops: an image is scaled by 2^exposure before tone mapping) at which HDR-FLIP compares.
struct FlipExposures
{
    double start = 0.0;
    double stop = 0.0;
    int count = 2;
    /// Exposure i of count, evenly spaced from start to stop (start alone when count is 1).
    double at(int i) const;
};

/// HDR-FLIP's automatic exposure range from the reference (HDR-FLIP paper, its exposure range): x_max the
/// input at which the tone mapper (flipToneMap) reaches 0.85, start = log2(x_max / L_max) and stop =
/// log2(x_max / L_median), L the Rec. 709 luminance of the reference's pixels (L_median: the element n / 2 of
/// the n sorted luminances), and count = max(2, ceil(stop - start)). Throws UsageError on an empty image or
/// where the range is undefined: a maximum or median luminance that is not positive and finite (a reference
/// at least half black), for which the caller must give the exposures.
FlipExposures flipAutomaticExposures(const Image& reference);

struct HdrFlipOptions
{
    double pixelsPerDegree = kFlipDefaultPixelsPerDegree;
    std::optional<double> startExposure; // stops; default: flipAutomaticExposures(reference).start
    std::optional<double> stopExposure;  // stops, >= start; default: flipAutomaticExposures(reference).stop
    int exposureCount = 0;               // >= 1; 0: max(2, ceil(stop - start))
};

struct HdrFlipResult
{
    FlipErrorMap error;      // per pixel, the maximum of LDR-FLIP over the exposures
    FlipExposures exposures; // the exposures used
};

/// HDR-FLIP of two linear HDR images (radiance, >= 0, finite): at each exposure c both are scaled by 2^c,
/// tone mapped per channel by flipToneMap, clamped to [0, 1] and compared by LDR-FLIP as display images; the
/// map is the per-pixel maximum over the exposures. Throws UsageError on a size mismatch, an empty image, a
/// start exposure above the stop, an exposure count below 0, or where flipAutomaticExposures throws.
HdrFlipResult hdrFlip(const Image& test, const Image& reference, const HdrFlipOptions& options = {});
/// hdrFlip(...).error.mean().
double meanHdrFlip(const Image& test, const Image& reference, const HdrFlipOptions& options = {});

/// HDR-FLIP's tone mapper: Narkowicz's 2016 fit of the ACES filmic curve, f(x) = x (2.51 x + 0.03) /
/// (x (2.43 x + 0.59) + 0.14), applied to 0.6 x (the fit's own exposure of 0.6 taken back into the input, as
/// HDR-FLIP does). Per channel; not clamped (f tends to 1.033 for large x).
float flipToneMap(float x);

/// The pieces of FLIP, exposed for the tests. Colours are float vec3; constants are the papers' values.
namespace flip
{
inline constexpr double kQc = 0.7;  // exponent on the HyAB colour difference
inline constexpr double kPc = 0.4;  // fraction of the maximum difference where the remapping's slope changes
inline constexpr double kPt = 0.95; // remapped value at that point
inline constexpr double kFeatureWidth = 0.082; // w, degrees: the feature detectors' sigma is w / 2
inline constexpr double kQf = 0.5;             // exponent on the feature difference

/// The contrast sensitivity functions as sums of Gaussians, S(f) = a1 e^(-b1 f^2) + a2 e^(-b2 f^2), f in
/// cycles per degree; in the image plane each term is a sqrt(pi / b) e^(-pi^2 r^2 / b), r in degrees
/// (LDR-FLIP paper, the colour pipeline's spatial filtering, with its table of a1, b1, a2, b2 per channel).
struct CsfConstants
{
    double a1, b1, a2, b2;
};
inline constexpr CsfConstants kCsfAchromatic{1.0, 0.0047, 0.0, 1.0e-5};
inline constexpr CsfConstants kCsfRedGreen{1.0, 0.0053, 0.0, 1.0e-5};
inline constexpr CsfConstants kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};

/// Linear sRGB (Rec. 709 primaries, D65 white) to CIE XYZ, the matrix derived from the primaries'
/// chromaticities (IEC 61966-2-1) and D65's (0.31271, 0.32902); white (1, 1, 1) maps to the reference white
/// of the two spaces below.
vec3 linearRgbToXyz(const vec3& rgb);
vec3 xyzToLinearRgb(const vec3& xyz);
/// The reference white: linearRgbToXyz(1, 1, 1), Y = 1.
vec3 referenceWhite();
/// YCxCz, the linearised CIELab of Zhang and Wandell: Y = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn),
/// Cz = 200 (Y/Yn - Z/Zn). White is (100, 0, 0); black (-16, 0, 0).
vec3 xyzToYCxCz(const vec3& xyz);
vec3 yCxCzToXyz(const vec3& yCxCz);
/// CIE 1976 L*a*b* relative to referenceWhite().
vec3 xyzToLab(const vec3& xyz);
/// The Hunt adjustment: a and b scaled by 0.01 L (chroma looks weaker in the dark).
vec3 huntAdjust(const vec3& lab);
/// HyAB distance: |L1 - L2| + ||(a1, b1) - (a2, b2)||.
float hyab(const vec3& lab1, const vec3& lab2);
/// cmax: the remapping's largest difference, HyAB(Hunt(green), Hunt(blue))^qc for linear green (0, 1, 0)
/// and blue (0, 0, 1), the most different pair of display colours.
double maxColorDifference();
/// The colour error in [0, 1] from a HyAB distance: d = hyab^qc, then d pt / (pc cmax) below pc cmax,
/// pt + (1 - pt) (d - pc cmax) / (cmax - pc cmax) above.
float remapColorDifference(float hyabDistance);

/// One 1D factor of each separable spatial filter, taps at -radius..radius pixels (offset / ppd degrees).
/// The 2D filters are achromatic x achromatic, redGreen x redGreen and blueYellow1 x blueYellow1 +
/// blueYellow2 x blueYellow2, each normalised so that its 2D weights sum to 1. Radius: ceil(3 sqrt(b_max /
/// (2 pi^2)) ppd), b_max the largest b of the three channels.
struct SpatialFilters
{
    int radius = 0;
    std::vector<float> achromatic, redGreen, blueYellow1, blueYellow2;
};
SpatialFilters spatialFilters(double pixelsPerDegree);

/// One 1D factor of the separable feature detectors, sigma = 0.5 w ppd pixels, radius ceil(3 sigma): the
/// Gaussian normalised to sum 1, and its first and second derivatives each normalised so that their positive
/// weights sum to 1 and negative weights to -1. The edge detector along x is firstDerivative(x) gaussian(y),
/// the point detector secondDerivative(x) gaussian(y), and likewise along y.
struct FeatureFilters
{
    int radius = 0;
    std::vector<float> gaussian, firstDerivative, secondDerivative;
};
FeatureFilters featureFilters(double pixelsPerDegree);
} // namespace flip
} // namespace rt
