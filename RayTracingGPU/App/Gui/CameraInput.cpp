#include "App/Gui/CameraInput.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "Scene/CameraMoves.h"

namespace rt::gpu::gui
{
void applyCameraInput(GLFWwindow* window, Controls& controls, float distance)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard)
    {
        const auto down = [window](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
        const MoveKeys keys{.forward = down(GLFW_KEY_W), .back = down(GLFW_KEY_S), .right = down(GLFW_KEY_D),
                            .left = down(GLFW_KEY_A), .up = down(GLFW_KEY_E), .down = down(GLFW_KEY_Q),
                            .fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT),
                            .slow = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL)};
        if (const vec3 move = keyMove(keys, distance); move != vec3(0.0f))
            controls.moveCamera(move);
    }
    if (!io.WantCaptureMouse)
    {
        if (io.MouseDown[0] && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
            controls.turnCamera(kTurnDegreesPerPixel * io.MouseDelta.x, -kTurnDegreesPerPixel * io.MouseDelta.y);
        if (io.MouseWheel != 0.0f)
            controls.setFov(controls.fov() - kFovDegreesPerWheelStep * io.MouseWheel);
    }
}
} // namespace rt::gpu::gui
