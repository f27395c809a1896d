// Device selection on fabricated devices: every shortfall is named, preferences and --device are honoured.
#include <gtest/gtest.h>

#include "Error.h"
#include "Vulkan/DeviceSelection.h"

namespace rt::vk
{
namespace
{
constexpr std::uint32_t kApi13 = (1u << 22) | (3u << 12);
constexpr std::uint32_t kApi11 = (1u << 22) | (1u << 12);

DeviceFeatures allFeatures()
{
    DeviceFeatures f;
    for (const FeatureRequirement& r : kRequiredFeatures)
        f.*r.member = true;
    return f;
}

DeviceCandidate capable(std::uint32_t index, std::string name, DeviceType type)
{
    DeviceCandidate c;
    c.index = index;
    c.name = std::move(name);
    c.type = type;
    c.apiVersion = kApi13;
    for (const char* e : kRequiredExtensions)
        c.extensions.emplace_back(e);
    c.extensions.emplace_back("VK_KHR_swapchain");
    c.features = allFeatures();
    c.computeQueue = true;
    return c;
}

bool mentions(const std::vector<std::string>& list, const std::string& text)
{
    for (const std::string& s : list)
        if (s == text)
            return true;
    return false;
}

TEST(DeviceSelection, CapableDeviceLacksNothing)
{
    EXPECT_TRUE(judge(capable(0, "rtx", DeviceType::DiscreteGpu)).suitable());
}

TEST(DeviceSelection, NamesEveryMissingExtensionAndFeatureField)
{
    DeviceCandidate c = capable(0, "old gpu", DeviceType::DiscreteGpu);
    c.extensions = {"VK_KHR_swapchain", "VK_KHR_deferred_host_operations"};
    c.features.rayTracingPipeline = false;
    c.features.scalarBlockLayout = false;
    const DeviceVerdict v = judge(c);
    EXPECT_FALSE(v.suitable());
    EXPECT_TRUE(mentions(v.missing, "extension VK_KHR_ray_tracing_pipeline"));
    EXPECT_TRUE(mentions(v.missing, "extension VK_KHR_acceleration_structure"));
    EXPECT_FALSE(mentions(v.missing, "extension VK_KHR_deferred_host_operations"));
    EXPECT_TRUE(mentions(v.missing, "feature VkPhysicalDeviceRayTracingPipelineFeaturesKHR::rayTracingPipeline"));
    EXPECT_TRUE(mentions(v.missing, "feature VkPhysicalDeviceVulkan12Features::scalarBlockLayout"));
    EXPECT_EQ(v.missing.size(), 4u);
}

TEST(DeviceSelection, EachRequiredFeatureIsChecked)
{
    for (const FeatureRequirement& r : kRequiredFeatures)
    {
        DeviceCandidate c = capable(0, "gpu", DeviceType::DiscreteGpu);
        c.features.*r.member = false;
        const DeviceVerdict v = judge(c);
        ASSERT_EQ(v.missing.size(), 1u) << r.field;
        EXPECT_EQ(v.missing[0], std::string("feature ") + r.featureStruct + "::" + r.field);
    }
}

TEST(DeviceSelection, NamesOldApiAndMissingComputeQueue)
{
    DeviceCandidate c = capable(0, "gpu", DeviceType::IntegratedGpu);
    c.apiVersion = kApi11;
    c.computeQueue = false;
    const DeviceVerdict v = judge(c);
    EXPECT_TRUE(mentions(v.missing, "Vulkan 1.2 (has 1.1)"));
    EXPECT_TRUE(mentions(v.missing, "a queue family with VK_QUEUE_COMPUTE_BIT"));
}

TEST(DeviceSelection, PrefersDiscreteOverIntegratedOverCpu)
{
    const std::vector<DeviceCandidate> devices = {capable(0, "llvmpipe", DeviceType::Cpu),
                                                  capable(1, "igpu", DeviceType::IntegratedGpu),
                                                  capable(2, "dgpu", DeviceType::DiscreteGpu)};
    EXPECT_EQ(selectDevice(devices, std::nullopt), 2u);
    EXPECT_EQ(selectDevice({devices[0], devices[1]}, std::nullopt), 1u);
}

TEST(DeviceSelection, SkipsUnsuitablePreferredDevice)
{
    DeviceCandidate dgpu = capable(0, "dgpu without RT", DeviceType::DiscreteGpu);
    dgpu.features.accelerationStructure = false;
    EXPECT_EQ(selectDevice({dgpu, capable(1, "llvmpipe", DeviceType::Cpu)}, std::nullopt), 1u);
}

TEST(DeviceSelection, EachRankOfAHostTakesItsOwnGpuOfTheBestKind)
{
    // An MPI job's ranks on one host (their index: the share): one GPU each, never the CPU device or the slower
    // kind while a GPU of the best kind is there; ranks beyond the GPUs share them, in turn.
    DeviceCandidate broken = capable(2, "dgpu without RT", DeviceType::DiscreteGpu);
    broken.features.rayTracingPipeline = false;
    const std::vector<DeviceCandidate> devices = {capable(0, "llvmpipe", DeviceType::Cpu),
                                                  capable(1, "dgpu A", DeviceType::DiscreteGpu), broken,
                                                  capable(3, "igpu", DeviceType::IntegratedGpu),
                                                  capable(4, "dgpu B", DeviceType::DiscreteGpu)};
    EXPECT_EQ(selectDevice(devices, std::nullopt, {}, 0), 1u);
    EXPECT_EQ(selectDevice(devices, std::nullopt, {}, 1), 4u);
    EXPECT_EQ(selectDevice(devices, std::nullopt, {}, 2), 1u);
    EXPECT_EQ(selectDevice(devices, std::nullopt, {}, 3), 4u);
    EXPECT_EQ(selectDevice(devices, 3, {}, 1), 3u) << "--device overrides the rank's share";
    EXPECT_EQ(selectDevice({devices[0]}, std::nullopt, {}, 5), 0u) << "one device: every rank shares it";
}

TEST(DeviceSelection, HonoursRequestedIndex)
{
    const std::vector<DeviceCandidate> devices = {capable(0, "llvmpipe", DeviceType::Cpu),
                                                  capable(1, "dgpu", DeviceType::DiscreteGpu)};
    EXPECT_EQ(selectDevice(devices, 0), 0u);
}

TEST(DeviceSelection, RequestedIndexOutOfRangeIsUsageError)
{
    const std::vector<DeviceCandidate> devices = {capable(0, "llvmpipe", DeviceType::Cpu)};
    try
    {
        selectDevice(devices, 3);
        FAIL() << "expected UsageError";
    }
    catch (const UsageError& e)
    {
        EXPECT_NE(std::string(e.what()).find("--device 3 does not exist"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("llvmpipe"), std::string::npos) << e.what();
    }
}

TEST(DeviceSelection, RequestedUnsuitableDeviceSaysWhatItLacks)
{
    DeviceCandidate c = capable(0, "old", DeviceType::DiscreteGpu);
    c.features.bufferDeviceAddress = false;
    try
    {
        selectDevice({c}, 0);
        FAIL() << "expected DeviceError";
    }
    catch (const DeviceError& e)
    {
        EXPECT_NE(std::string(e.what()).find("VkPhysicalDeviceVulkan12Features::bufferDeviceAddress"),
                  std::string::npos)
            << e.what();
    }
}

TEST(DeviceSelection, NoSuitableDeviceListsEveryDeviceAndItsShortfall)
{
    DeviceCandidate a = capable(0, "gpu A", DeviceType::DiscreteGpu);
    a.extensions.clear();
    DeviceCandidate b = capable(1, "gpu B", DeviceType::IntegratedGpu);
    b.features.runtimeDescriptorArray = false;
    try
    {
        selectDevice({a, b}, std::nullopt);
        FAIL() << "expected DeviceError";
    }
    catch (const DeviceError& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find("device 0 'gpu A' (discrete GPU): lacks extension VK_KHR_acceleration_structure"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("device 1 'gpu B' (integrated GPU): lacks feature "
                               "VkPhysicalDeviceVulkan12Features::runtimeDescriptorArray"),
                  std::string::npos)
            << message;
        EXPECT_EQ(e.exitCode(), 5);
    }
}

TEST(DeviceSelection, NoDeviceAtAllIsDeviceError)
{
    EXPECT_THROW(selectDevice({}, std::nullopt), DeviceError);
}

TEST(DeviceSelection, HeadlessNeedsNoPresentation)
{
    DeviceCandidate c = capable(0, "compute only", DeviceType::DiscreteGpu);
    c.extensions = {std::begin(kRequiredExtensions), std::end(kRequiredExtensions)};
    c.presentQueue = false;
    EXPECT_TRUE(judge(c).suitable());
    EXPECT_EQ(selectDevice({c}, std::nullopt), 0u);
}

TEST(DeviceSelection, WindowNeedsSwapchainAndAPresentingQueue)
{
    const DeviceRequirements window{.presentation = true};
    DeviceCandidate headless = capable(0, "no present", DeviceType::DiscreteGpu);
    headless.extensions = {std::begin(kRequiredExtensions), std::end(kRequiredExtensions)};
    const DeviceVerdict v = judge(headless, window);
    EXPECT_TRUE(mentions(v.missing, "extension VK_KHR_swapchain"));
    EXPECT_TRUE(mentions(v.missing, "a queue family with graphics, compute and presentation to the window's surface"));

    DeviceCandidate presenting = capable(1, "presents", DeviceType::Cpu);
    presenting.presentQueue = true;
    EXPECT_TRUE(judge(presenting, window).suitable());
    // The discrete GPU is preferred headless, but only the CPU device can present to the window.
    EXPECT_EQ(selectDevice({headless, presenting}, std::nullopt), 0u);
    EXPECT_EQ(selectDevice({headless, presenting}, std::nullopt, window), 1u);
    try
    {
        selectDevice({headless}, std::nullopt, window);
        FAIL() << "expected DeviceError";
    }
    catch (const DeviceError& e)
    {
        EXPECT_NE(std::string(e.what()).find("in a window"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("lacks extension VK_KHR_swapchain"), std::string::npos) << e.what();
    }
}
} // namespace
} // namespace rt::vk
