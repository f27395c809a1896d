#include "App/Gui/WindowApp.h"

#include <chrono>
#include <future>
#include <memory>
#include <utility>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "Scene/CameraMoves.h"
#include "App/Gui/AccumulationClock.h"
#include "App/Gui/CameraInput.h"
#include "App/Gui/Controls.h"
#include "App/Gui/CpuRenders.h"
#include "App/Gui/DisplayPass.h"
#include "App/Gui/ImGuiLayer.h"
#include "App/Gui/LabPanes.h"
#include "App/Gui/Panel.h"
#include "App/Gui/Presenter.h"
#include "App/Gui/Throughput.h"
#include "App/Gui/VulkanWindow.h"
#include "App/Gui/RasterPreview.h"
#include "App/Gui/WindowLayout.h"
#include "App/Gui/WindowReferences.h"
#include "Compare/AutoStrategy.h"
#include "Compare/ReferenceCache.h"
#include "Engine/ProgressiveFrame.h"
#include "Error.h"
#include "Gui/ConvergencePlot.h"
#include "Gui/EngineLabel.h"
#include "Gui/PlotFiles.h"
#include "Gui/TimingsTable.h"
#include "IO/AtomicFile.h"
#include "Image/Heatmap.h"
#include "Image/ImageIO.h"
#include "SceneFile/SceneFileWatch.h"

namespace rt::gpu::gui
{
namespace
{
using Clock = std::chrono::steady_clock;

constexpr double kIdleFrameSeconds = 1.0 / 60.0;

GpuEngineOptions engineOptions(const WindowOptions& options, const VulkanWindow& window)
{
    GpuEngineOptions e;
    e.deviceIndex = options.deviceIndex;
    e.validation = options.validation;
    e.integrator = options.integrator;
    e.shaderDir = options.shaderDir;
    e.presentation = Presentation{VulkanWindow::requiredInstanceExtensions(),
                                  [&window](VkInstance instance) { return window.createSurface(instance); }};
    return e;
}

class WindowApp final
{
public:
    WindowApp(const WindowOptions& options, VulkanWindow& window, Scene scene)
        : m_options(options), m_window(window), m_engine(engineOptions(options, window)),
          m_scene(std::make_shared<Scene>(std::move(scene))),
          m_presenter(m_engine.context(), window.framebufferSize()),
          m_renderer(m_engine, kFramesInFlight),
          m_preview(m_engine.context().device(), m_engine.shaderDir(), m_presenter.renderPass()),
          m_display(m_engine.context().device(), m_engine.shaderDir(), m_presenter.renderPass()),
          m_imgui(m_engine.context(), window.handle(), m_presenter.renderPass(), kFramesInFlight),
          m_references(m_engine, kFramesInFlight, compare::defaultReferenceCacheDir()),
          m_state(options.initial), m_controls(m_state), m_clock(kFramesInFlight, std::uint32_t(kMaxSamplesPerFrame))
    {
        m_panel.savePath = options.savePath;
        m_drawn.window = window.framebufferSize();
        m_state.costAvailable = m_renderer.costAvailable();
        m_state.fonts = m_imgui.fontNames();
        if (!options.screenshot.empty() && !m_presenter.canScreenshot())
            throw DeviceError("--screenshot: the window's swapchain cannot be copied from (no 8-bit format or no "
                              "VK_IMAGE_USAGE_TRANSFER_SRC_BIT)");
        m_state.image.heatmap = m_state.image.heatmap && m_state.costAvailable;
        if (options.initial.image.heatmap && !m_state.costAvailable)
            spdlog::warn("the device has no VK_KHR_shader_clock: no heatmap");
        showScene(*m_scene);
        m_watch.watch(m_state.image.request.scene.id, m_state.image.request.scene.fileVersion);
        spdlog::info("window on '{}': {} images, format {}, present mode {}, shader clock {}",
                     m_engine.deviceName(), m_presenter.imageCount(), static_cast<int>(m_presenter.format()),
                     static_cast<int>(m_presenter.presentMode()), m_state.costAvailable ? "yes" : "no");
    }

    ~WindowApp() { m_presenter.waitIdle(); }

    WindowApp(const WindowApp&) = delete;
    WindowApp& operator=(const WindowApp&) = delete;

    std::shared_ptr<const vk::ValidationLog> validationLog() const { return m_engine.validationLog(); }

