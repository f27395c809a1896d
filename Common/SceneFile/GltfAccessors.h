// Typed reads of glTF accessors (glTF 2.0 spec §3.6.2 "Accessors"), every byte they touch checked against its
// bufferView and buffer first, so that a corrupt or hostile file fails with a message instead of reading past
// its data. Sparse accessors (§3.6.2.3) are read with their substitutions applied.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "SceneFile/GltfFile.h"

namespace rt
{
/// The elements of accessor `index`, `components` numbers each (1 for SCALAR, 2 for VEC2, 3 for VEC3, 4 for VEC4),
/// flattened, as double. The accessor's type must have that many components. Float components are read as
/// written; integer components as their values, or, for a `normalized` accessor, mapped to [0, 1] (unsigned) or
/// [-1, 1] (signed) by the spec's equations (c / 255, max(c / 127, -1), ...). Data is little-endian (§3.6.2.2).
/// An accessor without a bufferView reads as zeros (then its sparse substitutions).
/// `usedAs` is the JSON pointer of the reference ("/meshes/0/primitives/1/attributes/POSITION"), for errors.
/// Throws SceneError naming the accessor (/accessors/N) or its bufferView: an index out of range, a type of a
/// different size, an unknown component type, a bufferView or buffer that does not exist, bytes beyond the
/// bufferView or the buffer, a stride shorter than an element, a sparse index out of range.
std::vector<double> readGltfAccessor(const GltfDocument& doc, int index, int components, const std::string& usedAs);

/// The vertex indices of accessor `index` (§3.7.2.1: SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT),
/// each checked to be below `vertexCount`. Throws SceneError as readGltfAccessor does, and for another component
/// type or an index out of range (naming the element and the value).
std::vector<std::uint32_t> readGltfIndices(const GltfDocument& doc, int index, std::size_t vertexCount,
                                           const std::string& usedAs);

/// Elements an accessor without a bufferView may have (they are zeros, made in memory: the limit stops a
/// count of 10^18 written in a file from asking for that much memory).
inline constexpr std::size_t kMaxGltfZeroAccessorCount = std::size_t{1} << 24;
} // namespace rt
