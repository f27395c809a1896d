// Counter-based random numbers, bit for bit the twin of Common/Random/Pcg.h: the stream of a camera sample
// depends only on (seed, pixel, sample index); with --sampling sobol, Owen-scrambled Sobol points
// (Shared/Sobol.h), one per 2D draw. Integer arithmetic only, so every GPU produces the C++ numbers.
#ifndef RT_RANDOM_GLSL
#define RT_RANDOM_GLSL

#include "Shared/Sobol.h"

/// PCG hash (RXS-M-XS 32/32): Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020.
uint pcgHash(uint v)
{
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// PCG32 (RXS-M-XS) with 32 bits of state: O'Neill, "PCG: A Family of Simple Fast Space-Efficient
/// Statistically Good Algorithms for Random Number Generation", 2014.
struct Rng
{
    uint state;
    uint sobolSeed;
    uint sampleIndex;
    uint dimension; // 2D draws made
    bool sobol;
};

/// The generator of one camera sample (rt::Rng::forSample).
Rng rngForSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    return Rng(pcgHash(pixelIndex ^ pcgHash(sampleIndex ^ pcgHash(seed))), 0u, 0u, 0u, false);
}

/// The Owen-scrambled Sobol draws of one camera sample (rt::Rng::forSobolSample).
Rng rngForSobolSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    Rng rng = rngForSample(seed, pixelIndex, sampleIndex);
    rng.sobolSeed = pcgHash(pixelIndex ^ pcgHash(seed ^ 0x736f626cu));
    rng.sampleIndex = sampleIndex;
    rng.sobol = true;
    return rng;
}

/// The next 2D Sobol draw (rt::Rng::nextSobol).
vec2 nextSobol(inout Rng rng)
{
    uint draw = pcgHash(rng.sobolSeed + rng.dimension);
    rng.dimension += 1u;
    return owenScrambledSobol2D(rng.sampleIndex, draw, pcgHash(draw ^ 0x68bc21ebu), pcgHash(draw ^ 0x02e5be93u));
}

uint nextUint(inout Rng rng)
{
    rng.state = rng.state * 747796405u + 2891336453u;
    uint word = ((rng.state >> ((rng.state >> 28u) + 4u)) ^ rng.state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Uniform in [0, 1): the top 24 bits, exactly representable, never 1. Sobol: the next 2D draw's first coordinate.
float nextFloat(inout Rng rng)
{
    if (rng.sobol)
        return nextSobol(rng).x;
    return float(nextUint(rng) >> 8) * (1.0 / 16777216.0);
}

/// Two numbers, drawn x first (never inside one expression: argument order must not decide the stream); Sobol:
/// the next 2D draw.
vec2 nextFloat2(inout Rng rng)
{
    if (rng.sobol)
        return nextSobol(rng);
    float x = nextFloat(rng);
    float y = nextFloat(rng);
    return vec2(x, y);
}

#endif
