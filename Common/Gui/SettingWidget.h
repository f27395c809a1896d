// The panels' widget of a render setting, drawn from the settings table (Render/SettingsTable.h) so that both
// windows show the same label, words and tooltip: a combo of a Choice's words, a checkbox for OnOff. Dear ImGui;
// built only with the windows (RT_BUILD_GUI, library rt_setting_widget).
#pragma once

#include <optional>
#include <string>

#include "Render/SettingsTable.h"

namespace rt::gui
{
/// Draws `setting` of `settings` (a Choice or OnOff setting; others draw nothing) with the table's label and
/// tooltip. Returns the value the person picked, as Setting::assign reads it, when it differs from the current.
std::optional<std::string> settingWidget(const Setting& setting, const RenderSettings& settings);

/// Shows `text` wrapped at 30 font heights while the last item is hovered (disabled items too).
void itemTooltip(const char* text);
} // namespace rt::gui
