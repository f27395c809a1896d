#include "App/Gui/CameraInput.h"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace rt::gui
{
namespace
{
constexpr float kFastMove = 4.0f; // Shift
constexpr float kSlowMove = 0.25f; // Ctrl
constexpr float kDegreesPerPixel = 0.2f; // a drag
constexpr float kFovPerWheelStep = 2.0f; // degrees
} // namespace

void applyCameraInput(Session& session, const ImagePointer& pointer, double seconds)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantTextInput)
    {
        // ImGui 1.86's GLFW backend keeps io.KeysDown by GLFW key code.
        const auto down = [](int key) { return ImGui::IsKeyDown(key) ? 1.0f : 0.0f; };
        const vec3 direction(down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                             down(GLFW_KEY_W) - down(GLFW_KEY_S));
        if (direction != vec3(0.0f))
        {
            float distance = session.cameraSpeed() * float(std::min(seconds, 0.1));
            if (io.KeyShift)
                distance *= kFastMove;
            if (io.KeyCtrl)
                distance *= kSlowMove;
            session.applyCamera({.move = distance * direction});
        }
    }
    if (pointer.dragging && (pointer.dragX != 0.0f || pointer.dragY != 0.0f))
        session.applyCamera({.yawDegrees = kDegreesPerPixel * pointer.dragX, .pitchDegrees = -kDegreesPerPixel * pointer.dragY});
    if (pointer.wheel != 0.0f)
        if (const std::optional<CameraDesc> view = session.viewCamera())
            session.setFov(view->vfovDegrees - kFovPerWheelStep * pointer.wheel);
}
} // namespace rt::gui