    /// Runs until the window is closed or the automation is done; then writes --state-json.
    void run()
    {
        Clock::time_point last = Clock::now();
        while (!m_window.closeRequested() && !m_done)
        {
            // Nothing to trace: redraw on input, or at most at kIdleFrameSeconds (the preview, the panel).
            if (automated() || m_loading.valid() || tracing() || referencesToTrace() || m_cpu.busy())
                m_window.pollEvents();
            else
                m_window.waitEvents(kIdleFrameSeconds);
            const Clock::time_point now = Clock::now();
            const float seconds = std::chrono::duration<float>(now - last).count();
            last = now;
            finishSceneBuild();
            runAutomation();
            pollSceneFile();
            startSceneBuild();
            applyRequests();
            driveCpuRenders();
            if (m_window.framebufferSize().width == 0 || m_window.framebufferSize().height == 0)
            {
                // Minimised: nothing to draw into. Scripts keep running (their next action restores the window).
                m_window.waitEvents(automated() ? 0.01 : 0.0);
                continue;
            }
            drawFrame(seconds);
        }
        if (!m_options.stateJson.empty())
            writeStateJson();
    }

private:
    bool automated() const { return m_options.frames.has_value(); }

    /// The next frame traces samples: ray tracing is on and the image has not reached its stop.
    bool tracing() const
    {
        return m_state.engine == EngineKind::Gpu && m_state.image.rayTracing &&
               (!m_state.display.stopAtSpp || !m_state.image.accumulate ||
                                            m_accumulatedSpp < std::uint32_t(m_state.image.request.settings.trueSpp()));
    }

    /// The image has reached its stop and a reference waits for the device: the frames trace it.
    bool referencesToTrace() const
    {
        return m_state.image.rayTracing && !tracing() && !m_cpu.busy() && m_references.pending(m_state.image.request.scene);
    }

    /// The accumulation is a timed render: it stops at the settings' spp, accumulates, and is not timed per
    /// pixel (the heatmap's clock reads slow its samples).
    bool timedRender() const
    {
        return m_state.display.stopAtSpp && m_state.image.accumulate && !m_state.image.heatmap;
    }

    /// What a frame of `image` traces. Stratified samples only where the passes accumulate up to the settings'
    /// spp, the strata's count; otherwise random jitter per pass.
    FrameRequest requestOf(const ImageSettings& image) const
    {
        FrameRequest request;
        request.settings = image.request.settings;
        request.settings.sampling = progressiveSampling(request.settings.sampling,
                                                        m_state.display.stopAtSpp && image.accumulate);
        request.camera = image.camera;
        request.cost = image.heatmap;
        return request;
    }

    /// The samples in the accumulation image (traced with m_traced) are samples of the panel's image: the same
    /// settings but perhaps the spp, where tracing stops, as long as the spp does not change the integrator
    /// (whose images differ by noise).
    bool accumulationFits() const
    {
        ImageSettings now = m_state.image;
        // Stratified samples of another spp lie in other strata: another image.
        if (requestOf(now).settings.sampling != PixelSampling::Stratified)
            now.request.settings.spp = m_traced.request.settings.spp;
        return now == m_traced && requestOf(m_state.image).settings.sampling == requestOf(m_traced).settings.sampling &&
               m_renderer.integratorFor(requestOf(m_state.image)) == m_renderer.integratorFor(requestOf(m_traced));
    }

    /// Puts `scene` on the device, in the preview and behind the renderer's descriptor sets; the device is idle.
    void showScene(const Scene& scene)
    {
        m_references.sceneChanged(); // its descriptor sets name the old scene
        m_engine.setScene(scene);
        m_preview.setScene(scene, m_engine.context().commandPool());
        prepareImages(m_state.image.extent());
        m_state.image.request.scene.id = scene.id;
        m_state.sceneCamera = scene.camera;
        m_state.sceneObjects = scene.primitiveCount() + scene.lights.size();
        m_state.image.camera = scene.camera;
        m_state.cameraSpeed = movementSpeed(scene.camera);
        glfwSetWindowTitle(m_window.handle(), ("ray-tracing-gpu: " + scene.id).c_str());
    }

    void prepareImages(Extent extent)
    {
        m_renderer.prepare({static_cast<std::uint32_t>(extent.width), static_cast<std::uint32_t>(extent.height)});
        m_display.setImages(m_renderer.accumulationView(), m_renderer.costView());
        m_needsClear = true;
    }

    void startSceneBuild()
    {
        if (!m_state.sceneRequest || m_loading.valid())
            return; // one build at a time; a newer request waits for it
        m_loadingId = *m_state.sceneRequest;
        m_state.sceneRequest.reset();
        // The version is read before the file: an edit saved while it is being read is noticed afterwards.
        const SceneRef ref{.id = m_loadingId,
                           .options = m_state.image.request.scene.options,
                           .fileVersion = sceneFileVersion(m_loadingId)};
        m_watch.watch(ref.id, ref.fileVersion);
        // The same version of the scene on screen, built again for its options (Fresnel, roughness): the view
        // the user moved to stays.
        m_loadingKeepsView = ref.id == m_state.image.request.scene.id &&
                             ref.fileVersion == m_state.image.request.scene.fileVersion;
        m_loadingVersion = ref.fileVersion;
        m_loading = std::async(std::launch::async, [ref] { return buildScene(ref); });
    }

