// Shaders/Tests/Parity.comp from the host: its modes and their case layouts, and a dispatch over a batch of
// cases. ShaderParityTest.cpp compares the modes case by case with Common's C++; GpuSamplerChiSquareTest.cpp
// histograms mode kLightSampling's samples.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "Math/Math.h"
#include "Sampling/LightBvh.h"

namespace rt::gpu::test
{
// Case layouts of Shaders/Tests/Parity.comp, in 32-bit words (kParityLayouts).
enum ParityMode : std::uint32_t
{
    kRandom = 0,
    kRayOffset = 1,
    kWarps = 2,
    kLightSampling = 3,
    kPerlin = 4,
    kSphere = 5,
    kSrgb = 6,
    kLightBvh = 7,
    kSobol = 8,
    kMicrofacet = 9
};

/// kMicrofacet's material kinds (input word 1).
enum ParityMicrofacetKind : std::uint32_t
{
    kParityConductor = 0, // words 5, 6: alphaX, alphaY; 8-10: eta; 11-13: k
    kParityRoughDielectric = 1, // word 5: alpha; 7: ior
    kParityGltfPbr = 2 // word 5: alpha; 7: metallic; 8-10: base colour; 14: f0
};

struct ParityLayout
{
    std::uint32_t inputWords;
    std::uint32_t outputWords;
};
inline constexpr ParityLayout kParityLayouts[] = {{3, 8},  {7, 3}, {3, 13}, {10, 7}, {3, 2},
                                                  {10, 3}, {1, 1}, {8, 3},  {3, 8}, {15, 8}};

inline std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }
inline float asFloat(std::uint32_t u) { return std::bit_cast<float>(u); }
inline vec3 vec3At(const std::vector<std::uint32_t>& w, std::size_t i)
{
    return {asFloat(w[i]), asFloat(w[i + 1]), asFloat(w[i + 2])};
}

/// Runs `mode` on the shared engine's device over `inputs` (inputWords per case); returns outputWords per
/// case. `lights` and `lightBvh` fill the light bindings (a placeholder each when absent). `sharedCases` > 0
/// runs that many cases on the one case of `inputs` (the kernel reads it at input stride 0): kMicrofacet draws
/// a million samples of one material so.
std::vector<std::uint32_t> runParity(ParityMode mode, const std::vector<std::uint32_t>& inputs,
                                     const std::vector<LightData>& lights = {},
                                     const LightBvh* lightBvh = nullptr, std::uint32_t sharedCases = 0);
} // namespace rt::gpu::test
