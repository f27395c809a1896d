#include "App/Gui/SettingsPanel.h"

#include <filesystem>
#include <thread>

#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/fmt/fmt.h>

#include "App/Gui/Theme.h"
#include "Cli/ActionGrammar.h"
#include "Gui/PilotView.h"
#include "Gui/SettingWidget.h"
#include "Render/MemoryBudget.h"
#include "Scenes/Catalogue.h"

namespace rt::gui
{
namespace
{
// Numeric fields apply on Enter (or a +/- click): every applied change starts a render, and a render per
// keystroke of "1000" would be three wasted ones.
constexpr ImGuiInputTextFlags kApplyOnEnter = ImGuiInputTextFlags_EnterReturnsTrue;

void tooltip(const char* text) { itemTooltip(text); }

/// An integer setting's field, applied on Enter.
void integerField(Session& session, const Setting& setting, int value, int step, int fastStep)
{
    if (ImGui::InputInt(std::string(setting.label).c_str(), &value, step, fastStep, kApplyOnEnter))
        session.setSetting(setting, std::to_string(value));
    tooltip(std::string(setting.tooltip).c_str());
}

/// Fields as wide as the panel allows with their labels still whole on their right.
void pushFieldWidth()
{
    ImGui::PushItemWidth(-(ImGui::CalcTextSize("Samples per pixel").x + ImGui::GetStyle().ItemInnerSpacing.x * 2.0f));
}
} // namespace

void SettingsPanel::draw(Session& session)
{
    pushFieldWidth();
    if (ImGui::CollapsingHeader("UI parameters"))
        drawUiParameters(session);
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Rendering parameters"))
        drawRenderingParameters(session);
    ImGui::Spacing();
    drawRenderControls(session);
    ImGui::Spacing();
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Save image"))
        drawSaveImage(session);
    ImGui::PopItemWidth();
}

void SettingsPanel::drawUiParameters(Session& session)
{
    const DisplaySettings& d = session.display();
    if (ImGui::RadioButton("Dark", d.dark))
        session.setDark(true);
    ImGui::SameLine();
    if (ImGui::RadioButton("Light", !d.dark))
        session.setDark(false);
    if (ImGui::BeginCombo("Font", d.font.c_str()))
    {
        for (const FontChoice& f : availableFonts())
            if (ImGui::Selectable(f.name.c_str(), f.name == d.font))
                session.setFont(f.name);
        ImGui::EndCombo();
    }
    float size = d.fontSize;
    ImGui::SliderFloat("Font size", &size, float(kMinFontPixels), float(kMaxFontPixels), "%.0f px");
    if (ImGui::IsItemDeactivatedAfterEdit()) // a new atlas per drag step would stutter
        session.setFontSize(size);
}

void SettingsPanel::drawRenderingParameters(Session& session)
{
    const RenderRequest& request = session.image();
    const RenderSettings& s = request.settings;
    const SceneInfo* current = findScene(request.scene.id);
    // A scene file by its name: the whole path is in the title bar of the image.
    const std::string shown = current ? request.scene.id : std::filesystem::path(request.scene.id).filename().string();
    if (ImGui::BeginCombo("Scene", shown.c_str(), ImGuiComboFlags_HeightLarge))
    {
        for (const SceneInfo& info : sceneCatalogue())
        {
            if (ImGui::Selectable(info.id.c_str(), info.id == request.scene.id))
                session.setScene(info.id);
            ImGui::SameLine(ImGui::GetFontSize() * 12.0f);
            ImGui::TextDisabled("%s", info.title.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::InputTextWithHint("##scene-file", "scene file: .json, .gltf, .glb", &m_sceneFile);
    ImGui::SameLine();
    if (ImGui::Button("Load") && !m_sceneFile.empty())
        session.setScene(m_sceneFile);
    tooltip("render a scene file (docs/SCENES.md); the window renders it again whenever it changes on disk");
    if (ImGui::SmallButton("Scene defaults"))
        session.applySceneDefaults();
    tooltip("the scene's own spp, depth, width, aspect ratio, light mode, estimator and pixel sampling");
    if (current)
    {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", current->title.c_str());
        tooltip(current->source.c_str());
    }

    integerField(session, setting("spp"), s.spp, 1, 10);
    if (const int trueSpp = s.trueSpp(); trueSpp != s.spp)
        ImGui::TextDisabled("stratified: a square number of strata, %d true spp", trueSpp);
    integerField(session, setting("depth"), s.depth, 1, 10);
    float aspect = s.aspect;
    if (ImGui::InputFloat("Aspect ratio", &aspect, 0.0f, 0.0f, "%.4f", kApplyOnEnter))
        session.setSetting(setting("aspect"), fmt::format("{}", aspect));
    integerField(session, setting("width"), s.width, 16, 128);
    if (const std::optional<std::uint64_t> bytes = session.memoryEstimate())
        ImGui::TextDisabled("%d x %d pixels, about %s", s.width, s.height(), describeBytes(*bytes).c_str());
    else
        ImGui::TextDisabled("%d x %d pixels", s.width, s.height());
    tooltip("the host memory the render needs, as the command line estimates it: a size that would not fit is "
            "refused");
    for (const auto& [label, value] : {std::pair{"1:1", 1.0f}, {"4:3", 4.0f / 3.0f}, {"16:9", 16.0f / 9.0f}})
    {
        ImGui::SameLine();
        if (ImGui::SmallButton(label))
            session.setSetting(setting("aspect"), fmt::format("{}", value));
    }
    if (request.scene.id == "white-spheres" || request.scene.id == "many-lights")
    {
        const bool spheres = request.scene.id == "white-spheres";
        int count = request.scene.options.count;
        if (ImGui::InputInt(spheres ? "Spheres" : "Lights", &count, 100, 1000, kApplyOnEnter))
            session.setCount(count);
        tooltip(spheres ? "number of white spheres (-1: the scene's default, 20000)"
                        : "number of small lights (-1: the scene's default, 1000)");
    }

    const std::optional<shader::FresnelModel> fresnel = request.scene.options.fresnel;
    if (ImGui::BeginCombo("Fresnel", fresnelOptionName(fresnel)))
    {
        for (const auto& choice : {std::optional<shader::FresnelModel>{}, std::optional(shader::FresnelModel::Schlick),
                                   std::optional(shader::FresnelModel::Exact)})
            if (ImGui::Selectable(fresnelOptionName(choice), choice == fresnel))
                session.setFresnel(choice);
        ImGui::EndCombo();
    }
    tooltip("every dielectric's reflectance: scene (each material's own: Schlick in the books' scenes), schlick "
            "(Schlick's approximation) or exact (the unpolarised Fresnel equations)");
    if (session.hasMicrofacetMaterial())
    {
        float roughness = request.scene.options.roughnessScale;
        if (ImGui::SliderFloat("Roughness x", &roughness, kMinRoughnessScale, kMaxRoughnessScale, "%.3g",
                               ImGuiSliderFlags_Logarithmic))
            session.setRoughnessScale(roughness);
        tooltip("every microfacet material's GGX roughness alpha times this factor (alpha at most 1; 1: the "
                "scene's own): in veach-mis, watch which strategy wins on each plate as they turn from mirror to "
                "matte (--roughness-scale)");
    }

    drawEngineChoice(session);

    // The choices and switches of the settings table, as the command line lists them.
    for (const Setting& setting : settingsTable())
        if (const auto picked = settingWidget(setting, s))
            session.setSetting(setting, *picked);
    bool loop = session.loop();
    if (ImGui::Checkbox("Loop rendering", &loop))
        session.setLoop(loop);
    bool heatmap = session.heatmap();
    if (ImGui::Checkbox("Cost heatmap", &heatmap))
        session.setHeatmap(heatmap);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Each pixel's cost per sample, blue (cheap) to red, in place of the image: the CPU engines "
                          "time each pixel's paths (microseconds), the GPU sums its shader clock's ticks. Timing "
                          "renders again and slows a render of few samples per pixel on the CPU.");
    if (heatmap && session.preview() && !session.preview()->costUnavailable.empty())
        ImGui::TextWrapped("no heatmap: %s", session.preview()->costUnavailable.c_str());
    tooltip("when a render finishes, render again with the next seed and average: the image keeps converging");
    std::uint32_t seed = s.seed;
    const std::uint32_t step = 1;
    if (ImGui::InputScalar("Seed", ImGuiDataType_U32, &seed, &step, nullptr, "%u", kApplyOnEnter))
        session.setSetting(setting("seed"), std::to_string(seed));
}

void SettingsPanel::drawEngineChoice(Session& session)
{
    ImGui::TextUnformatted("Rendering engine");
    ImGui::Indent();
    if (ImGui::RadioButton("Single core CPU", session.engine() == EngineKind::Single))
        session.selectEngine(EngineKind::Single);
    const std::string multi = fmt::format("Multi core CPU ({} threads)", std::thread::hardware_concurrency());
    if (ImGui::RadioButton(multi.c_str(), session.engine() == EngineKind::Multi))
        session.selectEngine(EngineKind::Multi);
    const GpuStartup::Status& gpu = session.gpu();
    switch (gpu.state)
    {
    case GpuStartup::State::Starting:
        if (ImGui::RadioButton("GPU (starting...)", session.engine() == EngineKind::Gpu))
            session.selectEngine(EngineKind::Gpu);
        tooltip("the Vulkan device is opening and the ray-tracing pipeline compiling; a GPU render waits for it");
        break;
    case GpuStartup::State::Ready:
        if (ImGui::RadioButton(fmt::format("GPU ({})", gpu.detail).c_str(), session.engine() == EngineKind::Gpu))
            session.selectEngine(EngineKind::Gpu);
        break;
    case GpuStartup::State::Unavailable:
        ImGui::BeginDisabled();
        ImGui::RadioButton("GPU (unavailable)", false);
        ImGui::EndDisabled();
        tooltip(gpu.detail.c_str());
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", gpu.detail.c_str());
        ImGui::PopTextWrapPos();
        break;
    }
    ImGui::Unindent();
}

void SettingsPanel::drawRenderControls(Session& session)
{
    const JobProgress& p = session.progress();
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    if (ImGui::Button("Render", ImVec2(half, 0.0f)))
        session.render();
    ImGui::SameLine();
    ImGui::BeginDisabled(!p.busy);
    if (ImGui::Button("Cancel", ImVec2(half, 0.0f)))
        session.cancel();
    ImGui::EndDisabled();

    if (ImGui::Button("Choose strategy (pilot), then render", ImVec2(-1.0f, 0.0f)))
        session.chooseStrategy();
    tooltip("--strategy auto: a short pilot on the selected engine (5 % of the render's estimated time, 2 s at most) "
            "measures the efficiency 1/(relMSE s) of nee-mis and mixture with each light sampler and selection "
            "(and Sobol samples where the scene's are random, beside the panel's random or accumulated ones), sets the "
            "panel to the best and renders it; change any setting afterwards to override it");

    ImGui::ProgressBar(session.progressFraction(), ImVec2(-1.0f, 0.0f), session.progressText().c_str());
    // Its line is kept when empty, so that the panel below does not jump as references come and go.
    const std::string reference = session.referenceText();
    ImGui::TextDisabled("%s", reference.empty() ? " " : reference.c_str());
    tooltip("The timings' relMSE is measured against a reference of each row's work at 4x its spp (two halves, "
            "rendered while no render runs, on the row's fastest engine), shared with --compare's reference cache");

    if (const compare::AutoChoice* choice = session.strategyChoice();
        choice && ImGui::CollapsingHeader("Strategy pilot", ImGuiTreeNodeFlags_DefaultOpen))
        rt::gui::drawPilot(*choice);

    if (const auto& last = session.lastFinished())
    {
        const RenderStats& st = *last->stats;
        ImGui::Text("Last render: %.3f s", st.renderSeconds);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s, %s, %dx%d, %d spp, %.2f Mpaths/s, scene build %.3f s", engineLabel(st.engine),
                            st.request.scene.id.c_str(), st.width, st.height, st.trueSpp, st.mpathsPerSecond(), st.buildSeconds);
        ImGui::PopTextWrapPos();
    }
    else
        ImGui::TextDisabled("Last render: none yet");
    if (!session.message().empty())
    {
        const ImVec4 colour = session.messageIsError() ? ImVec4(0.95f, 0.40f, 0.35f, 1.0f)
                                                       : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(session.message().c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
}

void SettingsPanel::drawSaveImage(Session& session)
{
    if (!m_savePathEdited)
        m_savePath = session.suggestedImageName();
    if (ImGui::InputText("File", &m_savePath))
        m_savePathEdited = true;
    tooltip("PNG (sRGB) of the image on screen; the linear radiance goes beside it as .pfm and .exr (float)");
    ImGui::BeginDisabled(!session.preview());
    if (ImGui::Button("Save PNG + PFM"))
        session.saveImage(m_savePath);
    ImGui::EndDisabled();
    if (m_savePathEdited)
    {
        ImGui::SameLine();
        if (ImGui::SmallButton("Suggested name"))
            m_savePathEdited = false;
    }
}
} // namespace rt::gui