    /// A new version of the scene file asked for last is built as if selected again; the scene on screen
    /// stays until it has been built, and stays for good when it fails.
    void pollSceneFile()
    {
        const std::optional<std::int64_t> version = m_watch.poll(Clock::now());
        if (!version || m_state.sceneRequest)
            return;
        spdlog::info("{} changed on disk: reloading it", m_watch.path());
        m_state.sceneRequest = m_watch.path();
    }

    void finishSceneBuild()
    {
        if (!m_loading.valid() || m_loading.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            return;
        try
        {
            auto scene = std::make_unique<Scene>(m_loading.get());
            m_presenter.waitIdle();
            const CameraDesc view = m_state.image.camera;
            const float speed = m_state.cameraSpeed;
            try
            {
                showScene(*scene);
                if (m_loadingKeepsView)
                {
                    m_state.image.camera = view;
                    m_state.cameraSpeed = speed;
                }
            }
            catch (const Error&)
            {
                showScene(*m_scene); // the engine dropped the old scene before failing: put it back
                throw;
            }
            m_scene = std::move(scene);
            m_state.image.request.scene.fileVersion = m_loadingVersion;
            m_state.message.clear();
            m_sceneError.clear();
        }
        catch (const Error& e)
        {
            m_state.message = e.what();
            m_sceneError = e.what();
            if (automated())
                throw;
            spdlog::error("{}", e.what());
        }
    }

    /// wait's end: the image has reached its stop (or has none), or a CPU engine's render of the panel ended.
    bool renderDone() const
    {
        if (m_state.engine != EngineKind::Gpu)
            return m_state.image.rayTracing && m_cpuShown && !m_cpu.busy();
        return !m_state.display.stopAtSpp || !tracing();
    }

    /// wait-reference's end: the image has reached its stop (or has none) and no reference is queued or rendering.
    bool referencesDone() const
    {
        if (m_state.engine != EngineKind::Gpu)
            return m_state.image.rayTracing && m_cpuShown && !m_cpu.busy() &&
                   !m_references.pending(m_state.image.request.scene);
        return (!m_state.display.stopAtSpp || !tracing()) && !m_references.pending(m_state.image.request.scene);
    }

    void runAutomation()
    {
        if (!automated() || m_loading.valid() || m_state.sceneRequest)
            return; // a scene action waits until its scene is on screen
        if (m_waitReference)
        {
            if (!referencesDone())
                return;
            m_waitReference = false;
        }
        if (m_waitRender)
        {
            if (!renderDone())
                return;
            m_waitRender = false;
        }
        if (m_waitFrames > 0)
        {
            --m_waitFrames;
            return;
        }
        if (Clock::now() < m_sleepUntil)
            return;
        if (m_nextAction < m_options.actions.size())
        {
            const Action& action = m_options.actions[m_nextAction++];
            spdlog::debug("action {}={}", action.name, action.value);
            if (action.name == "wait-reference")
                m_waitReference = true;
            else if (action.name == "wait")
                m_waitRender = true;
            else if (!applyAction(action, m_controls))
            {
                m_waitFrames = waitFrames(action);
                m_sleepUntil = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(waitSeconds(action)));
            }
        }
    }

    bool actionsDone() const
    {
        return m_nextAction >= m_options.actions.size() && m_waitFrames == 0 && Clock::now() >= m_sleepUntil &&
               !m_loading.valid() && !m_state.sceneRequest && !m_waitReference && !m_waitRender &&
               !m_state.pilotRequest;
    }

    void applyRequests()
    {
        if (m_state.resizeRequest)
        {
            m_window.resize(*m_state.resizeRequest);
            m_state.resizeRequest.reset();
        }
        if (m_state.saveRequest)
        {
            const std::filesystem::path png = *m_state.saveRequest;
            m_state.saveRequest.reset();
            save(png);
        }
        if (m_state.savePlotRequest)
        {
            const std::filesystem::path png = *m_state.savePlotRequest;
            m_state.savePlotRequest.reset();
            savePlot(png);
        }
        if (m_state.pilotRequest && !m_loading.valid() && !m_state.sceneRequest) // the pilot is of the scene to show
        {
            m_state.pilotRequest = false;
            choosePilotStrategy();
        }
    }

