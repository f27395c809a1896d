// A zlib stream (RFC 1950) compressed in pieces on several threads, as pigz does: each piece is a raw deflate
// stream of its own (RFC 1951), the pieces but the last end with a sync flush (byte-aligned, not final), and
// the adler-32 of the whole closes the stream. Any inflater reads it as one stream. The PNG of a render is
// written after the render, while every other core waits: compressed in pieces it keeps the cores busy
// (docs/notebook/PERFORMANCE.md §1).
#pragma once

#include <cstddef>
#include <vector>

namespace rt
{
/// `data` (length bytes) as a zlib stream at compression level `level` (0-9), compressed in `parts` pieces of
/// equal length on as many threads (parts >= 1; fewer when the data is shorter). Empty on a zlib failure.
std::vector<unsigned char> deflateInParts(const unsigned char* data, std::size_t length, int level, int parts);
} // namespace rt
