#include "RayTracing/SceneAccelerationStructures.h"

#include <cstring>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"

namespace rt::gpu
{
namespace
{
using vk::alignUp;

/// The geometries and ranges of one BLAS; the build info points into `geometries`, so this does not move.
struct BlasInput
{
    std::vector<VkAccelerationStructureGeometryKHR> geometries;
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
    std::vector<std::uint32_t> primitiveCounts;

    void add(const VkAccelerationStructureGeometryKHR& geometry, std::uint32_t primitiveCount)
    {
        geometries.push_back(geometry);
        ranges.push_back({primitiveCount, 0, 0, 0});
        primitiveCounts.push_back(primitiveCount);
    }
};

BlasInput blasInput(const BlasDesc& blas, const GeometryAddresses& geometry)
{
    BlasInput input;
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.flags = VK_GEOMETRY_OPAQUE_BIT_KHR; // no any-hit shaders: closest hits only
    if (blas.kind == BlasDesc::Kind::Triangles)
    {
        g.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        auto& t = g.geometry.triangles;
        t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
        t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
        t.vertexData.deviceAddress = geometry.positions + VkDeviceAddress(blas.firstVertex) * sizeof(vec3);
        t.vertexStride = sizeof(vec3);
        t.maxVertex = blas.vertexCount > 0 ? blas.vertexCount - 1 : 0;
        t.indexType = VK_INDEX_TYPE_UINT32;
        t.indexData.deviceAddress = geometry.triangles + VkDeviceAddress(blas.firstTriangle) * sizeof(glm::uvec3);
        input.add(g, blas.triangleCount);
        return input;
    }
    g.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    auto& a = g.geometry.aabbs;
    a.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
    a.stride = sizeof(AabbRecord);
    // Geometry order fixes the hit group (SceneLayout.h): spheres first, then media.
    if (blas.sphereCount > 0)
    {
        a.data.deviceAddress = geometry.aabbs + VkDeviceAddress(blas.firstSphereAabb) * sizeof(AabbRecord);
        input.add(g, blas.sphereCount);
    }
    if (blas.mediumCount > 0)
    {
        a.data.deviceAddress = geometry.aabbs + VkDeviceAddress(blas.firstMediumAabb) * sizeof(AabbRecord);
        input.add(g, blas.mediumCount);
    }
    return input;
}

VkAccelerationStructureBuildGeometryInfoKHR buildInfo(VkAccelerationStructureTypeKHR type,
                                                      const std::vector<VkAccelerationStructureGeometryKHR>& geometries)
{
    VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    info.type = type;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = static_cast<std::uint32_t>(geometries.size());
    info.pGeometries = geometries.data();
    return info;
}

VkAccelerationStructureBuildSizesInfoKHR buildSizes(const vk::Device& device,
                                                    const VkAccelerationStructureBuildGeometryInfoKHR& info,
                                                    const std::vector<std::uint32_t>& primitiveCounts)
{
    VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    vkGetAccelerationStructureBuildSizesKHR(device.Handle(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                                            primitiveCounts.data(), &sizes);
    return sizes;
}

/// A device-local scratch buffer of `size` bytes whose returned address meets the device's alignment.
vk::Buffer scratchBuffer(const vk::Device& device, VkDeviceSize size, VkDeviceSize alignment, VkDeviceAddress& base)
{
    vk::Buffer scratch(device, size + alignment,
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                       vk::MemoryUse::DeviceLocal);
    base = alignUp(scratch.address(), alignment);
    return scratch;
}

VkTransformMatrixKHR toVulkan(const mat4& m)
{
    VkTransformMatrixKHR t;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 4; ++column)
            t.matrix[row][column] = m[column][row]; // glm is column-major, Vulkan's 3x4 is row-major
    return t;
}

void checkLimits(const vk::Device& device, const SceneLayout& layout)
{
    const auto& limits = device.properties().accelerationStructure;
    const std::string& name = device.properties().name;
    for (const BlasDesc& blas : layout.blases)
    {
        const std::uint64_t primitives = std::uint64_t(blas.triangleCount) + blas.sphereCount + blas.mediumCount;
        if (primitives > limits.maxPrimitiveCount)
            throw DeviceError(fmt::format("a BLAS of {} primitives exceeds maxPrimitiveCount {} of device '{}'",
                                          primitives, limits.maxPrimitiveCount, name));
    }
    if (layout.instances.size() > limits.maxInstanceCount)
        throw DeviceError(fmt::format("{} TLAS instances exceed maxInstanceCount {} of device '{}'",
                                      layout.instances.size(), limits.maxInstanceCount, name));
}
} // namespace

SceneAccelerationStructures buildAccelerationStructures(const vk::Device& device, const vk::CommandPool& pool,
                                                        const SceneLayout& layout, const GeometryAddresses& geometry)
{
    checkLimits(device, layout);
    const VkDeviceSize scratchAlignment =
        std::max<VkDeviceSize>(device.properties().accelerationStructure.minAccelerationStructureScratchOffsetAlignment, 1);
    SceneAccelerationStructures out;

    // Bottom level: sizes first, then one scratch buffer carved into aligned regions.
    std::vector<BlasInput> inputs;
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> blasInfos;
    std::vector<VkDeviceSize> scratchOffsets;
    VkDeviceSize scratchTotal = 0;
    inputs.reserve(layout.blases.size());
    for (const BlasDesc& blas : layout.blases)
    {
        inputs.push_back(blasInput(blas, geometry));
        VkAccelerationStructureBuildGeometryInfoKHR info =
            buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, inputs.back().geometries);
        const VkAccelerationStructureBuildSizesInfoKHR sizes = buildSizes(device, info, inputs.back().primitiveCounts);
        out.blases.emplace_back(device, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, sizes.accelerationStructureSize);
        info.dstAccelerationStructure = out.blases.back().Handle();
        blasInfos.push_back(info);
        scratchOffsets.push_back(scratchTotal);
        scratchTotal += alignUp(sizes.buildScratchSize, scratchAlignment);
    }