    /// --strategy auto's pilot on the window's GPU engine (its headless path: the render driver on the same device,
    /// idle, between frames; the window waits, its budget and the pipelines it compiles) for the panel's image at
    /// its spp and camera, then the panel's strategy settings are its choice.
    void choosePilotStrategy()
    {
        if (m_state.engine != EngineKind::Gpu)
        {
            m_state.message = "the strategy pilot measures the GPU engine: select it first (ray-tracing-cpu's window "
                              "pilots its CPU engines)";
            return;
        }
        m_presenter.waitIdle();
        RenderRequest request = m_state.image.request;
        if (!(m_state.image.camera == m_state.sceneCamera))
            request.camera = m_state.image.camera;
        const std::optional<compare::StrategyLists> candidates = compare::pilotCandidates(
            compare::autoCandidates(*m_scene, {}, m_options.fixedSettings), request.settings);
        if (!candidates)
        {
            m_state.message = compare::kNoPilotForRestirDi;
            return;
        }
        try
        {
            compare::AutoChoice choice =
                compare::chooseStrategy(m_engine, request, *candidates, m_options.pilotBudget);
            m_state.image.request.settings = choice.chosen.applyTo(m_state.image.request.settings);
            m_state.message =
                choice.tooShort ? fmt::format("the image is too short to choose a strategy for (a pilot's share of it "
                                              "would measure nothing): the scene's own, {}",
                                              choice.chosen.name())
                : choice.rows.empty()
                    ? fmt::format("the scene leaves one strategy: {}", choice.chosen.name())
                    : fmt::format("strategy chosen by a pilot of {:.2f} s: {}", choice.pilotWallSeconds,
                                  choice.chosen.name());
            spdlog::info("{}\n{}", m_state.message, choice.table());
            m_pilot = std::move(choice);
        }
        catch (const Error& e)
        {
            m_state.message = std::string("the strategy pilot failed: ") + e.what();
            spdlog::error("{}", m_state.message);
        }
    }

    void savePlot(const std::filesystem::path& png)
    {
        try
        {
            const std::size_t points = rt::gui::savePlotFiles(m_plot, m_state.image.request, png);
            if (points == 0)
                throw UsageError("no plot to save: no point of this work has its relMSE yet");
            std::filesystem::path csv = png;
            m_state.message = fmt::format("saved the plot {} and its {} points {}", png.string(), points,
                                          csv.replace_extension(".csv").string());
            spdlog::info("{}", m_state.message);
        }
        catch (const Error& e)
        {
            m_state.message = std::string("the plot was not saved: ") + e.what();
            if (automated())
                throw;
            spdlog::error("{}", m_state.message);
        }
    }

    void save(const std::filesystem::path& png)
    {
        try
        {
            if (!m_state.image.rayTracing)
                throw UsageError("nothing to save: the window shows the rasterised preview; turn ray tracing on");
            // Before the first frame, or before the first frame of new settings (a save in the same frame as
            // the change): the accumulation image is empty or holds the old settings' samples.
            if (m_accumulatedSpp == 0 || !accumulationFits())
                throw UsageError("nothing to save yet: no frame rendered yet with the panel's settings (save after "
                                 "the first frame)");
            m_presenter.waitIdle();
            const Image image = m_renderer.readImage();
            const std::vector<std::filesystem::path> linear = writePngWithLinear(png, image);
            m_state.message = "saved " + png.string() + ", " + linear[0].string() + " and " + linear[1].string() + " (" +
                              std::to_string(m_accumulatedSpp) + " spp)";
            spdlog::info("{}", m_state.message);
        }
        catch (const Error& e)
        {
            m_state.message = e.what();
            if (automated())
                throw;
            spdlog::error("{}", e.what());
        }
    }

    PanelInfo panelInfo(Extent window) const
    {
        PanelInfo info;
        info.device = m_engine.deviceName();
        info.costAvailable = m_state.costAvailable;
        info.building = m_loading.valid() ? m_loadingId : std::string();
        info.sceneError = m_sceneError;
        info.microfacet = m_scene->hasMicrofacetMaterial();
        info.framesPerSecond = m_throughput.framesPerSecond();
        info.megaSamplesPerSecond = m_throughput.samplesPerSecond() * 1e-6;
        info.accumulatedSpp = static_cast<int>(m_accumulatedSpp);
        info.samplesPerFrame = static_cast<int>(frameSamples());
        if (m_state.engine != EngineKind::Gpu)
            info.engineStatus = m_cpu.busy() ? fmt::format("{}: rendering, {:.0f}%", rt::gui::engineLabel(m_state.engine),
                                                           100.0 * m_cpu.fraction())
                                             : m_cpuStatus;
        info.costMax = m_cost.max;
        info.costScale = costScale();
        info.costUnit = m_costUnit;
        info.window = window;
        info.image = m_state.image.extent();
        info.pilot = m_pilot ? &*m_pilot : nullptr;
        return info;
    }

    float costScale() const
    {
        // The automatic scale's floor only keeps an empty frame's zero away: a CPU map's microseconds are below 1.
        return m_state.display.autoCostScale ? (m_cost.high > 0.0f ? m_cost.high : 1.0f) : m_state.display.costScale;
    }

