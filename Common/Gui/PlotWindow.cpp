#include "Gui/PlotWindow.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <imgui.h>
#include <spdlog/fmt/fmt.h>

#include "Gui/EngineLabel.h"

namespace rt::gui
{
namespace
{
constexpr const char* kXLabel = "render time (s)";
constexpr const char* kYLabel = "relMSE";

// Matplotlib's default cycle, as plot_convergence.py draws the saved figure: a line keeps its colour in both.
constexpr std::array<ImU32, 10> kColours = {
    IM_COL32(31, 119, 180, 255), IM_COL32(255, 127, 14, 255), IM_COL32(44, 160, 44, 255),
    IM_COL32(214, 39, 40, 255),  IM_COL32(148, 103, 189, 255), IM_COL32(140, 86, 75, 255),
    IM_COL32(227, 119, 194, 255), IM_COL32(127, 127, 127, 255), IM_COL32(188, 189, 34, 255),
    IM_COL32(23, 190, 207, 255)};

/// A log10 range, widened to half a decade around a single value.
struct LogRange
{
    double lo = std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::lowest();
    void add(double value)
    {
        lo = std::min(lo, std::log10(value));
        hi = std::max(hi, std::log10(value));
    }
    void pad()
    {
        if (hi - lo < 0.5)
        {
            const double mid = 0.5 * (lo + hi);
            lo = mid - 0.25;
            hi = mid + 0.25;
        }
        const double margin = 0.06 * (hi - lo);
        lo -= margin;
        hi += margin;
    }
    float at(double value, float from, float to) const
    {
        return from + float((std::log10(value) - lo) / (hi - lo)) * (to - from);
    }
};

/// Tick values inside the range: the decades, or 1, 2, 5 of each decade where fewer than two decades show.
std::vector<double> ticks(const LogRange& r)
{
    std::vector<double> out;
    const int first = int(std::floor(r.lo));
    const int last = int(std::ceil(r.hi));
    const bool fine = std::ceil(r.lo) > std::floor(r.hi) - 1.0; // fewer than two decades inside
    for (int k = first; k <= last; ++k)
        for (double m : fine ? std::vector<double>{1.0, 2.0, 5.0} : std::vector<double>{1.0})
        {
            const double v = m * std::pow(10.0, k);
            if (std::log10(v) >= r.lo && std::log10(v) <= r.hi)
                out.push_back(v);
        }
    return out;
}

std::string tickText(double v)
{
    return std::abs(std::log10(v)) < 3.0 ? fmt::format("{:g}", v) : fmt::format("{:.0e}", v);
}

struct DrawnPoint
{
    ImVec2 at;
    const PlotPoint* point;
    std::size_t line;
};
} // namespace

PlotDrawn drawConvergencePlot(const ConvergencePlot& plot, const RenderRequest& work, const std::string& saveName)
{
    PlotDrawn result;
    const std::vector<const PlotLine*> lines = plot.linesOf(work);
    const std::vector<std::string> labels = shortLabels(lines);
    std::size_t waiting = 0;
    LogRange x, y;
    for (const PlotLine* line : lines)
        for (const PlotPoint& p : line->points)
        {
            if (!p.error || p.error->relMse <= 0.0 || p.seconds <= 0.0)
            {
                waiting += p.unmeasured ? 1 : 0;
                continue;
            }
            x.add(p.seconds);
            y.add(p.error->relMse);
        }
    nlohmann::json& drawn = result.state;
    drawn = {{"x_label", kXLabel}, {"y_label", kYLabel}, {"lines", nlohmann::json::array()}, {"waiting", waiting}};

    result.saveClicked = ImGui::SmallButton("Save");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("write %s (the figure, by plot_convergence.py) and its points as CSV beside it",
                          saveName.c_str());
    ImGui::SameLine();
    if (waiting > 0)
        ImGui::TextDisabled("%zu point%s wait%s for a reference", waiting, waiting == 1 ? "" : "s",
                            waiting == 1 ? "s" : "");
    else
        ImGui::TextDisabled("a line per engine x strategy of this work");

    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x < 40.0f || size.y < 40.0f)
        return result;
    ImGui::InvisibleButton("plot", size);
    const bool hovered = ImGui::IsItemHovered();
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const float font = ImGui::GetFontSize();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 faint = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border);
    // Room for the y ticks' text at the left and the x ticks' and label below.
    const float left = origin.x + font * 3.2f;
    const float right = origin.x + size.x - font * 0.6f;
    const float top = origin.y + font * 1.3f;
    const float bottom = origin.y + size.y - font * 2.4f;
    draw.AddRect(ImVec2(left, top), ImVec2(right, bottom), grid);
    draw.AddText(ImVec2(origin.x, origin.y), text, kYLabel);
    const ImVec2 xLabelSize = ImGui::CalcTextSize(kXLabel);
    draw.AddText(ImVec2(0.5f * (left + right - xLabelSize.x), bottom + font * 1.2f), text, kXLabel);
    if (x.lo > x.hi)
    {
        const char* empty = "no relMSE yet: a reference renders when the window is idle";
        draw.AddText(ImVec2(left + font * 0.5f, 0.5f * (top + bottom) - font * 0.5f), faint, empty);
        return result;
    }
    x.pad();
    y.pad();
    drawn["x_range"] = {std::pow(10.0, x.lo), std::pow(10.0, x.hi)};
    drawn["y_range"] = {std::pow(10.0, y.lo), std::pow(10.0, y.hi)};
    draw.PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    for (double t : ticks(x))
    {
        const float px = x.at(t, left, right);
        draw.AddLine(ImVec2(px, top), ImVec2(px, bottom), grid);
        const std::string label = tickText(t);
        draw.AddText(ImVec2(px - 0.5f * ImGui::CalcTextSize(label.c_str()).x, bottom + 2.0f), faint, label.c_str());
    }
    for (double e : ticks(y))
    {
        const float py = y.at(e, bottom, top);
        draw.AddLine(ImVec2(left, py), ImVec2(right, py), grid);
        const std::string label = tickText(e);
        draw.AddText(ImVec2(left - ImGui::CalcTextSize(label.c_str()).x - 3.0f, py - 0.5f * font), faint, label.c_str());
    }

    std::vector<DrawnPoint> points;
    float legendY = top + 3.0f;
    for (std::size_t l = 0; l < lines.size(); ++l)
    {
        std::vector<const PlotPoint*> measured;
        for (const PlotPoint& p : lines[l]->points)
            if (p.error && p.error->relMse > 0.0 && p.seconds > 0.0)
                measured.push_back(&p);
        if (measured.empty())
            continue;
        std::stable_sort(measured.begin(), measured.end(),
                         [](const PlotPoint* a, const PlotPoint* b) { return a->seconds < b->seconds; });
        // By the lines drawn, as plot_convergence.py numbers the lines of the saved CSV.
        const ImU32 colour = kColours[drawn["lines"].size() % kColours.size()];
        std::vector<ImVec2> polyline;
        nlohmann::json json = nlohmann::json::array();
        for (const PlotPoint* p : measured)
        {
            const ImVec2 at(x.at(p->seconds, left, right), y.at(p->error->relMse, bottom, top));
            polyline.push_back(at);
            points.push_back({at, p, l});
            json.push_back({p->seconds, p->spp, p->error->relMse});
        }
        draw.AddPolyline(polyline.data(), int(polyline.size()), colour, ImDrawFlags_None, 1.5f);
        for (const DrawnPoint& d : points)
            if (d.line == l)
            {
                if (d.point->loopMean)
                    draw.AddCircle(d.at, 3.5f, colour, 0, 1.5f);
                else
                    draw.AddCircleFilled(d.at, 3.5f, colour);
            }
        // The legend, top right inside the axes.
        const ImVec2 labelSize = ImGui::CalcTextSize(labels[l].c_str());
        const float legendX = right - labelSize.x - font * 1.1f;
        draw.AddRectFilled(ImVec2(legendX, legendY + 0.3f * font), ImVec2(legendX + 0.6f * font, legendY + 0.9f * font),
                           colour);
        draw.AddText(ImVec2(legendX + 0.8f * font, legendY), text, labels[l].c_str());
        legendY += font + 1.0f;
        drawn["lines"].push_back({{"label", labels[l]},
                                  {"engine", rt::toString(lines[l]->engine)},
                                  {"colour", {colour & 0xff, (colour >> 8) & 0xff, (colour >> 16) & 0xff}},
                                  {"points", std::move(json)}});
    }
    draw.PopClipRect();

    if (hovered)
    {
        const ImVec2 mouse = ImGui::GetMousePos();
        const DrawnPoint* nearest = nullptr;
        float best = 8.0f * 8.0f;
        for (const DrawnPoint& d : points)
        {
            const float dx = d.at.x - mouse.x, dy = d.at.y - mouse.y;
            if (dx * dx + dy * dy < best)
            {
                best = dx * dx + dy * dy;
                nearest = &d;
            }
        }
        if (nearest)
        {
            const PlotPoint& p = *nearest->point;
            ImGui::SetTooltip("%s\n%d spp%s in %.3f s\nrelMSE %.4g (its %d-spp reference's own: %.3g)",
                              lines[nearest->line]->label().c_str(), p.spp,
                              p.loopMean ? " (loop rendering's mean)" : "", p.seconds, p.error->relMse,
                              p.reference.spp, p.referenceRelMse);
        }
    }
    return result;
}
} // namespace rt::gui
