// Fitting a loaded mesh into a scene, in double, before its positions become float. An OBJ file may sit
// anywhere: a unit cube written at x = 1e7 has corners 1e7 +- 0.5, which float rounds to whole numbers, and
// a mesh 1e-7 wide is below what a scene's float epsilons resolve. Both engines build from the float
// positions, so fitting in float (or by an instance transform scaling 1e-7) gave each engine its own wrong
// mesh. Normalising the double coordinates first gives every finite mesh the same float positions, whatever
// its size and place.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "Math/Math.h"

namespace rt
{
/// The frame fitMesh maps a mesh into: the centre of its bounding box's floor (x and z mid-way, lowest y) at
/// the origin, and its fit height 1. The fit height is the mesh's height, but at least kFlatMeshRatio of its
/// widest extent, so a flat mesh (a floor plate: height 0) is fitted by its width instead of blown up: a
/// fitted mesh is at most 1 / kFlatMeshRatio = 2 fit units wide.
inline constexpr double kFlatMeshRatio = 0.5;

/// `positions` (finite, in any units) mapped into the fit frame above, then rounded to float. Empty when the
/// mesh cannot be fitted; `why` then says why (every vertex at one point, or extents too small for double to
/// divide by).
std::optional<std::vector<vec3>> fitMesh(std::span<const dvec3> positions, std::string& why);
} // namespace rt