    /// The layout of a window of `framebuffer` pixels for the panel at the current font scale.
    WindowLayout layoutFor(Extent framebuffer) const
    {
        const float panelPixels = kPanelWidth * m_state.display.fontScale * framebufferScale();
        return layoutWindow(framebuffer, static_cast<int>(panelPixels), m_state.image.extent(),
                            ImGui::GetFontSize() * framebufferScale());
    }

    /// Framebuffer pixels per window coordinate (ImGui's coordinates): 1 on X11, 2 on a Retina display.
    static float framebufferScale() { return std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1e-3f); }

    void drawFrame(float seconds)
    {
        const Extent size = m_window.framebufferSize();
        m_imgui.newFrame(m_state.display.darkStyle, m_state.display.font, m_state.display.fontScale);
        applyCameraInput(m_window.handle(), m_controls, m_state.cameraSpeed * seconds);
        WindowLayout layout = layoutFor(size);
        const PixelRect panelDrawn =
            drawPanel(m_controls, m_state, panelInfo(size), m_panel, layout.panel, framebufferScale());
        drawLab(layout);

        const std::optional<Frame> frame = m_presenter.beginFrame(size);
        if (!frame)
        {
            m_imgui.render(VK_NULL_HANDLE);
            return;
        }
        const Extent frameExtent{static_cast<int>(frame->extent.width), static_cast<int>(frame->extent.height)};
        if (!(frameExtent == size))
            layout.image = layoutFor(frameExtent).image; // the swapchain held to its surface's limits
        const VkExtent2D traced = m_renderer.extent();
        if (int(traced.width) != m_state.image.extent().width || int(traced.height) != m_state.image.extent().height)
        {
            m_presenter.waitIdle();
            prepareImages(m_state.image.extent());
        }
        m_drawn = {frameExtent, panelDrawn, layout.image, layout.timings, layout.plot};
        if (const CostSummary cost = m_renderer.takeCostSummary(frame->slot); cost.max > 0.0f)
        {
            m_cost = cost;
            m_costUnit = "ticks per sample";
        }
        m_clock.take(m_renderer, frame->slot);

        const VkCommandBuffer cmd = frame->commands;
        std::uint64_t samples = 0;
        if (m_state.image.rayTracing)
            samples = m_state.engine == EngineKind::Gpu ? traceSamples(*frame) : traceReferences(*frame);
        m_presenter.beginRenderPass(*frame);
        if (m_state.image.rayTracing)
        {
            shader::DisplayPushConstants push{};
            push.mode = m_state.image.heatmap ? shader::DisplayMode::Cost : shader::DisplayMode::Radiance;
            push.encodeSrgb = m_presenter.shaderEncodesSrgb() ? 1u : 0u;
            push.costScale = costScale();
            m_display.record(cmd, layout.image, m_state.image.extent(), push);
        }
        else
            m_preview.record(cmd, m_state.image.camera, layout.image, m_state.image.request.settings.aspect,
                             m_presenter.shaderEncodesSrgb());
        m_imgui.render(cmd);
        m_presenter.endRenderPass(*frame);

        const bool last = automated() && actionsDone() && m_framesAfterActions + 1 >= *m_options.frames;
        if (last && !m_options.screenshot.empty())
            m_presenter.recordScreenshot(*frame);
        m_presenter.endFrame(*frame, size);
        m_throughput.add(Throughput::Clock::now(), samples);
        afterFrame();
        if (automated() && actionsDone() && ++m_framesAfterActions >= *m_options.frames)
        {
            if (!m_options.screenshot.empty())
                saveScreenshot();
            m_done = true;
        }
    }

    /// Records this frame's samples; returns the camera samples (paths) traced.
    std::uint64_t traceSamples(const Frame& frame)
    {
        const VkCommandBuffer cmd = frame.commands;
        const bool restart = m_needsClear || !accumulationFits();
        if (restart)
        {
            m_nextSample = 0; // a new image: its samples are those of a headless render from index 0
            startAccumulation(); // before the clear: its warm-up leaves a sample in the image
        }
        if (restart || !m_state.image.accumulate)
        {
            m_renderer.recordClear(cmd);
            m_accumulatedSpp = 0;
            m_needsClear = false;
        }
        m_traced = m_state.image;

        std::uint32_t count = frameSamples();
        if (m_state.display.stopAtSpp && m_state.image.accumulate)
        {
            const auto target = static_cast<std::uint32_t>(m_state.image.request.settings.trueSpp());
            count = std::min(count, target > m_accumulatedSpp ? target - m_accumulatedSpp : 0u);
        }
        if (count == 0)
            return m_references.recordSamples(cmd, frame.slot, frameSamples(), *m_scene, m_state.image.request.scene);
        m_renderer.recordSamples(cmd, frame.slot, requestOf(m_state.image), m_nextSample, count);
        m_clock.traced(frame.slot, count);
        // Without accumulation the indices still advance, so each frame shows new noise, not the same frame.
        m_nextSample += count;
        m_accumulatedSpp += count;
        const Extent image = m_state.image.extent();
        return std::uint64_t(count) * std::uint64_t(image.width) * std::uint64_t(image.height);
    }

