#include "App/Gui/GuiApp.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>

#include <imgui.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "App/Gui/ActionScript.h"
#include "App/Gui/CameraInput.h"
#include "App/Gui/FramePacer.h"
#include "App/Gui/ImageView.h"
#include "App/Gui/GlWindow.h"
#include "App/Gui/PaneLayout.h"
#include "App/Gui/RenderJob.h"
#include "App/Gui/Screenshot.h"
#include "App/Gui/Session.h"
#include "App/Gui/SettingsPanel.h"
#include "App/Gui/Theme.h"
#include "Compare/AutoCommand.h"
#include "Compare/ReferenceCache.h"
#include "Error.h"
#include "Gui/PlotWindow.h"
#include "Gui/TimingsWindow.h"
#include "IO/AtomicFile.h"

namespace rt::gui
{
namespace
{
constexpr ImGuiWindowFlags kPaneFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoBringToFrontOnFocus;

std::string describe(const Preview& p)
{
    const RenderSettings& r = p.request.image.settings;
    const std::string roulette = r.russianRoulette == RussianRoulette::Off    ? ", no roulette"
                                 : r.russianRoulette == RussianRoulette::Sqrt ? ", sqrt roulette"
                                                                              : "";
    return fmt::format("{}  |  {}x{}  |  {} spp{}  |  depth {}  |  {}{}  |  {}  |  {}", p.request.image.scene.id,
                       r.width, r.height(), p.samples,
                       p.request.loop || p.samples == r.trueSpp() ? "" : fmt::format(" of {}", r.trueSpp()), r.depth,
                       toString(r.estimator), roulette, toString(r.sampling), engineLabel(p.request.engine));
}

class GuiApp
{
public:
    /// `size` and `script`: the options' --window-size and --actions, parsed (and so checked) before;
    /// `fitToMonitor` for the default size.
    GuiApp(const GuiOptions& options, WindowSize size, bool fitToMonitor, std::optional<ActionScript> script,
           const RenderRequest& initial, std::shared_ptr<const Scene> scene, EngineKind engine, bool chooseStrategy,
           bool heatmap, PilotOptions pilot)
        : m_options(options),
          m_window(size, fitToMonitor, "ray-tracing-cpu: light-sampling lab"),
          // The launch render waits for the first frame, and the GPU engine's start for the launch render's end
          // (RenderJob.h): the window's start-up made a 1.1 s multi-core render 10 % slower than headless on 2
          // cores (tests/Bench/window_vs_headless.sh).
          m_job({.enabled = !options.noGpu, .validation = options.validation, .deferred = true}, initial,
                std::move(scene), [] { GlWindow::wake(); }, compare::defaultReferenceCacheDir(), true, std::move(pilot)),
          m_session(m_job, initial, engine, false, chooseStrategy, heatmap)
    {
        m_session.setFont(availableFonts().front().name);
        m_script = std::move(script);
    }

    int run()
    {
        int framesLeft = -1; // counts down once the automation has settled
        bool screenshotFailed = false;
        while (!m_window.closeRequested())
        {
            const bool rendering = m_session.progress().busy;
            const bool keyHeld = m_window.cameraKeyHeld();
            m_window.waitEvents(m_pacer.timeout(rendering, automating(), FramePacer::Clock::now(), keyHeld));
            const FramePacer::Frame frame = m_pacer.next(rendering, automating(), m_window.inputEvents(),
                                                         GlWindow::takeWake(), FramePacer::Clock::now(), keyHeld);
            if (frame == FramePacer::Frame::Skip)
                continue; // the pointer moved over the window during a render: the next paced frame shows it
            m_theme.apply(m_session.display());
            const bool scriptDone = !m_script || m_script->step(m_session, m_window);
            m_session.update();
            m_imageView.update(m_session.preview(), m_session.heatmap());

            const FramebufferSize size = m_window.framebufferSize();
            if (!size.empty()) // minimised or 0x0: nothing to draw into
            {
                m_window.beginFrame();
                drawPanes();
                m_window.endFrame(m_session.display().dark ? 0.08f : 0.85f);
                if (rendering || m_session.progress().busy)
                    m_job.countRedraw(frame == FramePacer::Frame::Input);
            }
            if (m_options.frames > 0)
            {
                if (framesLeft < 0 && scriptDone && settled())
                    framesLeft = m_options.frames;
                if (framesLeft > 0 && --framesLeft == 0)
                {
                    screenshotFailed = !saveScreenshotIfAsked(size);
                    break;
                }
            }
            if (!size.empty())
            {
                m_window.present();
                m_job.release(); // the first frame is on screen
            }
        }
        return finish(screenshotFailed);
    }

private:
    bool automating() const { return m_options.frames > 0 || (m_script && !m_script->done()); }

