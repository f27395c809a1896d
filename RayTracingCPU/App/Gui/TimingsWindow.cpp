#include "App/Gui/TimingsWindow.h"

#include <cstdint>
#include <string>

#include <imgui.h>
#include <spdlog/fmt/fmt.h>

namespace rt::gui
{
namespace
{
constexpr EngineKind kEngines[] = {EngineKind::Single, EngineKind::Multi, EngineKind::Gpu};

/// How many times faster than single core `engine` ran this row's work; empty without both timings.
std::string speedUp(const TimingRow& row, EngineKind engine)
{
    const auto& single = row.engines[std::size_t(EngineKind::Single)];
    const auto& other = row.engines[std::size_t(engine)];
    if (!single || !other || other->lastSeconds <= 0.0)
        return {};
    return fmt::format("{} {:.1f}x", engine == EngineKind::Gpu ? "GPU" : "multi", single->lastSeconds / other->lastSeconds);
}
} // namespace

bool drawTimings(Session& session)
{
    const TimingsTable& table = session.timings();
    if (ImGui::SmallButton("Clear"))
        session.clearTimings();
    ImGui::SameLine();
    ImGui::TextDisabled("tracing time of the latest render and its Mpaths/s; hover a time for the best of n; * the "
                        "window redrew for input during the render (render again untouched for a clean time)");
    // Every column follows its widest cell as timings arrive; a pane too narrow scrolls rather than clips.
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    const std::vector<const Setting*> columns = timingColumns();
    // Scene, size, the settings, one per engine, the ratio.
    if (!ImGui::BeginTable("timings", int(2 + columns.size() + std::size(kEngines) + 1), flags))
        return table.rows().empty();
    bool latestVisible = table.rows().empty();
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableSetupColumn("Scene");
    ImGui::TableSetupColumn("Size");
    for (const Setting* setting : columns)
        ImGui::TableSetupColumn(std::string(setting->label).c_str());
    for (EngineKind e : kEngines)
        ImGui::TableSetupColumn(engineLabel(e));
    ImGui::TableSetupColumn("vs single core");
    ImGui::TableHeadersRow();

    const ImU32 fastest = ImGui::GetColorU32(ImVec4(0.25f, 0.70f, 0.35f, 0.35f));
    // A new timing scrolls its row into view once; the user's own scrolling is left alone in between.
    static std::uint64_t shownRevision = 0;
    const bool scrollToLatest = table.revision() != shownRevision;
    shownRevision = table.revision();
    for (std::size_t index = 0; index < table.rows().size(); ++index)
    {
        const TimingRow& row = table.rows()[index];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.key.scene.id.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%dx%d", row.key.settings.width, row.key.settings.height());
        for (const Setting* setting : columns)
        {
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(setting->text(row.key.settings).c_str());
        }

        std::size_t best = row.engines.size();
        for (std::size_t e = 0; e < row.engines.size(); ++e)
            if (row.engines[e] && (best == row.engines.size() || row.engines[e]->lastSeconds < row.engines[best]->lastSeconds))
                best = e;
        for (std::size_t e = 0; e < row.engines.size(); ++e)
        {
            ImGui::TableNextColumn();
            const auto& cell = row.engines[e];
            if (!cell)
            {
                ImGui::TextDisabled("-");
                continue;
            }
            if (e == best)
                ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, fastest);
            const bool disturbed = cell->redraws.onInput > 0;
            ImGui::BeginGroup();
            ImGui::Text("%.3f s%s", cell->lastSeconds, disturbed ? " *" : "");
            ImGui::TextDisabled("%.2f Mpaths/s", cell->mpathsPerSecond);
            ImGui::EndGroup();
            if (index == table.latestRow())
            {
                // A timing is the row's tallest cell (two lines): the row is in view when all of it is.
                const ImDrawList& draw = *ImGui::GetWindowDrawList();
                latestVisible = ImGui::GetItemRectMin().y >= draw.GetClipRectMin().y &&
                                ImGui::GetItemRectMax().y <= draw.GetClipRectMax().y;
                if (scrollToLatest)
                    ImGui::SetScrollHereY(1.0f); // the cursor is below the two lines: the whole row comes into view
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("best %.3f s of %d render%s\n%s\nthe window drew %d frame%s during it%s",
                                  cell->bestSeconds, cell->renders, cell->renders == 1 ? "" : "s",
                                  cell->device.c_str(), cell->redraws.total, cell->redraws.total == 1 ? "" : "s",
                                  disturbed ? fmt::format(", {} for input: their drawing took CPU time from the "
                                                          "render, which this time includes",
                                                          cell->redraws.onInput)
                                                  .c_str()
                                            : " (paced: every 0.5 s)");
        }
        ImGui::TableNextColumn();
        for (EngineKind e : {EngineKind::Multi, EngineKind::Gpu})
            if (const std::string s = speedUp(row, e); !s.empty())
                ImGui::TextUnformatted(s.c_str());
    }
    ImGui::EndTable();
    return latestVisible;
}
} // namespace rt::gui
