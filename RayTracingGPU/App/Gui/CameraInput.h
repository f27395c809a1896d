// The interactive camera's input: WASD move, Q/E down/up, Shift x4, Ctrl x1/4, left-drag to look, wheel for
// the field of view, each through Controls (as the panel's camera widgets). Nothing happens while the panel
// has the keyboard or the mouse (typing a file name, dragging a slider).
#pragma once

#include "App/Gui/Controls.h"

struct GLFWwindow;

namespace rt::gpu::gui
{
/// Reads the keys' state and ImGui's mouse of this frame; `distance` is how far WASD moves in this frame at
/// normal speed (world units).
void applyCameraInput(GLFWwindow* window, Controls& controls, float distance);
} // namespace rt::gpu::gui
