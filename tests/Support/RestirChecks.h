// restir-di's checks for either engine. Issue 36's unbiasedness test: the mean of 32 independent restir-di renders
// (seeds) agrees with a nee-mis reference (8 renders of 128 spp), block by block and over the image, with |Z| < 4
// and the variance of each mean from the spread between renders. ReSTIR's pixels are correlated (a reservoir
// serves its neighbours and the next iteration), so the spread is never taken over the pixels of one render.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Render/RenderEngine.h"
#include "Render/RenderSettings.h"
#include "Scene/Scene.h"

namespace rt::test
{
/// Block means (16 x 16 pixels) of luminance over independent renders: their mean and the variance of that mean,
/// from the spread between renders; the same for the whole image.
struct OverSeeds
{
    std::vector<double> mean;
    std::vector<double> variance;
    double imageMean = 0.0;
    double imageVariance = 0.0;
};

/// Renders `settings` on `engine` (its scene set) with seeds firstSeed .. firstSeed + seeds - 1.
OverSeeds renderSeeds(RenderEngine& engine, RenderSettings settings, int seeds, std::uint32_t firstSeed);

double zScore(double a, double va, double b, double vb);

/// 48 px, 16 samples per pixel (temporal reuse fifteen times, with M up to its cap; five neighbours), depth 8,
/// random pixel sampling, restir-di's defaults. The biased combination is 1.4 % dark over cornell-box-lights'
/// image at 4 spp (Z -3.9 over 32 renders): 16 spp gives the test the power to see it.
RenderSettings restirSettings(const Scene& scene);

/// The reference: nee-mis with restirSettings' size and depth, 8 renders of 128 spp.
OverSeeds neeMisReference(RenderEngine& engine, const Scene& scene);

/// The mean of 32 restir-di renders of catalogue scene `id` on `engine` against its nee-mis reference, block by
/// block and over the image (gtest expectations).
void expectRestirUnbiased(RenderEngine& engine, const std::string& id);

/// One sample of cornell-box-lights with restirSettings on `engine`: the stats state the reservoirs' memory (at most
/// 64 bytes per pixel, as many bytes in all as the pixels take) and name the combination, unbiased and biased; a
/// nee-mis render states none (gtest expectations).
void expectRestirStats(RenderEngine& engine);
} // namespace rt::test
