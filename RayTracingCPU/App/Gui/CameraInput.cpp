#include "App/Gui/CameraInput.h"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "Scene/CameraMoves.h"

namespace rt::gui
{
void applyCameraInput(Session& session, const ImagePointer& pointer, double seconds)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantTextInput)
    {
        // ImGui 1.86's GLFW backend keeps io.KeysDown by GLFW key code.
        const auto down = [](int key) { return ImGui::IsKeyDown(key); };
        const MoveKeys keys{.forward = down(GLFW_KEY_W), .back = down(GLFW_KEY_S), .right = down(GLFW_KEY_D),
                            .left = down(GLFW_KEY_A), .up = down(GLFW_KEY_E), .down = down(GLFW_KEY_Q),
                            .fast = io.KeyShift, .slow = io.KeyCtrl};
        if (const vec3 move = keyMove(keys, session.cameraSpeed() * float(std::min(seconds, 0.1))); move != vec3(0.0f))
            session.applyCamera({.move = move});
    }
    if (pointer.dragging && (pointer.dragX != 0.0f || pointer.dragY != 0.0f))
        session.applyCamera({.yawDegrees = kTurnDegreesPerPixel * pointer.dragX, .pitchDegrees = -kTurnDegreesPerPixel * pointer.dragY});
    if (pointer.wheel != 0.0f)
        if (const std::optional<CameraDesc> view = session.viewCamera())
            session.setFov(view->vfovDegrees - kFovDegreesPerWheelStep * pointer.wheel);
}
} // namespace rt::gui
