// The CPU window's camera input, as the GPU window's: W/A/S/D move forward, left, back, right and Q/E down and
// up (Shift x4, Ctrl x1/4) while no text field has the keyboard; a drag that began on the image turns the view;
// the wheel over the image zooms (the field of view). Each goes through the session's camera commands, the ones
// the camera= action calls, so every move renders again from the new view.
#pragma once

#include "App/Gui/ImageView.h"
#include "App/Gui/Session.h"

namespace rt::gui
{
/// Applies this frame's input; `seconds` since the previous frame (held to 0.1 s, so a paced frame after a pause
/// does not jump).
void applyCameraInput(Session& session, const ImagePointer& pointer, double seconds);
} // namespace rt::gui
