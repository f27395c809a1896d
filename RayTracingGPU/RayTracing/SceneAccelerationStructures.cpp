#include "RayTracing/SceneAccelerationStructures.h"

#include <cstring>
#include <memory>

#include <spdlog/fmt/fmt.h>

#include "Check.h"
#include "Error.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"
#include "Vulkan/QueryPool.h"

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

/// The TLAS of `layout`'s instances over `blases`, ready to build: its instance buffer filled, the structure
/// created, the build info pointing at them (scratch left to the caller).
struct TlasBuild
{
    vk::Buffer instances;
    AccelerationStructure tlas;
    std::vector<VkAccelerationStructureGeometryKHR> geometries;
    VkAccelerationStructureBuildGeometryInfoKHR info{};
    VkAccelerationStructureBuildRangeInfoKHR range{};
    VkDeviceSize scratchSize = 0;
};

std::unique_ptr<TlasBuild> prepareTlas(const vk::Device& device, const SceneLayout& layout,
                                       const std::vector<AccelerationStructure>& blases)
{
    auto t = std::make_unique<TlasBuild>();
    std::vector<VkAccelerationStructureInstanceKHR> instances;
    for (const TlasInstanceDesc& d : layout.instances)
    {
        VkAccelerationStructureInstanceKHR instance{};
        instance.transform = toVulkan(d.worldFromObject);
        instance.instanceCustomIndex = d.record;
        instance.mask = 0xFF;
        instance.instanceShaderBindingTableRecordOffset = d.hitGroup;
        instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
        instance.accelerationStructureReference = blases[d.blas].address();
        instances.push_back(instance);
    }
    const VkDeviceSize instanceBytes = instances.size() * sizeof(VkAccelerationStructureInstanceKHR);
    t->instances = vk::Buffer(device, instanceBytes,
                              VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                  VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                              vk::MemoryUse::Upload);
    if (instanceBytes > 0)
        std::memcpy(t->instances.mapped(), instances.data(), instanceBytes);

    VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    geometry.geometry.instances.data.deviceAddress = t->instances.address();
    t->geometries = {geometry};
    const std::vector<std::uint32_t> instanceCount{static_cast<std::uint32_t>(instances.size())};
    t->info = buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, t->geometries);
    const VkAccelerationStructureBuildSizesInfoKHR sizes = buildSizes(device, t->info, instanceCount);
    t->tlas = AccelerationStructure(device, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                    sizes.accelerationStructureSize);
    t->info.dstAccelerationStructure = t->tlas.Handle();
    t->range = {instanceCount[0], 0, 0, 0};
    t->scratchSize = sizes.buildScratchSize;
    return t;
}

/// Timestamps 0, 1, 2 around the BLAS and TLAS builds, where the queue has them.
class BuildTimer
{
public:
    explicit BuildTimer(const vk::Device& device)
        : m_device(&device), m_timed(device.properties().timestampValidBits > 0)
    {
        if (m_timed)
            m_queries = vk::QueryPool(device, 3);
    }
    void reset(VkCommandBuffer cmd) const
    {
        if (m_timed)
            vkCmdResetQueryPool(cmd, m_queries.Handle(), 0, 3);
    }
    void mark(VkCommandBuffer cmd, std::uint32_t query) const
    {
        if (m_timed)
            vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, m_queries.Handle(), query);
    }
    /// Seconds between marks `first` and `first + 1` (after the submission), or -1 without timestamps.
    double seconds(std::uint32_t first) const
    {
        return m_timed ? m_queries.secondsBetween(first, m_device->properties().limits.timestampPeriod) : -1.0;
    }

private:
    const vk::Device* m_device;
    bool m_timed;
    vk::QueryPool m_queries;
};

/// Records the builds of `blasInfos` (if any) and then of the TLAS, one scratch buffer for both, and waits.
void runBuilds(const vk::Device& device, const vk::CommandPool& pool,
               std::vector<VkAccelerationStructureBuildGeometryInfoKHR>& blasInfos,
               const std::vector<const VkAccelerationStructureBuildRangeInfoKHR*>& blasRanges,
               const std::vector<VkDeviceSize>& scratchOffsets, VkDeviceSize blasScratch, TlasBuild& tlas,
               AsBuildTimes* times)
{
    const VkDeviceSize scratchAlignment =
        std::max<VkDeviceSize>(device.properties().accelerationStructure.minAccelerationStructureScratchOffsetAlignment, 1);
    // The TLAS build may reuse the BLAS scratch memory after the barrier between them.
    VkDeviceAddress scratchBase = 0;
    const vk::Buffer scratch =
        scratchBuffer(device, std::max(blasScratch, tlas.scratchSize), scratchAlignment, scratchBase);
    for (std::size_t i = 0; i < blasInfos.size(); ++i)
        blasInfos[i].scratchData.deviceAddress = scratchBase + scratchOffsets[i];
    tlas.info.scratchData.deviceAddress = scratchBase;
    const VkAccelerationStructureBuildRangeInfoKHR* tlasRanges = &tlas.range;

    const BuildTimer timer(device);
    vk::submitAndWait(device, pool, [&](VkCommandBuffer cmd) {
        timer.reset(cmd);
        timer.mark(cmd, 0);
        if (!blasInfos.empty())
        {
            vkCmdBuildAccelerationStructuresKHR(cmd, static_cast<std::uint32_t>(blasInfos.size()), blasInfos.data(),
                                                blasRanges.data());
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                              VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                              VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                              VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                                  VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
        }
        timer.mark(cmd, 1);
        vkCmdBuildAccelerationStructuresKHR(cmd, 1, &tlas.info, &tlasRanges);
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                          VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
        timer.mark(cmd, 2);
    });
    if (times)
    {
        times->blasGpuSeconds = blasInfos.empty() ? -1.0 : timer.seconds(0);
        times->tlasGpuSeconds = timer.seconds(1);
    }
}
} // namespace

SceneAccelerationStructures buildAccelerationStructures(const vk::Device& device, const vk::CommandPool& pool,
                                                        const SceneLayout& layout, const GeometryAddresses& geometry,
                                                        AsBuildTimes* times)
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
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> blasRanges;
    for (const BlasInput& input : inputs)
        blasRanges.push_back(input.ranges.data());

    // Top level: one instance per TlasInstanceDesc; the instance buffer is read by the build directly.
    const std::unique_ptr<TlasBuild> tlas = prepareTlas(device, layout, out.blases);
    runBuilds(device, pool, blasInfos, blasRanges, scratchOffsets, scratchTotal, *tlas, times);
    out.instances = std::move(tlas->instances);
    out.tlas = std::move(tlas->tlas);
    return out;
}

void rebuildTlas(const vk::Device& device, const vk::CommandPool& pool, const SceneLayout& layout,
                 SceneAccelerationStructures& structures, AsBuildTimes* times)
{
    checkLimits(device, layout);
    RT_CHECK_EQ(structures.blases.size(), layout.blases.size());
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> noBlases;
    const std::unique_ptr<TlasBuild> tlas = prepareTlas(device, layout, structures.blases);
    runBuilds(device, pool, noBlases, {}, {}, 0, *tlas, times);
    structures.instances = std::move(tlas->instances);
    structures.tlas = std::move(tlas->tlas);
}
} // namespace rt::gpu
