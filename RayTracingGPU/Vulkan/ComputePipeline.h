// A compute pipeline of one shader module (entry point "main").
#pragma once

#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"
#include "Vulkan/ShaderModule.h"
#include "Vulkan/Specialization.h"

namespace rt::vk
{
/// Throws rt::DeviceError when the driver rejects the pipeline.
Pipeline createComputePipeline(const Device& device, const PipelineLayout& layout, const ShaderModule& module,
                               const Specialization& specialization);
} // namespace rt::vk
