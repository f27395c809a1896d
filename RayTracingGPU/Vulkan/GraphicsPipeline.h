// The window's graphics pipelines (the display pass, the rasterised preview): one vertex and one fragment
// shader into subpass 0 of a colour + depth render pass, triangle lists, no blending, no culling (quads and
// open meshes are seen from both sides), viewport and scissor set when drawing (they follow the window).
#pragma once

#include <filesystem>
#include <vector>

#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::vk
{
struct GraphicsPipelineDesc
{
    std::filesystem::path vertexShader; // SPIR-V files
    std::filesystem::path fragmentShader;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    bool depthTest = false; // test and write depth (LESS); the display pass covers everything and needs neither
};

/// Throws rt::AssetError for a missing shader, rt::DeviceError when the driver rejects the pipeline.
Pipeline createGraphicsPipeline(const Device& device, const GraphicsPipelineDesc& desc);
} // namespace rt::vk
