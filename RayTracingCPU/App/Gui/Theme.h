// The thesis' "UI parameters": dark or light colours and the UI font, applied to Dear ImGui between frames
// (a new font size means a new font atlas, which may not change inside a frame).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "App/Gui/PanelSettings.h"

namespace rt::gui
{
struct FontChoice
{
    std::string name;
    std::filesystem::path file; // empty: Dear ImGui's built-in ProggyClean
};

/// The fonts this machine has (Debian's DejaVu and Noto when installed), then the built-in one.
const std::vector<FontChoice>& availableFonts();

class Theme
{
public:
    /// Applies what changed since the last call. Call outside a frame (before GlWindow::beginFrame).
    void apply(const DisplaySettings& display);

private:
    std::optional<DisplaySettings> m_applied;
};
} // namespace rt::gui
