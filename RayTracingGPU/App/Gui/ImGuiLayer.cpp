#include "App/Gui/ImGuiLayer.h"

#include "App/Gui/WindowState.h"

#include <algorithm>
#include <filesystem>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>
#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Vulkan/Check.h"
#include "Vulkan/CommandBuffer.h"

namespace rt::gpu::gui
{
namespace
{
void checkImGuiResult(VkResult result)
{
    if (result < 0)
        throw DeviceError(fmt::format("Dear ImGui's Vulkan backend: {}", vk::resultName(result)));
}

PFN_vkVoidFunction loadFunction(const char* name, void* instance)
{
    return vk::instanceProcAddr(static_cast<VkInstance>(instance), name);
}

struct FontFile
{
    const char* name;
    const char* path;
};

// Debian's fonts-dejavu-core (build.sh installs it); where a file is missing the font is not offered.
constexpr FontFile kFontFiles[] = {
    {"DejaVu Sans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
    {"DejaVu Sans Mono", "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"},
};

const std::vector<vk::DescriptorBinding>& fontBindings()
{
    static const std::vector<vk::DescriptorBinding> bindings = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
    return bindings;
}
} // namespace

ImGuiLayer::ImGuiLayer(const GpuContext& context, GLFWwindow* window, VkRenderPass renderPass,
                       std::uint32_t framesInFlight)
    : m_pool(context.device(), fontBindings(), 0)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini in whatever directory the app runs from
    ImGui::StyleColorsDark();
    io.Fonts->AddFontDefault();
    m_fontNames.push_back("ImGui default");
    for (const FontFile& font : kFontFiles)
        if (std::filesystem::exists(font.path) && io.Fonts->AddFontFromFileTTF(font.path, kPanelFontPixels))
            m_fontNames.push_back(font.name);
    const VkInstance instance = context.instance().Handle();
    if (!ImGui_ImplVulkan_LoadFunctions(loadFunction, instance))
        throw DeviceError("Dear ImGui's Vulkan backend could not load its Vulkan functions");
    ImGui_ImplGlfw_InitForVulkan(window, true);

    const vk::Device& device = context.device();
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = instance;
    info.PhysicalDevice = device.physical();
    info.Device = device.Handle();
    info.QueueFamily = device.queueFamily();
    info.Queue = device.queue();
    info.DescriptorPool = m_pool.Handle();
    info.Subpass = 0;
    info.MinImageCount = framesInFlight;
    info.ImageCount = framesInFlight; // the backend rotates its vertex buffers by this count, one per frame
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImGuiResult;
    ImGui_ImplVulkan_Init(&info, renderPass);
    vk::submitAndWait(device, context.commandPool(),
                      [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiLayer::~ImGuiLayer()
{
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::newFrame(bool darkStyle, int font, float fontScale)
{
    if (darkStyle != m_darkStyle)
    {
        darkStyle ? ImGui::StyleColorsDark() : ImGui::StyleColorsLight();
        m_darkStyle = darkStyle;
    }
    ImGuiIO& io = ImGui::GetIO();
    io.FontDefault = io.Fonts->Fonts[std::clamp(font, 0, io.Fonts->Fonts.Size - 1)];
    io.FontGlobalScale = fontScale;
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::render(VkCommandBuffer cmd)
{
    ImGui::Render();
    if (cmd != VK_NULL_HANDLE)
        ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}
} // namespace rt::gpu::gui
