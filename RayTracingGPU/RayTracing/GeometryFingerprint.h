// What the acceleration structures of a SceneLayout are built from, as two 64-bit hashes, so that a new scene
// whose geometry is the same as the last one's reuses its BLASes and TLAS (the window rebuilds the whole
// Scene when only a material or the Fresnel model changes; a scene file reloads when edited).
//   blases: the BLAS inputs: positions, triangles, AABBs (a sphere's or medium's bounds, not its centre or
//           density, which the shaders read from buffers uploaded anew) and the BLAS descriptions;
//   tlas:   the TLAS instances: BLAS, transform, record index (instanceCustomIndex) and hit record.
// Equal BLAS hashes let the BLASes stay; equal TLAS hashes as well let the TLAS stay. Pure (tested in
// tests/Gpu/SceneLayoutTest.cpp).
#pragma once

#include <compare>
#include <cstdint>

#include "RayTracing/SceneLayout.h"

namespace rt::gpu
{
struct GeometryFingerprint
{
    std::uint64_t blases = 0;
    std::uint64_t tlas = 0;

    auto operator<=>(const GeometryFingerprint&) const = default;
};

GeometryFingerprint fingerprintOf(const SceneLayout& layout);
} // namespace rt::gpu
