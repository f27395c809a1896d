#include "App/Gui/Theme.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace rt::gui
{
namespace
{
void applyColours(bool dark)
{
    ImGuiStyle& style = ImGui::GetStyle();
    if (dark)
        ImGui::StyleColorsDark(&style);
    else
        ImGui::StyleColorsLight(&style);
    // The three panes tile the window: square outer corners, soft controls.
    style.WindowRounding = 0.0f;
    style.WindowBorderSize = 0.0f;
    style.FrameRounding = 4.0f;
    style.GrabRounding = 4.0f;
    style.PopupRounding = 4.0f;
    style.TabRounding = 4.0f;
    style.FramePadding = ImVec2(8.0f, 3.0f);
    style.ItemSpacing = ImVec2(8.0f, 5.0f);
    style.WindowPadding = ImVec2(12.0f, 10.0f);
    style.Colors[ImGuiCol_PlotHistogram] = dark ? ImVec4(0.30f, 0.62f, 0.95f, 1.0f) : ImVec4(0.20f, 0.48f, 0.85f, 1.0f);
}

const FontChoice& fontNamed(const std::string& name)
{
    const auto& fonts = availableFonts();
    const auto it = std::find_if(fonts.begin(), fonts.end(), [&](const FontChoice& f) { return f.name == name; });
    return it == fonts.end() ? fonts.front() : *it;
}

void buildFontAtlas(const DisplaySettings& display)
{
    ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
    atlas.Clear();
    const FontChoice& font = fontNamed(display.font);
    if (!font.file.empty() && atlas.AddFontFromFileTTF(font.file.string().c_str(), display.fontSize))
        return;
    ImFontConfig config;
    config.SizePixels = display.fontSize;
    atlas.AddFontDefault(&config);
}
} // namespace

const std::vector<FontChoice>& availableFonts()
{
    static const std::vector<FontChoice> fonts = [] {
        const FontChoice candidates[] = {
            {"DejaVu Sans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
            {"DejaVu Sans Mono", "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"},
            {"Noto Sans", "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf"},
            {"Noto Sans Mono", "/usr/share/fonts/truetype/noto/NotoSansMono-Regular.ttf"},
        };
        std::vector<FontChoice> found;
        for (const FontChoice& c : candidates)
            if (std::error_code ec; std::filesystem::is_regular_file(c.file, ec))
                found.push_back(c);
        found.push_back({"ProggyClean (built in)", {}});
        return found;
    }();
    return fonts;
}

void Theme::apply(const DisplaySettings& display)
{
    if (m_applied == display)
        return;
    if (!m_applied || m_applied->dark != display.dark)
        applyColours(display.dark);
    if (!m_applied || m_applied->font != display.font || m_applied->fontSize != display.fontSize)
    {
        buildFontAtlas(display);
        // Before the first frame the backend has no font texture yet and makes it itself in NewFrame.
        if (m_applied)
        {
            ImGui_ImplOpenGL3_DestroyFontsTexture();
            ImGui_ImplOpenGL3_CreateFontsTexture();
        }
    }
    m_applied = display;
}
} // namespace rt::gui
