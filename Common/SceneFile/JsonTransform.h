// An instance's placement in the JSON scene format: a list of steps multiplied in the order written,
// worldFromObject = step_0 * step_1 * ... * step_n, so the last step acts first on the object's points (as
// matrices compose, and as pbrt's nested transforms read).
//
//   {"translate": [x, y, z]}            {"scale": s} or {"scale": [sx, sy, sz]}
//   {"rotate_x": degrees} (also _y, _z)  {"rotate": {"axis": [x, y, z], "degrees": d}}
//   {"matrix": [[m00, m01, m02, m03], [m10, ...], [m20, ...]]}  (rows; the last row 0 0 0 1 is implied,
//                                                                and may be written as a fourth row)
// Rotations are counter-clockwise looking down the axis towards the origin (right-handed).
#pragma once

#include "Math/Transform.h"
#include "SceneFile/JsonNode.h"

namespace rt
{
/// Throws SceneError at the offending step for an unknown step, a bad value, or a matrix that is not an
/// invertible affine map.
Transform readTransform(const JsonNode& steps);
} // namespace rt
