#include "App/Gui/LabPanes.h"

#include <imgui.h>
#include <spdlog/fmt/fmt.h>

#include "Gui/PlotWindow.h"
#include "Gui/TimingsWindow.h"
#include "SceneFile/SceneFile.h"

namespace rt::gpu::gui
{
namespace
{
constexpr ImGuiWindowFlags kPaneFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoBringToFrontOnFocus;
} // namespace

LabPanesDrawn drawLabPanes(const WindowLayout& layout, float framebufferScale, const rt::gui::TimingsTable& table,
                           const rt::gui::ConvergencePlot& plot, const RenderRequest& work,
                           const rt::gui::ReferenceProgress& reference)
{
    const auto place = [framebufferScale](const PixelRect& r) {
        ImGui::SetNextWindowPos(ImVec2(float(r.x) / framebufferScale, float(r.y) / framebufferScale));
        ImGui::SetNextWindowSize(ImVec2(float(r.width) / framebufferScale, float(r.height) / framebufferScale));
    };
    LabPanesDrawn drawn;
    std::string title = "Timings of this session (the GPU's on its own clock)";
    if (reference.rendering)
        title += fmt::format("  |  reference for relMSE: {:.0f}% of {} spp{}", reference.fraction * 100.0,
                             reference.task.spp,
                             reference.waiting > 0 ? fmt::format(" ({} more waiting)", reference.waiting) : "");
    place(layout.timings);
    if (ImGui::Begin((title + "###timings").c_str(), nullptr, kPaneFlags))
    {
        const rt::gui::TimingsDrawn timings = rt::gui::drawTimings(table);
        drawn.latestTimingVisible = timings.latestVisible;
        drawn.clearClicked = timings.clearClicked;
    }
    ImGui::End();
    place(layout.plot);
    if (ImGui::Begin("Convergence: relMSE against time", nullptr, kPaneFlags | ImGuiWindowFlags_NoScrollbar))
    {
        rt::gui::PlotDrawn plotDrawn = rt::gui::drawConvergencePlot(plot, work, plotFileName(work));
        drawn.plot = std::move(plotDrawn.state);
        drawn.saveClicked = plotDrawn.saveClicked;
    }
    ImGui::End();
    return drawn;
}

std::string plotFileName(const RenderRequest& work)
{
    const RenderSettings& r = work.settings;
    return fmt::format("{}_{}x{}_depth{}_gpu_convergence.png", sceneShortName(work.scene.id), r.width, r.height(),
                       r.depth);
}
} // namespace rt::gpu::gui
