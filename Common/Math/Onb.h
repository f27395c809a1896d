// The orthonormal basis of Shared/Onb.h (one algorithm for both engines), with C++ conveniences.
#pragma once

#include "Shared/Onb.h"

namespace rt
{
/// Orthonormal basis around a unit vector `w`: local (x, y, z) -> world x u + y v + z w.
struct Onb : shader::Onb
{
    explicit Onb(const vec3& n) : shader::Onb(shader::onbFromNormal(n)) {}

    vec3 toWorld(const vec3& local) const { return shader::onbToWorld(*this, local); }
};
} // namespace rt
