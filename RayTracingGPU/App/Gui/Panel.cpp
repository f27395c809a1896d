#include "App/Gui/Panel.h"

#include <cmath>
#include <filesystem>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/fmt/fmt.h>

#include "Scene/CameraMoves.h"
#include "Cli/ActionGrammar.h"
#include "Gui/EngineLabel.h"
#include "Gui/PilotView.h"
#include "Gui/SettingWidget.h"
#include "Error.h"
#include "Image/ImageIO.h"
#include "Render/MemoryBudget.h"
#include "Render/SettingsTable.h"
#include "Scenes/Catalogue.h"
#include "Shared/HeatmapPalette.h"

namespace rt::gpu::gui
{
namespace
{
ImU32 displayColor(const vec3& linear)
{
    return IM_COL32(linearToSrgb8(linear.x), linearToSrgb8(linear.y), linearToSrgb8(linear.z), 255);
}

void sceneSection(Controls& controls, const WindowState& state, const PanelInfo& info, PanelState& panel)
{
    const SceneInfo* current = findScene(state.image.request.scene.id);
    // A scene file by its name: the whole path is in the window's title.
    const std::string shown =
        current ? current->title : std::filesystem::path(state.image.request.scene.id).filename().string();
    if (ImGui::BeginCombo("Scene", shown.c_str()))
    {
        for (const SceneInfo& scene : sceneCatalogue())
            if (ImGui::Selectable(scene.title.c_str(), scene.id == state.image.request.scene.id))
                controls.selectScene(scene.id);
        ImGui::EndCombo();
    }
    ImGui::InputTextWithHint("##scene-file", "scene file: .json, .gltf, .glb", &panel.sceneFile);
    ImGui::SameLine();
    if (ImGui::Button("Load") && !panel.sceneFile.empty())
    {
        panel.loadError.clear();
        try
        {
            controls.selectScene(panel.sceneFile);
        }
        catch (const Error& e)
        {
            panel.loadError = e.what();
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A scene file (docs/SCENES.md); the window reloads it whenever it changes on disk");
    const std::optional<shader::FresnelModel> fresnel = state.image.request.scene.options.fresnel;
    if (ImGui::BeginCombo("Fresnel", fresnelOptionName(fresnel)))
    {
        for (const auto& choice : {std::optional<shader::FresnelModel>{}, std::optional(shader::FresnelModel::Schlick),
                                   std::optional(shader::FresnelModel::Exact)})
            if (ImGui::Selectable(fresnelOptionName(choice), choice == fresnel))
                controls.setFresnel(choice);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Every dielectric's reflectance: scene (each material's own: Schlick in the books' "
                          "scenes), schlick (Schlick's approximation) or exact (the unpolarised Fresnel equations)");
    if (info.microfacet)
    {
        float roughness = state.image.request.scene.options.roughnessScale;
        if (ImGui::SliderFloat("Roughness x", &roughness, kMinRoughnessScale, kMaxRoughnessScale, "%.3g",
                               ImGuiSliderFlags_Logarithmic))
            controls.setRoughnessScale(roughness);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Every microfacet material's GGX roughness alpha times this factor (alpha at most 1; "
                              "1: the scene's own): in veach-mis, watch which strategy wins on each plate as they "
                              "turn from mirror to matte (--roughness-scale)");
    }
    const ImVec4 warning(1.0f, 0.8f, 0.2f, 1.0f);
    if (!info.building.empty())
        ImGui::TextColored(warning, "Building %s...", info.building.c_str());
    for (const std::string* error : {&std::as_const(panel.loadError), &info.sceneError})
        if (!error->empty())
        {
            ImGui::PushStyleColor(ImGuiCol_Text, warning);
            ImGui::TextWrapped("%s", error->c_str());
            ImGui::PopStyleColor();
        }
}

/// The image's size (it keeps it whatever the window's: letterboxed) and the host memory its render needs.
void imageSection(Controls& controls, const WindowState& state)
{
    const RenderSettings& s = state.image.request.settings;
    if (int width = s.width; ImGui::InputInt("Width", &width, 16, 128, ImGuiInputTextFlags_EnterReturnsTrue))
        controls.setSetting(setting("width"), std::to_string(width));
    if (float aspect = s.aspect;
        ImGui::InputFloat("Aspect", &aspect, 0.0f, 0.0f, "%.4f", ImGuiInputTextFlags_EnterReturnsTrue))
        controls.setSetting(setting("aspect"), fmt::format("{}", aspect));
    for (const auto& [label, value] : {std::pair{"1:1", 1.0f}, {"4:3", 4.0f / 3.0f}, {"16:9", 16.0f / 9.0f}})
    {
        if (ImGui::SmallButton(label))
            controls.setSetting(setting("aspect"), fmt::format("{}", value));
        ImGui::SameLine();
    }
    ImGui::TextDisabled("%d x %d, about %s", s.width, s.height(),
                        describeBytes(renderBytes(s, state.sceneObjects)).c_str());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the host memory the render needs, as the command line estimates it: a size that would not "
                          "fit is refused");
}

void rayTracingSection(Controls& controls, const WindowState& state, const PanelInfo& info)
{
    const ImageSettings& image = state.image;
    const DisplaySettings& display = state.display;
    if (bool on = image.rayTracing; ImGui::Checkbox("Enable ray tracing", &on))
        controls.setRayTracing(on);
    if (ImGui::BeginCombo("Engine", rt::gui::engineLabel(state.engine)))
    {
        for (const EngineKind kind : {EngineKind::Gpu, EngineKind::Single, EngineKind::Multi})
            if (ImGui::Selectable(rt::gui::engineLabel(kind), kind == state.engine))
                controls.setEngine(kind);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("GPU: samples traced in the frames; single and multi core: a whole render of Stop at spp "
                          "(or the settings' spp) on the CPU, shown when it ends, timed beside the GPU");
    if (!info.engineStatus.empty())
        ImGui::TextDisabled("%s", info.engineStatus.c_str());
    if (bool on = image.accumulate; ImGui::Checkbox("Accumulate between frames", &on))
        controls.setAccumulate(on);
    if (bool automatic = display.samplesPerFrame == 0; ImGui::Checkbox("Samples / frame by time", &automatic))
        controls.setSamplesPerFrame(automatic ? 0 : std::max(info.samplesPerFrame, 1));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("each frame traces about 50 ms of the device's samples: few samples a frame leave each "
                          "launch waiting for its slowest paths (1 a frame took 3.9x a headless render's time on an "
                          "H200)");
    if (display.samplesPerFrame > 0)
    {
        if (int samples = display.samplesPerFrame; ImGui::SliderInt("Samples / frame", &samples, 1, 64))
            controls.setSamplesPerFrame(samples);
    }
    else
        ImGui::TextDisabled("by time: %d a frame now", info.samplesPerFrame);
    if (int spp = display.stopAtSpp ? image.request.settings.spp : 0; ImGui::InputInt("Stop at spp", &spp, 16, 256))
        controls.setStopSpp(spp);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Tracing stops at this many samples per pixel, the image of a headless render of that "
                          "spp; 0: never");
    if (int depth = image.request.settings.depth; ImGui::SliderInt("Depth", &depth, 1, 100))
        controls.setDepth(depth);
    // The choices and switches of the settings table, pixel sampling included, as the CPU window and the CLI name
    // them.
    for (const Setting& setting : settingsTable())
        if (const auto picked = rt::gui::settingWidget(setting, image.request.settings))
            controls.setSetting(setting, *picked);
    if (ImGui::Button("Choose strategy (pilot)", ImVec2(-1.0f, 0.0f)))
        controls.chooseStrategy();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("--strategy auto: a short pilot on the GPU (5 %% of the image's estimated time, 2 s at most, "
                          "and the pipelines it compiles; the window waits) measures the efficiency 1/(relMSE s) of "
                          "nee-mis and mixture with each light sampler and selection (and Sobol samples beside the "
                          "panel's accumulation where the scene's are random) and sets the panel to the best; "
                          "change any setting afterwards to override it");
    if (info.pilot && ImGui::TreeNodeEx("Strategy pilot", ImGuiTreeNodeFlags_DefaultOpen))
    {
        rt::gui::drawPilot(*info.pilot);
        ImGui::TreePop();
    }
    const RenderSettings& s = image.request.settings;
    if (s.sampling == PixelSampling::Stratified && !(display.stopAtSpp && image.accumulate))
        ImGui::TextDisabled("stratified needs Stop at spp (and accumulation): random samples until then");
    else if (s.sampling == PixelSampling::Stratified && s.trueSpp() != s.spp)
        ImGui::TextDisabled("stratified: %d x %d strata, stops at %d spp", s.strata(), s.strata(), s.trueSpp());
}

void cameraSection(Controls& controls, const WindowState& state)
{
    const CameraDesc& camera = state.image.camera;
    if (float fov = camera.vfovDegrees; ImGui::SliderFloat("Field of view", &fov, kMinFov, kMaxFov, "%.1f deg"))
        controls.setFov(fov);
    const float scale = camera.focusDistance;
    if (float aperture = apertureOf(camera); ImGui::DragFloat("Aperture", &aperture, 0.002f * scale, 0.0f, scale, "%.3f"))
        controls.setAperture(aperture);
    if (float focus = camera.focusDistance;
        ImGui::DragFloat("Focus distance", &focus, 0.005f * scale, 1e-3f, 1e6f, "%.2f"))
        controls.setFocusDistance(focus);
    if (ImGui::Button("Reset camera"))
        controls.resetCamera();
    ImGui::TextDisabled("WASD/QE move, Shift x4, Ctrl x1/4,\ndrag to look, wheel: field of view");
}

void profilerSection(Controls& controls, const WindowState& state, const PanelInfo& info)
{
    if (bool on = state.image.heatmap; ImGui::Checkbox("Heatmap (time per pixel)", &on))
        controls.setHeatmap(on);
    if (bool on = state.display.autoCostScale; ImGui::Checkbox("Automatic scale", &on))
        controls.setAutoCostScale(on);
    if (!state.display.autoCostScale)
        if (float scale = state.display.costScale;
            ImGui::DragFloat("Scale", &scale, 0.01f * scale, 1.0f, 1e12f, "%.3g ticks", ImGuiSliderFlags_Logarithmic))
            controls.setCostScale(scale);
    // The colour scale: the display shader's own palette, 0 at the left, the scale in use at the right.
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const float height = ImGui::GetFrameHeight();
    constexpr int kSteps = 32;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (int i = 0; i < kSteps; ++i)
    {
        const float x0 = origin.x + width * float(i) / kSteps, x1 = origin.x + width * float(i + 1) / kSteps;
        draw->AddRectFilledMultiColor({x0, origin.y}, {x1, origin.y + height},
                                      displayColor(shader::heatmapColor(float(i) / kSteps)),
                                      displayColor(shader::heatmapColor(float(i + 1) / kSteps)),
                                      displayColor(shader::heatmapColor(float(i + 1) / kSteps)),
                                      displayColor(shader::heatmapColor(float(i) / kSteps)));
    }
    ImGui::Dummy({width, height});
    ImGui::Text("0 ... %.3g %s", info.costScale, info.costUnit.c_str());
    ImGui::Text("max %.3g %s", info.costMax, info.costUnit.c_str());
}

void statsSection(const WindowState& state, const PanelInfo& info)
{
    ImGui::Text("%.1f fps, %.2f Msamples/s", info.framesPerSecond, info.megaSamplesPerSecond);
    if (state.display.stopAtSpp)
        ImGui::Text("%d / %d spp accumulated", info.accumulatedSpp, state.image.request.settings.spp);
    else
        ImGui::Text("%d spp accumulated", info.accumulatedSpp);
    ImGui::Text("%d x %d image, depth %d", info.image.width, info.image.height, state.image.request.settings.depth);
    ImGui::TextDisabled("%d x %d window", info.window.width, info.window.height);
    ImGui::TextWrapped("%s", info.device.c_str());
}

void saveSection(Controls& controls, PanelState& panel, const WindowState& state)
{
    ImGui::InputText("File (.png)", &panel.savePath);
    if (ImGui::Button("Save image"))
        controls.save(panel.savePath);
    ImGui::SameLine();
    ImGui::TextDisabled("PNG + PFM");
    if (!state.message.empty())
        ImGui::TextWrapped("%s", state.message.c_str());
}
} // namespace

PixelRect drawPanel(Controls& controls, const WindowState& state, const PanelInfo& info, PanelState& panel,
                    const PixelRect& column, float framebufferScale)
{
    const float fontScale = state.display.fontScale;
    // A fixed column: the layout keeps the image beside it, so the panel must not be moved over the image.
    ImGui::SetNextWindowPos({float(column.x) / framebufferScale, float(column.y) / framebufferScale}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({float(column.width) / framebufferScale, float(column.height) / framebufferScale},
                             ImGuiCond_Always);
    ImGui::Begin("ray-tracing-gpu", nullptr,
                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_HorizontalScrollbar);
    const ImVec2 drawnAt = ImGui::GetWindowPos();
    const ImVec2 drawnSize = ImGui::GetWindowSize();
    ImGui::PushItemWidth(-110.0f * fontScale); // room for the labels right of the widgets
    if (ImGui::CollapsingHeader("UI", ImGuiTreeNodeFlags_DefaultOpen))
    {
        if (bool dark = state.display.darkStyle; ImGui::Checkbox("Dark style", &dark))
            controls.setDarkStyle(dark);
        if (ImGui::BeginCombo("Font", state.fonts.at(static_cast<std::size_t>(state.display.font)).c_str()))
        {
            for (std::size_t i = 0; i < state.fonts.size(); ++i)
                if (ImGui::Selectable(state.fonts[i].c_str(), static_cast<int>(i) == state.display.font))
                    controls.setFont(state.fonts[i]);
            ImGui::EndCombo();
        }
        if (int pixels = controls.fontPixels(); ImGui::SliderInt("Font size", &pixels, kMinFontPixels, kMaxFontPixels, "%d px"))
            controls.setFontPixels(pixels);
    }
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen))
        sceneSection(controls, state, info, panel);
    if (ImGui::CollapsingHeader("Image", ImGuiTreeNodeFlags_DefaultOpen))
        imageSection(controls, state);
    if (ImGui::CollapsingHeader("Ray tracing", ImGuiTreeNodeFlags_DefaultOpen))
        rayTracingSection(controls, state, info);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
        cameraSection(controls, state);
    if (info.costAvailable && ImGui::CollapsingHeader("Profiler", ImGuiTreeNodeFlags_DefaultOpen))
        profilerSection(controls, state, info);
    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen))
        statsSection(state, info);
    if (ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen))
        saveSection(controls, panel, state);
    ImGui::PopItemWidth();
    ImGui::End();
    const auto pixels = [framebufferScale](float v) { return int(std::lround(v * framebufferScale)); };
    return {pixels(drawnAt.x), pixels(drawnAt.y), pixels(drawnSize.x), pixels(drawnSize.y)};
}
} // namespace rt::gpu::gui
