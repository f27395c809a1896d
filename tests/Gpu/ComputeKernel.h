// Runs a test compute shader on the engine's device: storage buffers at bindings 0..n-1 (host-visible, filled
// from host data), push constants, a 1-D grid; returns the contents of one buffer afterwards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "Engine/GpuContext.h"

namespace rt::gpu::test
{
struct KernelBuffer
{
    const void* data; // null: zero-filled
    std::size_t bytes;
};

/// Dispatches `groupCount` workgroups of `spirv` with `buffers` bound at bindings 0, 1, ... and returns the
/// bytes of buffer `resultBinding` after the dispatch. Throws rt::Error on failure.
std::vector<std::byte> runKernel(const GpuContext& context, const std::filesystem::path& spirv,
                                 const std::vector<KernelBuffer>& buffers, std::size_t resultBinding,
                                 const void* pushConstants, std::uint32_t pushBytes, std::uint32_t groupCount);
} // namespace rt::gpu::test
