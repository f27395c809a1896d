// restir-di's ray-tracing pipeline (Shaders/Restir/): per specialisation (PipelineSpecialization, the megakernel's
// key, with kSpecIdRestir = 1), one pipeline with three raygens, Restir/Candidates.rgen (group 0), Spatial.rgen and
// Shade.rgen (the last groups), over the megakernel's miss and hit stages, on PathTracingPipeline's set 0 and push
// constants; an SBT per raygen. An iteration (one sample per pixel) is every band of each pass in turn: spatial
// reuse reads the neighbours' results of the candidates pass. Spatial reuse has a pass of its own so that the
// shading pass's path loop does not carry the combination's registers.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <span>

#include "Engine/PathTracingPipeline.h"
#include "RayTracing/RayTracingPipeline.h"
#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/Pipeline.h"

namespace rt::gpu
{
enum class RestirPass
{
    Candidates, // candidates, visibility, temporal reuse
    Spatial, // spatial reuse: the final reservoirs
    Shade // the camera path with the resampled direct light, the accumulation image
};

/// An iteration's passes, in order.
inline constexpr RestirPass kRestirPasses[] = {RestirPass::Candidates, RestirPass::Spatial, RestirPass::Shade};

class RestirPipeline final
{
    struct Compiled;

public:
    /// Loads the shaders; compiles nothing yet. `layout` (which must outlive this) gives the set and pipeline
    /// layouts and the specialisation of a render. Throws rt::AssetError for a missing shader, rt::DeviceError
    /// when the driver rejects a module.
    RestirPipeline(const vk::Device& device, const std::filesystem::path& shaderDir, const PathTracingPipeline& layout);
    RestirPipeline(const RestirPipeline&) = delete;
    RestirPipeline& operator=(const RestirPipeline&) = delete;
    ~RestirPipeline();

    /// Compiles the pipeline a render with `uniforms` of `scene` needs, unless it exists; true at its first call
    /// for that pipeline (as PathTracingPipeline::prepare). Throws rt::DeviceError when the driver rejects it.
    bool prepare(const shader::RenderUniforms& uniforms, const PipelineScene& scene) const;
    /// Pipelines compiled so far.
    std::size_t compiledCount() const { return m_compiled.size(); }

    /// Records `pass` of sample `sampleIndex` over `extent` (a band of rows: positions from `firstRow` on in the
    /// row order of `rowInterleave`, Shared/BandOrder.h), with `sets` bound from set 0 (whose uniform buffer holds
    /// `uniforms` and whose restir buffers are the frame's); `history`: the final reservoirs hold the last
    /// iteration. Ordered before whatever comes next.
    void recordPass(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets, const shader::RenderUniforms& uniforms,
                    const PipelineScene& scene, RestirPass pass, std::uint32_t sampleIndex, VkExtent2D extent,
                    std::uint32_t firstRow, std::uint32_t rowInterleave, bool history) const;

private:
    const Compiled& compiled(const PipelineSpecialization& key) const;

    const vk::Device* m_device;
    const PathTracingPipeline* m_layout;
    PathTracingShaders m_shaders; // Candidates.rgen, the megakernel's miss and hit stages, Spatial.rgen, Shade.rgen
    mutable std::map<PipelineSpecialization, std::unique_ptr<Compiled>> m_compiled;
};
} // namespace rt::gpu
