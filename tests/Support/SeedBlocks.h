// RenderEngine::setSeedBlock's promise, for any engine: a frame of k seed blocks of n samples holds the renders of
// seeds seed .. seed + k - 1 at n spp, each bit for bit the render of its seed alone, however the frame's samples are
// cut into batches (a batch that crosses from one block into the next included). --strategy auto's error estimate
// takes its two halves as independent renders; halves of one Sobol sequence ([0, n) and [n, 2n)) would not be.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Render/RenderEngine.h"

namespace rt::test
{
/// The estimate of `settings` on `engine` (its scene set) after its trueSpp samples, traced in batches of `batch`.
inline Image estimateInBatches(RenderEngine& engine, const RenderSettings& settings, std::uint32_t batch)
{
    engine.beginFrame(settings);
    RenderControl control;
    const auto samples = static_cast<std::uint32_t>(settings.trueSpp());
    control.begin(std::uint64_t(settings.width) * std::uint64_t(settings.height()) * samples);
    for (std::uint32_t first = 0; first < samples; first += batch)
        EXPECT_TRUE(engine.traceSamples(first, std::min(batch, samples - first), control).complete);
    return engine.estimate(samples);
}

/// Block `block` of a frame of seed blocks (estimate's image: the blocks one below the other, `height` rows each).
inline Image seedBlockOf(const Image& frame, int height, int block)
{
    Image out(frame.width(), height);
    const std::size_t pixels = out.pixelCount();
    std::copy_n(frame.pixels().begin() + static_cast<std::ptrdiff_t>(block * pixels), pixels, out.pixels().begin());
    return out;
}

/// Renders a frame of three seed blocks of settings.spp samples each (3 x spp in all), in batches that cross the
/// blocks' borders, and expects block k to be the render of seed settings.seed + k alone at settings.spp, bit for
/// bit; `what` names the case. Leaves the engine without seed blocks.
inline void expectSeedBlocksAreTheirSeedsRenders(RenderEngine& engine, const RenderSettings& settings,
                                                 const std::string& what)
{
    const auto n = static_cast<std::uint32_t>(settings.trueSpp());
    constexpr int kBlocks = 3;
    RenderSettings frame = settings;
    frame.spp = kBlocks * settings.spp;
    engine.setSeedBlock(n);
    Image blocks;
    try
    {
        // Batches of n + 1 samples: each after the first starts inside a block and ends inside the next.
        blocks = estimateInBatches(engine, frame, n + 1);
    }
    catch (...)
    {
        engine.setSeedBlock(0);
        throw;
    }
    engine.setSeedBlock(0);
    const int height = settings.height();
    ASSERT_EQ(blocks.width(), settings.width) << what;
    ASSERT_EQ(blocks.height(), kBlocks * height) << what;
    bool anyLight = false;
    for (int k = 0; k < kBlocks; ++k)
    {
        RenderSettings alone = settings;
        alone.seed = settings.seed + std::uint32_t(k);
        const Image expected = estimateInBatches(engine, alone, n);
        const Image block = seedBlockOf(blocks, height, k);
        EXPECT_EQ(block.pixels(), expected.pixels()) << what << ": seed block " << k << " is not seed "
                                                     << alone.seed << "'s render";
        const vec3 mean = expected.mean();
        anyLight = anyLight || mean.x + mean.y + mean.z > 0.0f;
    }
    EXPECT_TRUE(anyLight) << what << ": black renders compare equal whatever the seeds";
    // Two seeds' renders differ: a frame that drew every block on one seed would pass the equalities above only
    // if the seeds made no difference.
    EXPECT_NE(seedBlockOf(blocks, height, 0).pixels(), seedBlockOf(blocks, height, 1).pixels()) << what;
}
} // namespace rt::test
