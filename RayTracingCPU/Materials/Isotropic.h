#pragma once

#include "Sampling/Warps.h"

namespace rt::cpu
{
/// The isotropic phase function of constant media (RTTNW §9): every direction equally likely.
inline vec3 sampleIsotropic(const vec2& u) { return sampleUniformSphere(u); }
inline constexpr float isotropicPdf() { return kInv4Pi; }
} // namespace rt::cpu
