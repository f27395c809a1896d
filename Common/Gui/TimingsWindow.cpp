#include "Gui/TimingsWindow.h"

#include <cstdint>
#include <string>

#include <imgui.h>
#include <spdlog/fmt/fmt.h>

#include "Gui/EngineLabel.h"
#include "Image/Metrics.h"

namespace rt::gui
{
namespace
{
/// How many times faster than single core `engine` ran this row's work; empty without both timings.
std::string speedUp(const TimingRow& row, std::size_t engine)
{
    const auto& single = row.engines[std::size_t(EngineKind::Single)];
    const auto& other = row.engines[engine];
    if (engine == std::size_t(EngineKind::Single) || !single || !other || other->lastSeconds <= 0.0)
        return {};
    return fmt::format("{:.1f}x", single->lastSeconds / other->lastSeconds);
}

/// The engine of `row` with the shortest latest time (row.engines.size() when it has none).
std::size_t fastestEngine(const TimingRow& row)
{
    std::size_t best = row.engines.size();
    for (std::size_t e = 0; e < row.engines.size(); ++e)
        if (row.engines[e] && (best == row.engines.size() || row.engines[e]->lastSeconds < row.engines[best]->lastSeconds))
            best = e;
    return best;
}

/// The relMSE cell: the value once measured, else where its reference stands.
void relMseCell(const TimingRow& row, const EngineTiming& cell)
{
    const auto& reference = row.reference;
    if (cell.relMse && reference)
    {
        ImGui::Text("%.3g", *cell.relMse);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("mean (I - R)^2 / (R^2 + %.2g) against a %d-spp reference on %s%s\nits own relMSE %.3g "
                              "is part of this value%s",
                              kRelMseEpsilon, reference->task.spp, engineLabel(reference->task.engine),
                              reference->fromCache ? ", from the reference cache" : "", reference->ownRelMse,
                              *cell.relMse < 3.0 * reference->ownRelMse
                                  ? ": at less than 3x, this mostly measures the reference"
                                  : "");
        return;
    }
    if (!reference)
        ImGui::TextDisabled("-");
    else if (reference->state == RowReference::State::Failed)
    {
        ImGui::TextDisabled("failed");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the reference failed: %s", reference->error.c_str());
    }
    else
        ImGui::TextDisabled("waiting");
}

void renderTimeTooltip(const EngineTiming& cell, bool disturbed)
{
    ImGui::SetTooltip("best %.3f s of %d render%s\n%s\nthe window drew %d frame%s during it%s", cell.bestSeconds,
                      cell.renders, cell.renders == 1 ? "" : "s", cell.device.c_str(), cell.redraws.total,
                      cell.redraws.total == 1 ? "" : "s",
                      disturbed ? fmt::format(", {} for input: their drawing took CPU time from the render, which "
                                              "this time includes",
                                              cell.redraws.onInput)
                                      .c_str()
                                : " (paced: every 0.5 s)");
}
} // namespace

TimingsDrawn drawTimings(const TimingsTable& table)
{
    TimingsDrawn drawn;
    drawn.clearClicked = ImGui::SmallButton("Clear");
    ImGui::SameLine();
    ImGui::TextDisabled("render: tracing alone (hover for the best of n; * the window redrew for input during it); "
                        "build and compile: the setup before it; relMSE against a reference at 4x the spp");
    // Every column follows its widest cell as timings arrive; a pane too narrow scrolls rather than clips.
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    const std::vector<const Setting*> columns = timingColumns();
    // Scene and size, a line per engine (engine, render, Mpaths/s, relMSE, efficiency, build, compile, vs single),
    // then the settings: the times stay in view in a narrow pane.
    drawn.latestVisible = table.rows().empty();
    if (!ImGui::BeginTable("timings", int(2 + columns.size() + 8), flags))
        return drawn;
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableSetupColumn("Scene");
    ImGui::TableSetupColumn("Size");
    for (const char* name :
         {"Engine", "Render", "Mpaths/s", "relMSE", "1/(relMSE s)", "Build", "Compile", "vs single core"})
        ImGui::TableSetupColumn(name);
    for (const Setting* setting : columns)
        ImGui::TableSetupColumn(std::string(setting->label).c_str());
    ImGui::TableHeadersRow();

    const ImU32 fastest = ImGui::GetColorU32(ImVec4(0.25f, 0.70f, 0.35f, 0.35f));
    // A new timing scrolls its row into view once; the user's own scrolling is left alone in between.
    static std::uint64_t shownRevision = 0;
    const bool scrollToLatest = table.revision() != shownRevision;
    shownRevision = table.revision();
    for (std::size_t index = 0; index < table.rows().size(); ++index)
    {
        const TimingRow& row = table.rows()[index];
        const std::size_t best = fastestEngine(row);
        bool first = true; // the work's columns on its first engine's line only
        for (std::size_t e = 0; e < row.engines.size(); ++e)
        {
            const auto& cell = row.engines[e];
            if (!cell)
                continue;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            if (first)
            {
                ImGui::TextUnformatted(row.key.scene.id.c_str());
                if (row.key.camera)
                {
                    ImGui::SameLine();
                    ImGui::TextDisabled("(moved)");
                    if (ImGui::IsItemHovered())
                        ImGui::SetTooltip("seen from a moved camera (its settings in --state-json), not the scene's");
                }
            }
            ImGui::TableNextColumn();
            if (first)
                ImGui::Text("%dx%d", row.key.settings.width, row.key.settings.height());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(engineLabel(EngineKind(e)));
            ImGui::TableNextColumn();
            if (e == best)
                ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, fastest);
            const bool disturbed = cell->redraws.onInput > 0;
            ImGui::Text("%.3f s%s", cell->lastSeconds, disturbed ? " *" : "");
            if (ImGui::IsItemHovered())
                renderTimeTooltip(*cell, disturbed);
            if (index == table.latestRow())
            {
                const ImDrawList& draw = *ImGui::GetWindowDrawList();
                drawn.latestVisible = ImGui::GetItemRectMin().y >= draw.GetClipRectMin().y &&
                                ImGui::GetItemRectMax().y <= draw.GetClipRectMax().y;
                if (scrollToLatest)
                    ImGui::SetScrollHereY(1.0f);
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", cell->mpathsPerSecond);
            ImGui::TableNextColumn();
            relMseCell(row, *cell);
            ImGui::TableNextColumn();
            if (cell->relMse)
                ImGui::Text("%.3g", cell->efficiency());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f s", cell->buildSeconds);
            ImGui::TableNextColumn();
            if (cell->compileSeconds)
            {
                ImGui::Text("%.3f s", *cell->compileSeconds);
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("this render compiled its pipelines first (a driver's first use of them); "
                                      "the render time leaves that out");
            }
            else
                ImGui::TextDisabled(EngineKind(e) == EngineKind::Gpu ? "cached" : "-");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(speedUp(row, e).c_str());
            for (const Setting* setting : columns)
            {
                ImGui::TableNextColumn();
                if (first)
                    ImGui::TextUnformatted(setting->text(row.key.settings).c_str());
            }
            first = false;
        }
    }
    ImGui::EndTable();
    return drawn;
}
} // namespace rt::gui