    /// The renders started so far have finished (with loop rendering: one has).
    bool settled() const
    {
        return !m_session.progress().busy || (m_session.loop() && m_session.finishedRenders() > 0);
    }

    bool saveScreenshotIfAsked(FramebufferSize size)
    {
        if (m_options.screenshot.empty())
            return true;
        if (size.empty())
        {
            spdlog::error("no screenshot: the window is {}x{} at the last frame", size.width, size.height);
            return false;
        }
        saveScreenshot(m_options.screenshot, size);
        spdlog::info("screenshot {} ({}x{})", m_options.screenshot, size.width, size.height);
        return true;
    }

    int finish(bool screenshotFailed)
    {
        if (!m_options.stateJson.empty())
        {
            nlohmann::json state = m_session.stateJson();
            state["validation_messages"] = m_job.gpuValidationMessages();
            state["layout"] = m_layout;
            writeFileAtomically(m_options.stateJson, state.dump(2) + "\n");
        }
        int status = 0;
        if (const std::uint64_t n = m_job.gpuValidationMessages(); n > 0)
        {
            spdlog::error("Vulkan validation reported {} warnings or errors (see above)", n);
            status = 1;
        }
        // A person sees failures in the window; a test reads the status.
        const bool automated = m_options.frames > 0 || m_script.has_value();
        const int scriptFailures = m_script ? m_script->failures() : 0;
        if (automated && (scriptFailures > 0 || m_session.failedRenders() > 0 || screenshotFailed))
            status = 1;
        return status;
    }

    void drawPanes()
    {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        const PaneLayout panes = layoutPanes(display.x, display.y, ImGui::GetFontSize());
        const float panelWidth = panes.panel.width;
        const float timingsHeight = panes.timings.height;

        ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
        ImGui::SetNextWindowSize(ImVec2(panelWidth, display.y));
        if (ImGui::Begin("Light-sampling lab: CPU path tracer", nullptr, kPaneFlags))
            m_panel.draw(m_session);
        ImGui::End();

        const std::shared_ptr<const Preview>& preview = m_session.preview();
        const bool stale = m_session.imageIsStale();
        const JobProgress& progress = m_session.progress();
        std::string overlay;
        if (!preview)
            overlay = progress.busy ? "rendering the first image..." : "no image yet: press Render";
        else if (m_session.heatmap() && !m_imageView.showsHeatmap() && !stale)
            overlay = progress.busy                        ? std::string("timing every pixel...")
                      : !preview->costUnavailable.empty() ? "no cost heatmap: " + preview->costUnavailable
                                                          : std::string("no cost heatmap for this image: press Render");
        else if (stale)
            overlay = progress.busy ? fmt::format("rendered with other settings; rendering the panel's: {:.0f}%",
                                                  progress.fraction * 100.0)
                                    : "rendered with other settings: press Render";
        std::string title = preview ? (m_imageView.showsHeatmap() ? "Cost per sample: " : "Image: ") + describe(*preview)
                                    : std::string("Image");
        if (preview && !preview->complete && !(progress.busy && !stale))
            title += "  |  cancelled";
        title += "###image";
        ImGui::SetNextWindowPos(ImVec2(panelWidth, 0.0f));
        ImGui::SetNextWindowSize(ImVec2(display.x - panelWidth, display.y - timingsHeight));
        if (ImGui::Begin(title.c_str(), nullptr, kPaneFlags))
        {
            const auto now = std::chrono::steady_clock::now();
            const double seconds = std::chrono::duration<double>(now - m_lastInputFrame).count();
            m_lastInputFrame = now;
            applyCameraInput(m_session, m_imageView.draw(stale, overlay), seconds);
        }
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(panes.timings.x, panes.timings.y));
        ImGui::SetNextWindowSize(ImVec2(panes.timings.width, panes.timings.height));
        bool latestTimingVisible = false;
        if (ImGui::Begin("Timings of this session: every engine side by side", nullptr, kPaneFlags))
        {
            const TimingsDrawn timings = drawTimings(m_session.timings());
            latestTimingVisible = timings.latestVisible;
            if (timings.clearClicked)
                m_session.clearTimings();
        }
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(panes.plot.x, panes.plot.y));
        ImGui::SetNextWindowSize(ImVec2(panes.plot.width, panes.plot.height));
        nlohmann::json plot;
        if (ImGui::Begin("Convergence: relMSE against time", nullptr, kPaneFlags | ImGuiWindowFlags_NoScrollbar))
        {
            PlotDrawn drawn = drawConvergencePlot(m_session.plot(), m_session.image(), m_session.suggestedPlotName());
            plot = std::move(drawn.state);
            if (drawn.saveClicked)
                m_session.savePlot(m_session.suggestedPlotName());
        }
        ImGui::End();

