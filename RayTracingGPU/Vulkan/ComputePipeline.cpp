#include "Vulkan/ComputePipeline.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
Pipeline createComputePipeline(const Device& device, const PipelineLayout& layout, const ShaderModule& module,
                               const Specialization& specialization)
{
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.Handle();
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = specialization.info();
    info.layout = layout.Handle();
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateComputePipelines(device.Handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
          "vkCreateComputePipelines");
    return Pipeline(device, pipeline);
}
} // namespace rt::vk
