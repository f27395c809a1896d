// Counter-based random numbers: the stream of a camera sample depends only on (seed, pixel, sample index),
// never on the thread, the engine or the order pixels are rendered in. The GLSL twin is Shaders/Random.glsl
// and produces the same numbers bit for bit.
#pragma once

#include <cstdint>

namespace rt
{
/// PCG hash (RXS-M-XS 32/32) of one 32-bit word: Jarzynski & Olano, "Hash Functions for GPU Rendering",
/// JCGT 9(3), 2020. Used to turn counters into well-mixed seeds.
constexpr std::uint32_t pcgHash(std::uint32_t v)
{
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// A PCG32 (RXS-M-XS) generator with 32 bits of state: O'Neill, "PCG: A Family of Simple Fast
/// Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014. A path draws a few
/// hundred numbers, far inside the 2^32 period.
class Rng
{
public:
    constexpr explicit Rng(std::uint32_t state) : m_state(state) {}

    /// The generator of one camera sample.
    static constexpr Rng forSample(std::uint32_t seed, std::uint32_t pixelIndex, std::uint32_t sampleIndex)
    {
        return Rng(pcgHash(pixelIndex ^ pcgHash(sampleIndex ^ pcgHash(seed))));
    }

    constexpr std::uint32_t nextUint()
    {
        m_state = m_state * 747796405u + 2891336453u;
        const std::uint32_t word = ((m_state >> ((m_state >> 28u) + 4u)) ^ m_state) * 277803737u;
        return (word >> 22u) ^ word;
    }

    /// Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never returned.
    constexpr float nextFloat() { return static_cast<float>(nextUint() >> 8) * 0x1p-24f; }

    constexpr std::uint32_t state() const { return m_state; }

private:
    std::uint32_t m_state;
};

/// The generator behind scene content (random sphere fields, Perlin tables). Scenes draw from it with every
/// call sequenced explicitly, one statement per draw, so a scene is bit-identical on every compiler.
class SceneRandom
{
public:
    explicit SceneRandom(std::uint32_t seed) : m_rng(pcgHash(seed)) {}
    float uniform() { return m_rng.nextFloat(); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [lo, hi].
    int integer(int lo, int hi) { return lo + static_cast<int>(uniform() * static_cast<float>(hi - lo + 1)); }

private:
    Rng m_rng;
};
} // namespace rt
