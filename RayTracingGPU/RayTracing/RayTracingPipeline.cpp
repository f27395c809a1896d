#include "RayTracing/RayTracingPipeline.h"

#include <vector>

#include "Check.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Check.h"
#include "Vulkan/ShaderModule.h"
#include "Vulkan/Specialization.h"

namespace rt::gpu
{
namespace
{
VkRayTracingShaderGroupCreateInfoKHR group(VkRayTracingShaderGroupTypeKHR type)
{
    VkRayTracingShaderGroupCreateInfoKHR g{VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
    g.type = type;
    g.generalShader = VK_SHADER_UNUSED_KHR;
    g.closestHitShader = VK_SHADER_UNUSED_KHR;
    g.anyHitShader = VK_SHADER_UNUSED_KHR;
    g.intersectionShader = VK_SHADER_UNUSED_KHR;
    return g;
}

enum StageIndex : std::uint32_t
{
    RayGen,
    Miss,
    ShadowMiss,
    TriangleHit,
    SphereIntersection,
    SphereHit,
    MediumIntersection,
    MediumHit,
    StageCount
};

struct Stage
{
    const char* file;
    VkShaderStageFlagBits stage;
};

constexpr Stage kStages[StageCount] = {
    {nullptr, VK_SHADER_STAGE_RAYGEN_BIT_KHR}, // the caller's
    {"Background.rmiss.spv", VK_SHADER_STAGE_MISS_BIT_KHR},
    {"Shadow.rmiss.spv", VK_SHADER_STAGE_MISS_BIT_KHR},
    {"Triangle.rchit.spv", VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR},
    {"Sphere.rint.spv", VK_SHADER_STAGE_INTERSECTION_BIT_KHR},
    {"Sphere.rchit.spv", VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR},
    {"Medium.rint.spv", VK_SHADER_STAGE_INTERSECTION_BIT_KHR},
    {"Medium.rchit.spv", VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR},
};
} // namespace

PathTracingShaders::PathTracingShaders(const vk::Device& device, const std::filesystem::path& shaderDir,
                                       const char* rayGenFile, std::initializer_list<const char*> extraRayGenFiles)
{
    for (const Stage& s : kStages)
        m_modules.emplace_back(device, shaderDir / (s.file ? s.file : rayGenFile));
    for (const char* file : extraRayGenFiles)
        m_extraRayGens.emplace_back(device, shaderDir / file);
}

std::uint32_t extraRayGenGroup(const HitGroupLayout& hitGroups, std::uint32_t i)
{
    return 1 + kMissGroupCount + hitGroups.count() + i;
}

vk::Pipeline createPathTracingPipeline(const vk::Device& device, const vk::PipelineLayout& layout,
                                       const PathTracingShaders& shaders, std::span<const std::uint32_t> constants,
                                       const HitGroupLayout& hitGroups)
{
    const vk::Specialization specialization(constants);

    // Only the stages of the groups below: a scene without spheres compiles no sphere intersection shader.
    std::vector<VkPipelineShaderStageCreateInfo> stageInfos;
    const auto addStage = [&](VkShaderStageFlagBits stage, const vk::ShaderModule& module) {
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = stage;
        info.module = module.Handle();
        info.pName = "main";
        info.pSpecializationInfo = specialization.info();
        stageInfos.push_back(info);
        return static_cast<std::uint32_t>(stageInfos.size() - 1);
    };
    const auto stage = [&](StageIndex i) { return addStage(kStages[i].stage, shaders.modules()[i]); };

    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
    groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR));
    groups.back().generalShader = stage(RayGen);
    // Miss groups in the order of the kMiss* constants.
    static_assert(shader::kMissBackground == 0 && shader::kMissShadow == 1 && kMissGroupCount == 2);
    groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR));
    groups.back().generalShader = stage(Miss);
    groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR));
    groups.back().generalShader = stage(ShadowMiss);
    // Hit groups in the order of HitGroupLayout's records, only those of `hitGroups`.
    if (hitGroups.has(HitGroupKind::Triangles))
    {
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR));
        groups.back().closestHitShader = stage(TriangleHit);
    }
    if (hitGroups.has(HitGroupKind::Spheres))
    {
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR));
        groups.back().intersectionShader = stage(SphereIntersection);
        groups.back().closestHitShader = stage(SphereHit);
    }
    if (hitGroups.has(HitGroupKind::Media))
    {
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR));
        groups.back().intersectionShader = stage(MediumIntersection);
        groups.back().closestHitShader = stage(MediumHit);
    }
    RT_CHECK_EQ(groups.size(), extraRayGenGroup(hitGroups, 0));
    for (const vk::ShaderModule& rayGen : shaders.extraRayGens())
    {
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR));
        groups.back().generalShader = addStage(VK_SHADER_STAGE_RAYGEN_BIT_KHR, rayGen);
    }

    VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
    info.stageCount = static_cast<std::uint32_t>(stageInfos.size());
    info.pStages = stageInfos.data();
    info.groupCount = static_cast<std::uint32_t>(groups.size());
    info.pGroups = groups.data();
    info.maxPipelineRayRecursionDepth = 1;
    info.layout = layout.Handle();
    VkPipeline pipeline = VK_NULL_HANDLE;
    vk::check(vkCreateRayTracingPipelinesKHR(device.Handle(), VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info, nullptr,
                                             &pipeline),
              "vkCreateRayTracingPipelinesKHR");
    return vk::Pipeline(device, pipeline);
}
} // namespace rt::gpu
