// Counter-based random numbers, written once for both engines (Shared/ShaderLang.h): the stream of a camera
// sample depends only on (seed, pixel, sample index), never on the thread, the engine, the dispatch or the
// order pixels are rendered in. A stream is PCG's, or with --sampling sobol one Owen-scrambled Sobol point per
// 2D draw (Shared/Sobol.h). Integer arithmetic only: every GPU produces the CPU's numbers bit for bit.
// C++ callers reach it through Random/Pcg.h, which adds the scenes' generator.
#ifndef RT_SHARED_RANDOM_H
#define RT_SHARED_RANDOM_H

#include "Shared/ShaderLang.h"
#include "Shared/Sobol.h"

RT_SHADER_NAMESPACE_BEGIN

/// PCG hash (RXS-M-XS 32/32) of one 32-bit word: Jarzynski & Olano, "Hash Functions for GPU Rendering",
/// JCGT 9(3), 2020. Turns counters into well-mixed seeds.
RT_FN uint pcgHash(uint v)
{
    const uint state = v * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// The numbers of one camera sample: a PCG32 (RXS-M-XS) generator with 32 bits of state (O'Neill, "PCG: A
/// Family of Simple Fast Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014; a
/// path draws a few hundred numbers, far inside the 2^32 period), or one Owen-scrambled Sobol point per 2D draw.
struct Rng
{
    uint state;
    uint sobolSeed; // Sobol: the pixel's seed, from which each draw's seeds are hashed
    uint sampleIndex; // Sobol: the point of every draw's sequence
    uint dimension; // Sobol: 2D draws made
    bool sobol;
#ifdef __cplusplus
    Rng() = default;
    constexpr explicit Rng(uint pcgState) : state(pcgState), sobolSeed(0), sampleIndex(0), dimension(0), sobol(false)
    {
    }
    static Rng forSample(uint seed, uint pixelIndex, uint sampleIndex);
    static Rng forSobolSample(uint seed, uint pixelIndex, uint sampleIndex);
    uint nextUint();
    float nextFloat();
    vec2 next2D();
#endif
};

/// A PCG generator whose next state follows `state`.
RT_FN Rng rngWithState(uint state)
{
    Rng rng;
    rng.state = state;
    rng.sobolSeed = 0u;
    rng.sampleIndex = 0u;
    rng.dimension = 0u;
    rng.sobol = false;
    return rng;
}

/// The generator of one camera sample.
RT_FN Rng rngForSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    return rngWithState(pcgHash(pixelIndex ^ pcgHash(sampleIndex ^ pcgHash(seed))));
}

/// The Owen-scrambled Sobol draws of sample `sampleIndex` of a pixel: draw k of every sample of the pixel is
/// point sampleIndex of one scrambled (0, 2)-sequence, its seeds hashed from (seed, pixel, k). Its PCG state
/// is rngForSample's, unused by the draws.
RT_FN Rng rngForSobolSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    Rng rng = rngForSample(seed, pixelIndex, sampleIndex);
    rng.sobolSeed = pcgHash(pixelIndex ^ pcgHash(seed ^ 0x736f626cu));
    rng.sampleIndex = sampleIndex;
    rng.sobol = true;
    return rng;
}

/// The next 2D Sobol draw.
RT_FN vec2 nextSobol(RT_INOUT(Rng) rng)
{
    const uint draw = pcgHash(rng.sobolSeed + rng.dimension);
    rng.dimension += 1u;
    return owenScrambledSobol2D(rng.sampleIndex, draw, pcgHash(draw ^ 0x68bc21ebu), pcgHash(draw ^ 0x02e5be93u));
}

RT_FN uint nextUint(RT_INOUT(Rng) rng)
{
    rng.state = rng.state * 747796405u + 2891336453u;
    const uint word = ((rng.state >> ((rng.state >> 28u) + 4u)) ^ rng.state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never returned.
/// Sobol: the first coordinate of the next 2D draw.
RT_FN float nextFloat(RT_INOUT(Rng) rng)
{
    if (rng.sobol)
        return nextSobol(rng).x;
    return fixedPointToUnitFloat(nextUint(rng));
}

/// A point of [0, 1)^2: two numbers, x first (never inside one expression: the order of a call's arguments must
/// not decide the stream); Sobol: the next 2D draw, stratified over the pixel's samples.
RT_FN vec2 nextFloat2(RT_INOUT(Rng) rng)
{
    if (rng.sobol)
        return nextSobol(rng);
    const float x = nextFloat(rng);
    const float y = nextFloat(rng);
    return vec2(x, y);
}

#ifdef __cplusplus
inline Rng Rng::forSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    return rngForSample(seed, pixelIndex, sampleIndex);
}
inline Rng Rng::forSobolSample(uint seed, uint pixelIndex, uint sampleIndex)
{
    return rngForSobolSample(seed, pixelIndex, sampleIndex);
}
inline uint Rng::nextUint() { return shader::nextUint(*this); }
inline float Rng::nextFloat() { return shader::nextFloat(*this); }
inline vec2 Rng::next2D() { return nextFloat2(*this); }
#endif

RT_SHADER_NAMESPACE_END

#endif