    /// A CPU engine renders the image: the frames trace references only while it is idle (they would share the
    /// CPU with it on a CPU device), and the accumulation holds its last render (or is cleared, before the first).
    std::uint64_t traceReferences(const Frame& frame)
    {
        m_needsClear = true; // the GPU starts its image again when it is chosen
        if (!m_renderer.hasImage())
            m_renderer.recordClear(frame.commands);
        if (m_cpu.busy())
            return 0;
        return m_references.recordSamples(frame.commands, frame.slot, frameSamples(), *m_scene,
                                          m_state.image.request.scene);
    }

    /// The request a CPU engine renders for the panel: its settings, the window's camera where it moved.
    RenderRequest cpuRequest() const
    {
        RenderRequest request = m_state.image.request;
        if (!(m_state.image.camera == m_state.sceneCamera))
            request.camera = m_state.image.camera;
        return request;
    }

    /// The CPU engines' renders: the panel's image asked of the engine chosen once per change of its settings;
    /// the one that ended shown, timed in the table beside the GPU and measured against a reference on the GPU.
    void driveCpuRenders()
    {
        if (m_state.engine == EngineKind::Gpu || !m_state.image.rayTracing)
        {
            if (m_cpuSubmitted)
                m_cpu.cancel();
            m_cpuSubmitted.reset();
            m_cpuShown = false;
            return;
        }
        const CpuRender wanted{
            .request = cpuRequest(), .engine = m_state.engine, .scene = m_scene, .cost = m_state.image.heatmap};
        if (!m_cpuSubmitted || m_cpuSubmitted->request != wanted.request || m_cpuSubmitted->engine != wanted.engine ||
            m_cpuSubmitted->scene != wanted.scene || m_cpuSubmitted->cost != wanted.cost)
        {
            m_cpu.submit(wanted);
            m_cpuSubmitted = wanted;
            m_cpuShown = false;
        }
        std::optional<CpuOutcome> outcome = m_cpu.take();
        if (!outcome || outcome->render.request != wanted.request || outcome->render.engine != wanted.engine ||
            outcome->render.cost != wanted.cost)
            return; // none, or of settings left since
        if (!outcome->error.empty())
        {
            m_state.message = fmt::format("the {} render failed: {}", toString(outcome->render.engine), outcome->error);
            if (automated())
                throw Error(m_state.message);
            return;
        }
        const RenderResult& result = *outcome->result;
        if (result.image.width() != int(m_renderer.extent().width) ||
            result.image.height() != int(m_renderer.extent().height))
            return; // the images were made again for another size since
        m_presenter.waitIdle();
        m_renderer.showImage(result.image, outcome->cost.perSample);
        m_accumulatedSpp = std::uint32_t(result.stats.trueSpp);
        m_traced = m_state.image;
        m_cpuShown = true;
        m_cpuStatus = fmt::format("{}: {} spp in {:.3f} s", rt::gui::engineLabel(result.stats.engine),
                                  result.stats.trueSpp, result.stats.renderSeconds);
        if (wanted.cost)
        {
            // The heatmap's scale from the CPU's map, in its unit; its render is not a timing (the clock reads
            // around every pixel slow it), as the GPU's heatmap frames are not.
            if (!outcome->cost.empty())
            {
                const rt::CostSummary summary = rt::summarize(outcome->cost);
                m_cost = {.max = float(summary.max), .high = float(summary.high)};
                m_costUnit = outcome->cost.unit;
            }
            else
                m_state.message = "no heatmap: " + outcome->costUnavailable;
            return;
        }
        auto image = std::make_shared<const Image>(result.image);
        m_table.record(result.stats, {}, image);
        if (const auto task = m_table.referenceWanted(EngineKind::Gpu))
            m_references.request(*task, *m_scene);
        if (const auto task = m_plot.add(result.stats.request, result.stats.engine, result.stats.device,
                                         result.stats.renderSeconds, result.stats.trueSpp, image, EngineKind::Gpu,
                                         false))
            m_references.request(*task, *m_scene);
        attachReferences();
    }

    /// A new accumulation: its time from zero, its pipeline compiled and warmed up apart, no points yet.
    void startAccumulation()
    {
        m_clock.start(m_renderer, requestOf(m_state.image));
        m_points.clear();
    }

    /// Samples per pixel of the next frame: the panel's, or the automatic count.
    std::uint32_t frameSamples() const
    {
        return m_state.display.samplesPerFrame > 0 ? std::uint32_t(m_state.display.samplesPerFrame)
                                                   : m_clock.automaticSamples();
    }

