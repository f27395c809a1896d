// What the window shows, as a PNG: the back buffer of the frame just drawn (before it is presented).
#pragma once

#include <filesystem>

#include "App/Gui/GlWindow.h"

namespace rt::gui
{
/// Reads `size` pixels of the back buffer, turns them top-down and writes an RGBA PNG. Throws OutputError.
void saveScreenshot(const std::filesystem::path& path, FramebufferSize size);
} // namespace rt::gui
