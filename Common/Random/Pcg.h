// Counter-based random numbers: the stream of a camera sample depends only on (seed, pixel, sample index),
// never on the thread, the engine or the order pixels are rendered in. The GLSL twin is Shaders/Random.glsl
// and produces the same numbers bit for bit. A camera sample's stream is PCG's, or with --sampling sobol
// Owen-scrambled Sobol points (Shared/Sobol.h), one 2D point per 2D draw.
#pragma once

#include <cstdint>

#include "Math/Math.h"
#include "Shared/Sobol.h"

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

/// The numbers of one camera sample: a PCG32 (RXS-M-XS) generator with 32 bits of state (O'Neill, "PCG: A
/// Family of Simple Fast Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014; a
/// path draws a few hundred numbers, far inside the 2^32 period), or with forSobolSample one Owen-scrambled
/// Sobol point per draw (Shared/Sobol.h). The path loops draw through nextFloat and next2D, which serve both.
class Rng
{
public:
    constexpr explicit Rng(std::uint32_t state) : m_state(state) {}

    /// The generator of one camera sample.
    static constexpr Rng forSample(std::uint32_t seed, std::uint32_t pixelIndex, std::uint32_t sampleIndex)
    {
        return Rng(pcgHash(pixelIndex ^ pcgHash(sampleIndex ^ pcgHash(seed))));
    }

    /// The Owen-scrambled Sobol draws of sample `sampleIndex` of a pixel: draw k of every sample of the pixel
    /// is point sampleIndex of one scrambled (0, 2)-sequence, its seeds hashed from (seed, pixel, k).
    static constexpr Rng forSobolSample(std::uint32_t seed, std::uint32_t pixelIndex, std::uint32_t sampleIndex)
    {
        Rng rng = forSample(seed, pixelIndex, sampleIndex);
        rng.m_sobolSeed = pcgHash(pixelIndex ^ pcgHash(seed ^ kSobolSalt));
        rng.m_sampleIndex = sampleIndex;
        rng.m_sobol = true;
        return rng;
    }

    constexpr std::uint32_t nextUint()
    {
        m_state = m_state * 747796405u + 2891336453u;
        const std::uint32_t word = ((m_state >> ((m_state >> 28u) + 4u)) ^ m_state) * 277803737u;
        return (word >> 22u) ^ word;
    }

    /// Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never returned.
    /// Sobol: the first coordinate of the next 2D draw.
    float nextFloat() { return m_sobol ? nextSobol().x : static_cast<float>(nextUint() >> 8) * 0x1p-24f; }

    /// A point of [0, 1)^2: two numbers, x first; Sobol: the next 2D draw, stratified over the pixel's samples.
    vec2 next2D()
    {
        if (m_sobol)
            return nextSobol();
        const float x = nextFloat();
        const float y = nextFloat();
        return {x, y};
    }

    constexpr std::uint32_t state() const { return m_state; }

private:
    static constexpr std::uint32_t kSobolSalt = 0x736f626cu;

    vec2 nextSobol()
    {
        const std::uint32_t draw = pcgHash(m_sobolSeed + m_dimension++);
        return shader::owenScrambledSobol2D(m_sampleIndex, draw, pcgHash(draw ^ 0x68bc21ebu), pcgHash(draw ^ 0x02e5be93u));
    }

    std::uint32_t m_state;
    std::uint32_t m_sobolSeed = 0;
    std::uint32_t m_sampleIndex = 0;
    std::uint32_t m_dimension = 0; // 2D draws made
    bool m_sobol = false;
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
