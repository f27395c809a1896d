// Error metrics between a test image and a reference, both linear radiance of the same size, averaged over
// every pixel and RGB channel (research notes §5). Throws UsageError on a size mismatch.
#pragma once

#include "Image/Image.h"

namespace rt
{
struct ErrorMetrics
{
    double mse = 0.0; // mean (I - R)^2
    double rmse = 0.0; // sqrt(mse)
    double relMse = 0.0; // mean (I - R)^2 / (R^2 + epsilon)
    /// relMSE with the pixels of the largest 0.1 % of per-pixel relMSE (the mean of its three channels) left
    /// out: fireflies, which dominate relMSE at low spp, no longer decide a comparison (the papers' "relMSE,
    /// top 0.1 % trimmed", e.g. Figueiredo et al., EGSR 2025). floor(0.001 n) pixels are dropped.
    double trimmedRelMse = 0.0;
    /// Mean absolute percentage error, mean |I - R| / (|R| + epsilon) over pixels and channels (Vogels et al.
    /// 2018's MAPE, with relMSE's epsilon).
    double mape = 0.0;
    double psnr = 0.0; // 10 log10(peak^2 / mse), peak = 1 (display white); +inf for identical images
    /// Mean HDR-FLIP (Image/Flip.h) against the reference, its exposures from the reference; < 0 where it was
    /// not computed (it costs 0.2 s at 512 x 384: only for --metric flip).
    double flip = -1.0;
};

inline constexpr double kRelMseEpsilon = 1e-2; // Gharbi et al. 2019's choice, stated wherever relMSE is shown
inline constexpr double kTrimmedFraction = 1e-3; // trimmedRelMse drops this fraction of the pixels

/// Every metric but FLIP. Throws UsageError on a size mismatch.
ErrorMetrics compareImages(const Image& test, const Image& reference, double relMseEpsilon = kRelMseEpsilon);

/// The error a comparison's efficiency uses (--metric).
enum class ErrorMetric
{
    RelMse,
    TrimmedRelMse,
    Mape,
    Flip,
};

/// "relmse", "trimmed-relmse", "mape", "flip": the command line's names.
const char* toString(ErrorMetric metric);
/// The table heading: "relMSE", "trim relMSE", "MAPE", "FLIP".
const char* displayName(ErrorMetric metric);
/// The metric's value in `m` (FLIP's < 0 when not computed).
double metricValue(const ErrorMetrics& m, ErrorMetric metric);
/// The power k of the metric in the efficiency 1 / (metric^k x time): 1 for the squared errors (relMSE and its
/// trimmed form fall as 1/spp for an unbiased estimator), 2 for the first-order ones (MAPE and FLIP fall about
/// as 1/sqrt(spp)), so that an efficiency does not change with the sample count and compares strategies only.
int efficiencyPower(ErrorMetric metric);

/// A reference made of two independent renders of one estimator at the same spp: their mean, and the
/// relMSE that the mean's own noise adds to every relMSE measured against it. With independent halves A and
/// B, E[(A - B)^2] = 2 Var(half) and Var((A + B) / 2) = Var(half) / 2, so each channel's (A - B)^2 / 4 is an
/// unbiased estimate of the mean's squared error, here normalised as relMSE is (by the mean's square plus
/// epsilon). Test and reference being independent, E[relMSE(test)] = relMSE of the test alone + ownRelMse
/// (to first order in the normalisation): a test whose relMSE is within a few times ownRelMse is measuring the
/// reference. Holds for any sampler whose two halves are independently randomised (seeded PCG streams,
/// Owen-scrambled Sobol points of different seeds), whatever its convergence rate. Throws UsageError on a size
/// mismatch.
struct TwoHalfReference
{
    Image mean;
    double ownRelMse = 0.0;
};
TwoHalfReference combineReferenceHalves(const Image& halfA, const Image& halfB,
                                        double relMseEpsilon = kRelMseEpsilon);
} // namespace rt