    /// After a frame was submitted: a timed render's plot points (after 1, 2, 4, ... spp; a stratified one only at
    /// its end, whose strata the earlier samples do not cover) and its end go into the plot and the timings table,
    /// waiting for the device to read the image back and the samples' times; a reference half finished is read
    /// back; finished references are measured against.
    void afterFrame()
    {
        if (m_state.image.rayTracing && timedRender() && !m_clock.hasEnded() && m_accumulatedSpp > 0 &&
            accumulationFits())
        {
            const auto target = std::uint32_t(m_state.image.request.settings.trueSpp());
            const bool end = m_accumulatedSpp >= target;
            const bool stratified = requestOf(m_state.image).settings.sampling == PixelSampling::Stratified;
            if (end || (!stratified && m_clock.pointDue(m_accumulatedSpp)))
                recordEstimate(end);
        }
        if (m_references.halfRecorded())
        {
            m_presenter.waitIdle();
            m_references.finishHalf(*m_scene);
        }
        attachReferences();
    }

    /// Measures the table's rows and the plot's points against the references finished (or found) since.
    void attachReferences()
    {
        for (const rt::gui::FinishedReference& reference : m_references.take())
        {
            m_table.attach(reference);
            m_plot.attach(reference);
        }
    }

    /// The request the accumulation's samples are of: the panel's, at the spp traced, and the window's camera
    /// where it moved.
    RenderRequest tracedRequest() const
    {
        RenderRequest request = m_traced.request;
        request.settings.spp = int(m_accumulatedSpp);
        if (!(m_traced.camera == m_state.sceneCamera))
            request.camera = m_traced.camera;
        return request;
    }

    void recordEstimate(bool end)
    {
        m_presenter.waitIdle();
        m_clock.takeAll(m_renderer);
        m_clock.pointTaken(m_accumulatedSpp);
        if (end)
            m_clock.ended();
        const std::optional<double> seconds = m_clock.seconds();
        if (!seconds)
        {
            if (end)
                spdlog::warn("'{}' has no timestamps: the render is not timed", m_engine.deviceName());
            return;
        }
        const RenderRequest request = tracedRequest();
        auto image = std::make_shared<const Image>(m_renderer.readImage());
        // A point waits for its render's end: an accumulation the person abandons (a camera dragged with a stop set
        // restarts it every frame) would otherwise add a line and queue a reference per frame.
        m_points.push_back({request, *seconds, int(m_accumulatedSpp), image});
        if (!end)
            return;
        for (const EstimatePoint& point : std::exchange(m_points, {}))
            if (const auto task = m_plot.add(point.request, EngineKind::Gpu, m_engine.deviceName(), point.seconds,
                                             point.spp, point.image, EngineKind::Gpu, false))
                m_references.request(*task, *m_scene);
        RenderStats stats;
        stats.request = request;
        stats.engine = EngineKind::Gpu;
        stats.device = m_engine.deviceName();
        stats.width = request.settings.width;
        stats.height = request.settings.height();
        stats.trueSpp = int(m_accumulatedSpp);
        stats.renderSeconds = *seconds;
        stats.gpuSeconds = *seconds;
        stats.paths = std::uint64_t(stats.width) * std::uint64_t(stats.height) * m_accumulatedSpp;
        stats.buildSeconds = m_engine.buildSeconds();
        if (const std::optional<double> compile = m_clock.compileSeconds())
            stats.stageSeconds["pipeline_host"] = *compile;
        m_table.record(stats, {}, image);
        if (const auto task = m_table.referenceWanted(EngineKind::Gpu))
            m_references.request(*task, *m_scene);
    }

    /// The timings table and the convergence plot in the strip under the image.
    void drawLab(const WindowLayout& layout)
    {
        const LabPanesDrawn drawn =
            drawLabPanes(layout, framebufferScale(), m_table, m_plot, m_state.image.request,
                         m_references.progress(m_state.image.request.scene));
        m_latestTimingVisible = drawn.latestTimingVisible;
        m_plotState = drawn.plot;
        if (drawn.clearClicked)
        {
            m_table.clear();
            m_plot.clear();
            m_references.clear();
        }
        if (drawn.saveClicked)
            m_controls.savePlot(plotFileName(m_state.image.request));
    }

