// Perlin noise for C++ callers in namespace rt: the noise is Shared/Perlin.h, which the shaders compile too;
// its tables (host only) are generated here, once per process from a fixed seed, and uploaded unchanged to the GPU.
#pragma once

#include "Math/Math.h"
#include "Shared/HostDevice.h"
#include "Shared/Perlin.h"

namespace rt
{
/// The process-wide tables, generated on first use from a fixed seed.
const shader::PerlinData& perlinTables();

using shader::perlinNoise;
using shader::perlinTurbulence;
} // namespace rt