        // Where things are, in framebuffer pixels (what a screenshot holds): tests crop the panes with it.
        const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
        const auto pixels = [&](float x, float y, float w, float h) {
            return std::array{int(x * scale.x + 0.5f), int(y * scale.y + 0.5f), int(w * scale.x + 0.5f),
                              int(h * scale.y + 0.5f)};
        };
        const auto& image = m_imageView.drawnRect();
        m_layout = {{"panel", pixels(0.0f, 0.0f, panelWidth, display.y)},
                    {"image", pixels(image[0], image[1], image[2], image[3])},
                    {"timings", pixels(panes.timings.x, panes.timings.y, panes.timings.width, panes.timings.height)},
                    {"plot", pixels(panes.plot.x, panes.plot.y, panes.plot.width, panes.plot.height)},
                    {"plot_drawn", std::move(plot)},
                    {"latest_timing_visible", latestTimingVisible}};
    }

    const GuiOptions& m_options;
    GlWindow m_window; // first: the GL context outlives every GL object below
    RenderJob m_job;
    Session m_session;
    Theme m_theme;
    SettingsPanel m_panel;
    ImageView m_imageView;
    FramePacer m_pacer;
    std::optional<ActionScript> m_script;
    nlohmann::json m_layout; // of the last frame drawn, for --state-json
    std::chrono::steady_clock::time_point m_lastInputFrame = std::chrono::steady_clock::now(); // WASD's clock
};
} // namespace

int runGui(const CommonOptions& options, const std::string& engineName, const GuiOptions& gui)
{
    const auto engine = parseName<EngineKind>(engineName);
    if (!engine)
        throw UsageError("--engine must be single, multi or gpu (got '" + engineName + "')");
    for (const auto& [flag, value] : {std::pair{"--output", &options.output}, {"--hdr", &options.hdr}, {"--stats", &options.stats}})
        if (!value->empty())
            throw UsageError(std::string(flag) + " is for --headless runs; in the window, use Save image");
    // --heatmap names the headless run's file; the window takes on or off, and shows the cost for a file too.
    if (!options.heatmap.empty() && options.heatmap != "on" && options.heatmap != "off")
        spdlog::warn("--heatmap {}: the file is for --headless; the window shows the cost instead", options.heatmap);
    const bool heatmap = !options.heatmap.empty() && options.heatmap != "off";
    std::optional<WindowSize> size;
    if (!gui.windowSize.empty())
        size = parseWindowSize(gui.windowSize);
    checkGuiOutputPaths(gui);
    std::optional<ActionScript> script; // a typo fails here, before a window opens
    if (!gui.actions.empty())
        script.emplace(gui.actions);
    CommandLineRender job = resolveCommandLine(options);
    const RenderRequest initial = job.request;
    const RenderSettings& s = initial.settings;
    const WindowSize fitting = defaultWindowSize(s.width, s.height(), DisplaySettings{}.fontSize);
    GuiApp app(gui, size.value_or(fitting), !size, std::move(script), initial,
               std::make_shared<const Scene>(std::move(job.scene)), *engine,
               options.strategy == "auto" && options.strategyGiven, heatmap,
               {.budget = compare::pilotBudget(options), .fixed = compare::fixedSettings(options)});
    return app.run();
}
} // namespace rt::gui
