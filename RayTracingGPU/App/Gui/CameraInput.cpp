#include "App/Gui/CameraInput.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace rt::gpu::gui
{
namespace
{
constexpr float kFastMove = 4.0f; // Shift
constexpr float kSlowMove = 0.25f; // Ctrl
constexpr float kDegreesPerPixel = 0.2f; // mouse look
constexpr float kFovPerWheelStep = 2.0f; // degrees
} // namespace

void applyCameraInput(GLFWwindow* window, Controls& controls, float distance)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard)
    {
        const auto down = [window](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        const vec3 direction(down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                             down(GLFW_KEY_W) - down(GLFW_KEY_S));
        if (direction != vec3(0.0f))
        {
            if (down(GLFW_KEY_LEFT_SHIFT) + down(GLFW_KEY_RIGHT_SHIFT) > 0.0f)
                distance *= kFastMove;
            if (down(GLFW_KEY_LEFT_CONTROL) + down(GLFW_KEY_RIGHT_CONTROL) > 0.0f)
                distance *= kSlowMove;
            controls.moveCamera(distance * direction);
        }
    }
    if (!io.WantCaptureMouse)
    {
        if (io.MouseDown[0] && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
            controls.turnCamera(kDegreesPerPixel * io.MouseDelta.x, -kDegreesPerPixel * io.MouseDelta.y);
        if (io.MouseWheel != 0.0f)
            controls.setFov(controls.fov() - kFovPerWheelStep * io.MouseWheel);
    }
}
} // namespace rt::gpu::gui
