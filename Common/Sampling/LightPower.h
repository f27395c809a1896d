// The power of each emitter and the alias table that NEE's power selection draws from
// (Shared/LightSelection.h). Host only: both engines build the table from the scene once.
#pragma once

#include <vector>

#include "Scene/Scene.h"

namespace rt
{
using shader::AliasEntry;

/// Per emitter (Scene::lights[0, emitterCount())): its area times the luminance of its emission, which is
/// its emitted power up to the factor pi (and 2 for two-sided emitters, the same for every light of a
/// render). Emission textures count by their mean where it is known (solid, checker) and as 1 (an image) or
/// 1/2 (Perlin noise) where it is not.
std::vector<double> emitterPowers(const Scene& scene);

/// Vose's alias table (Vose 1991, IEEE TSE 17(9), §III) for the non-negative `weights`; all zero or empty
/// weights give the uniform table. Built in double: a slot's threshold and every pmf are exact to float.
std::vector<AliasEntry> makeAliasTable(const std::vector<double>& weights);

/// makeAliasTable(emitterPowers(scene)), or one uniform entry when the scene has no emitter (so the GPU's
/// buffer is never empty).
std::vector<AliasEntry> lightAliasTable(const Scene& scene);
} // namespace rt
