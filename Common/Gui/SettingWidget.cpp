#include "Gui/SettingWidget.h"

#include <imgui.h>

namespace rt::gui
{
void itemTooltip(const char* text)
{
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

std::optional<std::string> settingWidget(const Setting& setting, const RenderSettings& settings)
{
    const std::string label(setting.label);
    const std::string current = setting.text(settings);
    std::optional<std::string> picked;
    switch (setting.type)
    {
    case SettingType::Choice:
        if (ImGui::BeginCombo(label.c_str(), current.c_str()))
        {
            for (const std::string_view word : setting.choices)
                if (ImGui::Selectable(std::string(word).c_str(), word == current) && word != current)
                    picked = std::string(word);
            ImGui::EndCombo();
        }
        break;
    case SettingType::OnOff:
        if (bool on = current == "on"; ImGui::Checkbox(label.c_str(), &on))
            picked = on ? "on" : "off";
        break;
    case SettingType::Integer:
    case SettingType::Real: return std::nullopt;
    }
    itemTooltip(std::string(setting.tooltip).c_str());
    return picked;
}
} // namespace rt::gui