    // Top level: one instance per TlasInstanceDesc; the instance buffer is read by the build directly.
    std::vector<VkAccelerationStructureInstanceKHR> instances;
    for (const TlasInstanceDesc& d : layout.instances)
    {
        VkAccelerationStructureInstanceKHR instance{};
        instance.transform = toVulkan(d.worldFromObject);
        instance.instanceCustomIndex = d.record;
        instance.mask = 0xFF;
        instance.instanceShaderBindingTableRecordOffset = d.hitGroup;
        instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
        instance.accelerationStructureReference = out.blases[d.blas].address();
        instances.push_back(instance);
    }
    const VkDeviceSize instanceBytes = instances.size() * sizeof(VkAccelerationStructureInstanceKHR);
    out.instances = vk::Buffer(device, instanceBytes,
                               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                               vk::MemoryUse::Upload);
    if (instanceBytes > 0)
        std::memcpy(out.instances.mapped(), instances.data(), instanceBytes);

    VkAccelerationStructureGeometryKHR tlasGeometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    tlasGeometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    tlasGeometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    tlasGeometry.geometry.instances.data.deviceAddress = out.instances.address();
    const std::vector<VkAccelerationStructureGeometryKHR> tlasGeometries{tlasGeometry};
    const std::vector<std::uint32_t> instanceCount{static_cast<std::uint32_t>(instances.size())};
    VkAccelerationStructureBuildGeometryInfoKHR tlasInfo =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, tlasGeometries);
    const VkAccelerationStructureBuildSizesInfoKHR tlasSizes = buildSizes(device, tlasInfo, instanceCount);
    out.tlas = AccelerationStructure(device, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                     tlasSizes.accelerationStructureSize);
    tlasInfo.dstAccelerationStructure = out.tlas.Handle();

    // The TLAS build may reuse the BLAS scratch memory after the barrier between them.
    VkDeviceAddress scratchBase = 0;
    const vk::Buffer scratch = scratchBuffer(device, std::max(scratchTotal, tlasSizes.buildScratchSize),
                                             scratchAlignment, scratchBase);
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> blasRanges;
    for (std::size_t i = 0; i < blasInfos.size(); ++i)
    {
        blasInfos[i].scratchData.deviceAddress = scratchBase + scratchOffsets[i];
        blasRanges.push_back(inputs[i].ranges.data());
    }
    tlasInfo.scratchData.deviceAddress = scratchBase;
    const VkAccelerationStructureBuildRangeInfoKHR tlasRange{instanceCount[0], 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* tlasRanges = &tlasRange;

    vk::submitAndWait(device, pool, [&](VkCommandBuffer cmd) {
        if (!blasInfos.empty())
            vkCmdBuildAccelerationStructuresKHR(cmd, static_cast<std::uint32_t>(blasInfos.size()), blasInfos.data(),
                                                blasRanges.data());
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                          VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
        vkCmdBuildAccelerationStructuresKHR(cmd, 1, &tlasInfo, &tlasRanges);
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    });
    return out;
}
} // namespace rt::gpu
