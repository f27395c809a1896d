// Owen-scrambled Sobol points for `--sampling sobol`, written once for both engines (Shared/ShaderLang.h):
// Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4). Every 2D draw of a camera sample (pixel
// jitter, lens, a light's point, a BSDF direction...) takes the first two Sobol dimensions, Owen-scrambled
// with seeds of its own and with the sample index shuffled by a seed of its own: each 2D draw is a (0, 2)-
// sequence in base 2 over the pixel's samples (every power-of-two prefix stratified in every elementary
// interval), and the draws are decorrelated from each other ("padding", §4). 1D draws take one coordinate.
// Integer arithmetic only: both engines produce the same bits.
#ifndef RT_SHARED_SOBOL_H
#define RT_SHARED_SOBOL_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// The Laine-Karras permutation of x, a hash in which every bit depends only on the bits below it (Laine &
/// Karras 2011, "Stratified Sampling for Stochastic Transparency"; the constants of Burley 2020, §3). Applied
/// to bit-reversed numbers it scrambles as Owen's nested uniform scrambling does: each bit flipped by a random
/// function of the bits above it.
RT_FN uint laineKarrasPermutation(uint x, uint seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

/// Owen's nested uniform scramble of the 32-bit fixed-point number x (Burley 2020, §3, listing 2).
RT_FN uint nestedUniformScramble(uint x, uint seed)
{
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

/// sobolDimension1(i) with its bits reversed (bit j is output bit j's weight 2^-(j+1)): what a scramble,
/// which works on reversed bits, takes without reversing twice.
RT_FN uint sobolDimension1Reversed(uint i)
{
    i ^= (i >> 1u) & 0x55555555u;
    i ^= (i >> 2u) & 0x33333333u;
    i ^= (i >> 4u) & 0x0F0F0F0Fu;
    i ^= (i >> 8u) & 0x00FF00FFu;
    i ^= (i >> 16u) & 0x0000FFFFu;
    return i;
}

/// Sobol dimension 1 of index i as a 32-bit fixed-point number. Its generator matrix is Pascal's triangle mod 2
/// (primitive polynomial x + 1: direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), v_0 = 2^31), so by Lucas'
/// theorem output bit j (weight 2^-(j+1)) is the XOR of the index bits k whose binary digits include j's: a
/// superset XOR transform over the five bits of a position, five shift-and-XOR steps instead of a loop over
/// the index's 32 bits. Dimension 0 is bitfieldReverse(i), van der Corput's.
RT_FN uint sobolDimension1(uint i)
{
    return bitfieldReverse(sobolDimension1Reversed(i));
}

/// The top 24 bits of a 32-bit fixed-point number in [0, 1): exactly representable, never 1.
RT_FN float fixedPointToUnitFloat(uint x)
{
    return float(x >> 8u) * (1.0f / 16777216.0f);
}

/// Point `index` of one 2D draw: the index shuffled by `shuffleSeed` (Burley 2020, §4: a nested uniform
/// scramble of the index keeps every power-of-two block of the sequence a net), then Sobol dimensions 0 and 1
/// Owen-scrambled with xSeed and ySeed. The three seeds must be independent hashes.
RT_FN vec2 owenScrambledSobol2D(uint index, uint shuffleSeed, uint xSeed, uint ySeed)
{
    const uint i = nestedUniformScramble(index, shuffleSeed);
    // nestedUniformScramble(bitfieldReverse(i), xSeed) and nestedUniformScramble(sobolDimension1(i), ySeed),
    // with the two reversals that cancel left out (half of a draw's bit reversals; the same bits).
    const uint x = bitfieldReverse(laineKarrasPermutation(i, xSeed));
    const uint y = bitfieldReverse(laineKarrasPermutation(sobolDimension1Reversed(i), ySeed));
    return vec2(fixedPointToUnitFloat(x), fixedPointToUnitFloat(y));
}

RT_SHADER_NAMESPACE_END

#endif
