// Random numbers for C++ callers in namespace rt: a camera sample's stream is Shared/Random.h, which the
// shaders compile too; the scenes' generator (host only) is here.
#pragma once

#include <cstdint>

#include "Math/Math.h"
#include "Shared/Random.h"

namespace rt
{
using shader::pcgHash;
using shader::Rng;

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
