// The warps for C++ callers in namespace rt: the code is Shared/Warps.h, which the shaders compile too.
#pragma once

#include "Shared/Warps.h"

namespace rt
{
using shader::cosineHemispherePdf;
using shader::sampleCosineHemisphere;
using shader::sampleUniformCone;
using shader::sampleUniformDiskConcentric;
using shader::sampleUniformSphere;
using shader::sampleUniformTriangle;
using shader::sinCos2Pi;
using shader::uniformConePdf;
using shader::uniformSpherePdf;
} // namespace rt