    /// --state-json: what the last frame drew where (framebuffer pixels, [x, y, width, height]), for the
    /// window tests to check the layout against the screenshot.
    void writeStateJson() const
    {
        const auto rect = [](const PixelRect& r) { return nlohmann::json::array({r.x, r.y, r.width, r.height}); };
        const Extent image = m_state.image.extent();
        const nlohmann::json state = {
            {"window", {m_drawn.window.width, m_drawn.window.height}},
            {"image_size", {image.width, image.height}},
            {"layout",
             {{"panel", rect(m_drawn.panel)},
              {"image", rect(m_drawn.image)},
              {"timings", rect(m_drawn.timings)},
              {"plot", rect(m_drawn.plot)},
              {"plot_drawn", m_plotState},
              {"latest_timing_visible", m_latestTimingVisible}}},
            {"timings", m_table.toJson()},
            {"plot", m_plot.toJson()},
            {"references_pending", m_references.pending(m_state.image.request.scene)},
            {"engine", rt::toString(m_state.engine)},
            {"cost_unit", m_costUnit},
            {"ray_tracing", m_state.image.rayTracing},
            {"accumulated_spp", m_accumulatedSpp},
            {"samples_per_frame", m_state.display.samplesPerFrame},
            {"font_pixels", m_controls.fontPixels()},
            {"roughness_scale", m_state.image.request.scene.options.roughnessScale},
            {"message", m_state.message},
            {"settings", toJson(m_state.image.request.settings)},
            {"strategy_choice", m_pilot ? m_pilot->toJson() : nlohmann::json()}};
        writeFileAtomically(m_options.stateJson, state.dump(2) + "\n");
    }

    void saveScreenshot()
    {
        int width = 0;
        int height = 0;
        const std::vector<unsigned char> rgba = m_presenter.screenshotPixels(width, height);
        writePng8(m_options.screenshot, width, height, rgba);
        spdlog::info("screenshot {} ({}x{}, {} spp)", m_options.screenshot.string(), width, height, m_accumulatedSpp);
    }

    const WindowOptions& m_options;
    VulkanWindow& m_window;
    GpuEngine m_engine;
    std::shared_ptr<Scene> m_scene; // what the engines render (they keep a pointer; a CPU render shares it)
    Presenter m_presenter;
    ProgressiveFrame m_renderer;
    RasterPreview m_preview;
    DisplayPass m_display;
    ImGuiLayer m_imgui;
    WindowReferences m_references;
    WindowState m_state;
    Controls m_controls;
    rt::gui::TimingsTable m_table;
    rt::gui::ConvergencePlot m_plot;
    AccumulationClock m_clock; // the accumulation's device time and frame sizes
    struct EstimatePoint
    {
        RenderRequest request;
        double seconds = 0.0;
        int spp = 0;
        std::shared_ptr<const Image> image;
    };
    std::vector<EstimatePoint> m_points; // the accumulation's plot points, added to the plot at its end
    bool m_waitReference = false; // the wait-reference action holds the script
    bool m_waitRender = false; // and the wait action
    std::optional<compare::AutoChoice> m_pilot; // the last strategy pilot's
    CpuRenders m_cpu;
    std::optional<CpuRender> m_cpuSubmitted; // the render asked of a CPU engine for the panel's settings
    bool m_cpuShown = false; // its image is in the accumulation
    std::string m_cpuStatus; // the last CPU render's spp and time
    PanelState m_panel;
    struct Drawn
    {
        Extent window;
        PixelRect panel; // as ImGui drew it
        PixelRect image;
        PixelRect timings;
        PixelRect plot;
    } m_drawn; // by the last frame, for --state-json
    nlohmann::json m_plotState; // the plot as drawn (PlotDrawn::state)
    bool m_latestTimingVisible = true;

    std::future<Scene> m_loading;
    std::string m_loadingId;
    std::int64_t m_loadingVersion = 0;
    bool m_loadingKeepsView = false;
    SceneFileWatch m_watch; // the scene file asked for last
    std::string m_sceneError;
    ImageSettings m_traced; // the settings of the samples in the accumulation image
    bool m_needsClear = true; // new images, or a new scene behind them
    std::uint32_t m_nextSample = 0;
    std::uint32_t m_accumulatedSpp = 0;
    CostSummary m_cost; // of the last timed frame (or the CPU engine's last map)
    std::string m_costUnit = "ticks per sample"; // of m_cost: the shader clock's, or the CPU's microseconds
    Throughput m_throughput;

    std::size_t m_nextAction = 0;
    int m_waitFrames = 0;
    Clock::time_point m_sleepUntil{};
    int m_framesAfterActions = 0;
    bool m_done = false;
};
} // namespace

int runWindow(const WindowOptions& options, Scene scene)
{
    std::shared_ptr<const vk::ValidationLog> log;
    {
        const bool defaultSize = !options.windowSize;
        const WindowSize size = defaultSize ? defaultWindowSize(options.initial.image.extent(), int(kPanelWidth),
                                                                kPanelFontPixels * options.initial.display.fontScale)
                                            : *options.windowSize;
        VulkanWindow window("ray-tracing-gpu", size, defaultSize);
        WindowApp app(options, window, std::move(scene));
        log = app.validationLog();
        app.run();
    } // the device is destroyed here: leaked objects are reported into `log`
    if (log && log->total() > 0)
    {
        spdlog::error("Vulkan validation reported {} warnings or errors (see above)", log->total());
        return 1;
    }
    return 0;
}
} // namespace rt::gpu::gui
