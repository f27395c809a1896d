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
    double psnr = 0.0; // 10 log10(peak^2 / mse), peak = 1 (display white); +inf for identical images
};

inline constexpr double kRelMseEpsilon = 1e-2; // Gharbi et al. 2019's choice, stated wherever relMSE is shown

ErrorMetrics compareImages(const Image& test, const Image& reference, double relMseEpsilon = kRelMseEpsilon);

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
