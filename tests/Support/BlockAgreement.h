// Two renders of one scene agree in expectation (research notes §2.6; Mitsuba's per-pixel Z-tests, on
// blocks here): block means of luminance compared with a Z-test whose variance comes from independent
// renders (seeds) of each configuration. Compares engines (CPU against GPU) or estimators, samplers and
// Russian roulette on one engine: anything whose expectation must not change.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Render/RenderDriver.h"

namespace rt::test
{
inline constexpr int kAgreementSeeds = 4; // independent renders per configuration
inline constexpr int kAgreementBlock = 8; // pixels per block side
// |Z| bounds: 4 is 6e-5 two-sided per block, 0.05 false alarms expected over ~800 blocks; 4.5 is 7e-6 per
// block, 0.03 over ~4,400. A wrong pdf or a missing cosine moves whole regions by far more; the biases the
// heavy suite found (a wall re-hit by its own rays) gave |Z| from 4 to 7 on a dozen blocks of each Cornell box.
inline constexpr double kMaxZ = 4.0;
inline constexpr double kMaxZHeavy = 4.5;

struct BlockEstimate
{
    std::vector<double> mean; // per block, over seeds and pixels
    std::vector<double> variance; // of `mean`, pooled from the per-pixel spread over seeds
    int blocksX = 0;
    int blocksY = 0;
    std::uint64_t nonFiniteSamples = 0; // NaN and Inf samples the renders' stats counted (and dropped)
};

/// Renders `scene` kAgreementSeeds times on `engine` (seeds 1000, 1001, ...) and estimates its blocks.
BlockEstimate estimateBlocks(RenderEngine& engine, const Scene& scene, RenderSettings settings);

/// The blocks whose |Z| exceeds maxZ, one line each ("block (x, y) luminance A a, B b, sigma s, z z"); empty
/// when all agree. Blocks without noise (background, zero-variance paths) must agree to 1e-5 relative: the
/// engines sum in different orders and a GPU's sin/cos differ from the CPU's in the last bits.
std::vector<std::string> disagreeingBlocks(const BlockEstimate& a, const BlockEstimate& b, double maxZ);
} // namespace rt::test
