// Choosing the physical device: every device is judged against the engine's requirements and every
// shortfall is named down to the extension or the feature struct and field (vk-bootstrap's idea), so that
// "no suitable device" always says why. Pure logic on plain descriptions: tested without a GPU.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rt::vk
{
/// The features the engine enables, as one device reports them.
struct DeviceFeatures
{
    bool accelerationStructure = false;
    bool rayTracingPipeline = false;
    bool bufferDeviceAddress = false;
    bool runtimeDescriptorArray = false;
    bool shaderSampledImageArrayNonUniformIndexing = false;
    bool descriptorBindingPartiallyBound = false;
    bool descriptorBindingVariableDescriptorCount = false;
    bool scalarBlockLayout = false;
    // Optional: the window's heatmap of per-pixel cost (clockARB), hidden without it.
    bool shaderSubgroupClock = false; // VkPhysicalDeviceShaderClockFeaturesKHR, needs kShaderClockExtension
    // Optional: the wavefront integrator's indirect ray-tracing launches (the megakernel runs without it).
    bool rayTracingPipelineTraceRaysIndirect = false;
};

/// One feature the engine needs: where Vulkan reports it and where DeviceFeatures keeps it.
struct FeatureRequirement
{
    const char* featureStruct;
    const char* field;
    bool DeviceFeatures::*member;
};

inline constexpr FeatureRequirement kRequiredFeatures[] = {
    {"VkPhysicalDeviceAccelerationStructureFeaturesKHR", "accelerationStructure",
     &DeviceFeatures::accelerationStructure},
    {"VkPhysicalDeviceRayTracingPipelineFeaturesKHR", "rayTracingPipeline", &DeviceFeatures::rayTracingPipeline},
    {"VkPhysicalDeviceVulkan12Features", "bufferDeviceAddress", &DeviceFeatures::bufferDeviceAddress},
    {"VkPhysicalDeviceVulkan12Features", "runtimeDescriptorArray", &DeviceFeatures::runtimeDescriptorArray},
    {"VkPhysicalDeviceVulkan12Features", "shaderSampledImageArrayNonUniformIndexing",
     &DeviceFeatures::shaderSampledImageArrayNonUniformIndexing},
    {"VkPhysicalDeviceVulkan12Features", "descriptorBindingPartiallyBound",
     &DeviceFeatures::descriptorBindingPartiallyBound},
    {"VkPhysicalDeviceVulkan12Features", "descriptorBindingVariableDescriptorCount",
     &DeviceFeatures::descriptorBindingVariableDescriptorCount},
    {"VkPhysicalDeviceVulkan12Features", "scalarBlockLayout", &DeviceFeatures::scalarBlockLayout},
};

/// Device extensions the engine enables. Buffer device address, descriptor indexing, scalar block layout and
/// SPIR-V 1.4 are core in the required API version 1.2; acceleration structures need deferred host operations.
inline constexpr const char* kRequiredExtensions[] = {
    "VK_KHR_acceleration_structure",
    "VK_KHR_ray_tracing_pipeline",
    "VK_KHR_deferred_host_operations",
};

/// Window mode only: presenting to a surface.
inline constexpr const char* kPresentationExtension = "VK_KHR_swapchain";
/// Optional, enabled when present with DeviceFeatures::shaderSubgroupClock.
inline constexpr const char* kShaderClockExtension = "VK_KHR_shader_clock";

/// What the caller needs beyond the ray tracer itself.
struct DeviceRequirements
{
    /// The window: kPresentationExtension and one queue family with graphics, compute and presentation to the
    /// window's surface (one queue traces, rasterises the preview and the panel, and presents).
    bool presentation = false;
};

enum class DeviceType
{
    Other,
    IntegratedGpu,
    DiscreteGpu,
    VirtualGpu,
    Cpu
};

const char* toString(DeviceType type);

/// What selection needs to know about one physical device.
struct DeviceCandidate
{
    std::uint32_t index = 0; // in vkEnumeratePhysicalDevices order (what --device N counts)
    std::string name;
    DeviceType type = DeviceType::Other;
    std::uint32_t apiVersion = 0; // VK_MAKE_API_VERSION
    std::vector<std::string> extensions;
    DeviceFeatures features;
    bool computeQueue = false; // a queue family with VK_QUEUE_COMPUTE_BIT
    bool presentQueue = false; // a queue family with graphics, compute and presentation to the surface asked about
};

/// A device and everything it lacks (empty: it can run the engine).
struct DeviceVerdict
{
    DeviceCandidate candidate;
    std::vector<std::string> missing;

    bool suitable() const { return missing.empty(); }
};

/// Every reason `candidate` cannot run the engine, e.g. "extension VK_KHR_ray_tracing_pipeline" or
/// "feature VkPhysicalDeviceVulkan12Features::scalarBlockLayout".
DeviceVerdict judge(const DeviceCandidate& candidate, const DeviceRequirements& requirements = {});

/// Picks `requested` if given (it must exist and be suitable), else among the suitable devices of the most
/// preferred type (discrete, integrated, virtual, other, CPU), in index order, the one `share` names modulo their
/// count (an MPI rank's index on its host: one GPU per rank, ranks beyond the GPUs sharing them). Returns the index
/// into `candidates`.
/// Throws rt::UsageError for a requested index that does not exist, rt::DeviceError listing every device
/// and what it lacks when nothing fits.
std::size_t selectDevice(const std::vector<DeviceCandidate>& candidates, std::optional<int> requested,
                         const DeviceRequirements& requirements = {}, int share = 0);

/// One line per device: index, name, type, and "ok" or what it lacks.
std::string describeDevices(const std::vector<DeviceCandidate>& candidates,
                            const DeviceRequirements& requirements = {});
} // namespace rt::vk
