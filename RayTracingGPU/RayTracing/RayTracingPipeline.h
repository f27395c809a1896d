// The path tracer's ray-tracing pipeline. Shader groups, in SBT order:
//   0  raygen   RayGen.rgen         camera samples and the iterative bounce loop (or RayGenCost.rgen: timed)
//   1  miss     Background.rmiss    constant or gradient background           = kMissBackground
//   2  miss     Shadow.rmiss        a shadow ray reached its light           = kMissShadow
//   3  hit      Triangle.rchit      triangle BLASes (meshes, quads)        = kHitGroupTriangles
//   4  hit      Sphere.rint/.rchit  procedural geometry 0 (spheres)        = kHitGroupSpheres
//   5  hit      Medium.rint/.rchit  procedural geometry 1 (constant media) = kHitGroupMedia
// Maximum recursion depth 1: hit shaders never trace, raygen loops over bounces.
#pragma once

#include <filesystem>

#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu
{
inline constexpr std::uint32_t kMissGroupCount = 2;

/// Creates the pipeline from the SPIR-V files in `shaderDir`, with `rayGenFile` as group 0. Throws
/// rt::AssetError for a missing shader, rt::DeviceError when the driver rejects the pipeline.
vk::Pipeline createPathTracingPipeline(const vk::Device& device, const vk::PipelineLayout& layout,
                                       const std::filesystem::path& shaderDir,
                                       const char* rayGenFile = "RayGen.rgen.spv");
} // namespace rt::gpu
