// Perlin gradient noise and turbulence as in RTTNW §5 (Perlin, "An Image Synthesizer", SIGGRAPH 1985;
// Hermite-smoothed trilinear interpolation of random gradients). The tables are Common's, shared with the
// GPU (Shaders/Textures/Perlin.glsl evaluates the same tables the same way).
#pragma once

#include "Math/Math.h"
#include "Shared/HostDevice.h"

namespace rt
{
/// The process-wide tables, generated on first use from a fixed seed.
const shader::PerlinData& perlinTables();

/// Noise in [-1, 1] at point p (world units).
float perlinNoise(const shader::PerlinData& tables, const vec3& p);

/// Sum of |depth| octaves of noise with halving weights, absolute value (RTTNW §5.7).
float perlinTurbulence(const shader::PerlinData& tables, const vec3& p, int depth = 7);
} // namespace rt
