// The path tracer's ray-tracing pipelines. Shader groups, in SBT order:
//   0  raygen   RayGen.rgen         the megakernel: camera samples and the iterative bounce loop (or
//                                   RayGenCost.rgen: timed; or Wavefront/Extend.rgen: the wavefront's path rays)
//   1  miss     Background.rmiss    constant or gradient background           = kMissBackground
//   2  miss     Shadow.rmiss        a shadow ray reached its light           = kMissShadow
//   then the hit groups a HitGroupLayout names, in its order (each only when the layout has it):
//      hit      Triangle.rchit      triangle BLASes (meshes, quads)          HitGroupKind::Triangles
//      hit      Sphere.rint/.rchit  procedural geometry 0 (spheres)          HitGroupKind::Spheres
//      hit      Medium.rint/.rchit  procedural geometry 1 (constant media)   HitGroupKind::Media
//   last, further raygens: the wavefront's Wavefront/Shadow.rgen (its shadow rays); restir-di's Spatial.rgen and
//   Shade.rgen after its Candidates.rgen
// Maximum recursion depth 1: hit shaders never trace, raygen loops over bounces.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <vector>

#include "RayTracing/HitGroupLayout.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"
#include "Vulkan/ShaderModule.h"

namespace rt::gpu
{
inline constexpr std::uint32_t kMissGroupCount = 2;

/// The SPIR-V modules of the pipeline's stages, loaded once; every specialisation compiles from them.
class PathTracingShaders final
{
public:
    /// Loads the stages from `shaderDir`, with `rayGenFile` as group 0 and `extraRayGenFiles` as the last groups,
    /// in order. Throws rt::AssetError for a missing or malformed shader, rt::DeviceError when the driver rejects
    /// a module.
    PathTracingShaders(const vk::Device& device, const std::filesystem::path& shaderDir,
                       const char* rayGenFile = "RayGen.rgen.spv",
                       std::initializer_list<const char*> extraRayGenFiles = {});

    const std::vector<vk::ShaderModule>& modules() const { return m_modules; }
    /// The further raygens' modules, in order.
    const std::vector<vk::ShaderModule>& extraRayGens() const { return m_extraRayGens; }

private:
    std::vector<vk::ShaderModule> m_modules; // in the order of the stages above
    std::vector<vk::ShaderModule> m_extraRayGens;
};

/// The shader group of further raygen `i` of a pipeline with `hitGroups` (after the first raygen, the miss
/// groups, the hit groups and the further raygens before it).
std::uint32_t extraRayGenGroup(const HitGroupLayout& hitGroups, std::uint32_t i);

/// Compiles the pipeline from `shaders` with the specialization constants `constants` (constant id i takes
/// constants[i], in every stage; ids a stage does not declare are ignored) and the hit groups of `hitGroups`
/// (with only their stages). Throws rt::DeviceError when the driver rejects the pipeline.
vk::Pipeline createPathTracingPipeline(const vk::Device& device, const vk::PipelineLayout& layout,
                                       const PathTracingShaders& shaders, std::span<const std::uint32_t> constants,
                                       const HitGroupLayout& hitGroups);
} // namespace rt::gpu
