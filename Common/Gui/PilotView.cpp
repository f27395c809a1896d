#include "Gui/PilotView.h"

#include <imgui.h>

namespace rt::gui
{
void drawPilot(const compare::AutoChoice& choice)
{
    ImGui::PushTextWrapPos(0.0f);
    if (choice.tooShort)
    {
        ImGui::TextDisabled("kept %s: the render is too short for a pilot (its share would measure nothing)",
                            choice.chosen.name().c_str());
        ImGui::PopTextWrapPos();
        return;
    }
    ImGui::TextDisabled("chose %s in %.2f s (%dx%d, %d spp per candidate)%s", choice.chosen.name().c_str(),
                        choice.pilotWallSeconds, choice.width, choice.height, choice.spp,
                        choice.budgetSpent ? "; its budget ran out before every candidate" : "");
    ImGui::PopTextWrapPos();
    if (!ImGui::BeginTable("pilot", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit))
        return;
    for (const char* heading : {"strategy", "n", "relMSE", "1/(relMSE s)"})
        ImGui::TableSetupColumn(heading);
    ImGui::TableHeadersRow();
    for (const compare::PilotRow& row : choice.rows)
    {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s%s", row.strategy == choice.chosen ? "> " : "  ", row.strategy.name().c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%d", row.measurements);
        ImGui::TableNextColumn();
        if (row.measurements > 0 && !row.tooSlow)
            ImGui::Text("%.3g", row.relMse);
        else
            ImGui::TextDisabled(row.tooSlow ? "too slow" : "-");
        ImGui::TableNextColumn();
        ImGui::Text("%.4g", row.efficiency);
    }
    ImGui::EndTable();
}
} // namespace rt::gui
