#include "Cli/HeadlessRun.h"

#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <new>
#include <set>
#include <thread>

#include <spdlog/fmt/fmt.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "Cli/Interrupt.h"
#include "Error.h"
#include "Format.h"
#include "IO/OutputSet.h"
#include "Image/ImageIO.h"
#include "Render/RenderDriver.h"

#ifndef _WIN32
#include <unistd.h>
#endif

namespace rt
{
namespace
{

bool stderrIsTerminal()
{
#ifdef _WIN32
    return false;
#else
    return isatty(fileno(stderr)) != 0;
#endif
}

/// Prints "[####      ]  42%  12.1 s, ETA 16.4 s" on stderr: in place on a terminal, every 10 % otherwise.
class ProgressPrinter
{
public:
    ProgressPrinter(const RenderControl& control, bool enabled) : m_control(control)
    {
        if (enabled)
            m_thread = std::thread([this] { loop(); });
    }
    ~ProgressPrinter()
    {
        if (!m_thread.joinable())
            return;
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }

private:
    void loop()
    {
        const bool tty = stderrIsTerminal();
        int lastDecile = -1;
        std::unique_lock lock(m_mutex);
        while (!m_wake.wait_for(lock, std::chrono::milliseconds(tty ? 250 : 1000), [this] { return m_stop; }))
        {
            const double f = m_control.fraction();
            const int decile = static_cast<int>(f * 10.0);
            if (!tty && decile == lastDecile)
                continue;
            lastDecile = decile;
            const int filled = static_cast<int>(f * 30.0);
            const double eta = m_control.etaSeconds();
            std::fprintf(stderr, "%s[%s%s] %3d%%  %.1f s elapsed, ETA %s%s", tty ? "\r" : "",
                         std::string(filled, '#').c_str(), std::string(30 - filled, ' ').c_str(),
                         static_cast<int>(f * 100.0), m_control.elapsedSeconds(),
                         eta < 0 ? "?" : fmt::format("{:.1f} s", eta).c_str(), tty ? "   " : "\n");
            std::fflush(stderr);
        }
        if (tty)
            std::fprintf(stderr, "\r%70s\r", "");
    }

    const RenderControl& m_control;
    std::thread m_thread;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
};

/// ".png" of "OUT.PNG": the extension as the checks compare it.
std::string lowercaseExtension(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}
} // namespace

void checkOutputPath(const std::string& path, const char* flag, std::initializer_list<const char*> extensions)
{
    if (path.empty())
        return;
    const std::filesystem::path p(path);
    const std::string extension = lowercaseExtension(p);
    bool known = false;
    for (const char* e : extensions)
        known |= extension == e; // OUT.PNG is a PNG too
    if (!known)
    {
        std::string list;
        for (const char* e : extensions)
            list += (list.empty() ? "" : " or ") + std::string(e);
        throw UsageError(fmt::format("{} '{}' must end in {}", flag, path, list));
    }
    checkWritable(p, flag);
}

void checkOutputPaths(const CommonOptions& o)
{
    checkOutputPath(o.output, "--output", {".png"});
    checkOutputPath(o.hdr, "--hdr", {".pfm", ".exr"});
    checkOutputPath(o.stats, "--stats", {".json"});
}

int runHeadless(RenderEngine& engine, const Scene& scene, const RenderRequest& asked, const CommonOptions& o,
                const RequestChooser& choose)
{
    checkOutputPaths(o);
    spdlog::info("scene {}: {} primitives, {} lights; {} engine on {}", scene.id, scene.primitiveCount(),
                 scene.lights.size(), toString(engine.kind()), engine.deviceName());
    const double build = engine.setScene(scene);
    spdlog::info("acceleration structures built in {:.3f} s", build);

    RenderControl control;
    RenderResult result;
    ChosenRequest chosen{asked, nullptr, false};
    {
        InterruptScope interrupt;
        if (choose)
            chosen = choose(engine, asked);
        if (chosen.cancelled)
        {
            spdlog::warn("cancelled while choosing the strategy: no file written");
            return 130;
        }
        spdlog::info("settings: {}", chosen.request.settings); // the scene's defaults with the flags applied
        InterruptScope::route(&control);
        ProgressPrinter progress(control, !o.quiet);
        result = render(engine, chosen.request, control);
    }
    const RenderRequest& request = chosen.request;
    result.stats.strategyChoice = chosen.record;
    if (result.stats.cancelled)
    {
        spdlog::warn("render cancelled after {:.1f} s: no file written", result.stats.renderSeconds);
        return 130;
    }
    // All or none: a stats file that cannot be written must not leave the PNG behind.
    OutputSet outputs;
    if (!o.output.empty())
        outputs.add(o.output, [&](const std::filesystem::path& tmp) { writePng(tmp, result.image); });
    if (!o.hdr.empty())
    {
        // By --hdr's extension, not the temporary's.
        const bool exr = lowercaseExtension(o.hdr) == ".exr";
        const ExrPixelType type = o.hdrType == "float" ? ExrPixelType::Float : ExrPixelType::Half;
        outputs.add(o.hdr, [&, exr, type](const std::filesystem::path& tmp) {
            exr ? writeExr(tmp, result.image, type) : writePfm(tmp, result.image);
        });
    }
    if (!o.stats.empty())
        outputs.add(o.stats, [&](const std::filesystem::path& tmp) { writeStatsJson(tmp, result.stats); });
    outputs.commit();
    const RenderStats& s = result.stats;
    const RenderSettings& settings = request.settings;
    std::string written;
    for (const std::string& file : {o.output, o.hdr, o.stats})
        if (!file.empty())
            written += (written.empty() ? ", wrote " : ", ") + file;
    std::printf("%s: %dx%d, %d spp (%s, %s), depth %d, %s engine: render %.3f s, build %.3f s, %.2f Mpaths/s, "
                "NaN %llu, Inf %llu%s\n",
                request.scene.id.c_str(), s.width, s.height, s.trueSpp, toString(settings.sampling), estimatorLabel(settings).c_str(),
                settings.depth, toString(s.engine), s.renderSeconds, s.buildSeconds, s.mpathsPerSecond(),
                static_cast<unsigned long long>(s.nanSamples), static_cast<unsigned long long>(s.infSamples),
                written.c_str());
    return 0;
}

int guardedMain(CLI::App& app, int argc, char** argv, const std::function<int()>& body)
{
    // Every log line (info, warnings, errors) on stderr: stdout carries only what a script reads (the summary
    // line, the tables of --compare, --list-scenes).
    spdlog::set_default_logger(spdlog::stderr_color_mt("rt"));
    spdlog::set_pattern("%^%l%$: %v");
    // A flag of one value given twice is refused (which one was meant?), in words rather than CLI11's "At Most 1
    // required but received 2".
    std::set<std::string> seen;
    for (int i = 1; i < argc; ++i)
    {
        const std::string token = argv[i];
        if (token.rfind("--", 0) != 0)
            continue;
        const std::string name = token.substr(0, token.find('='));
        const CLI::Option* option = app.get_option_no_throw(name);
        if (option && option->get_items_expected_max() <= 1 && !seen.insert(name).second)
        {
            std::fprintf(stderr, "error: %s is given more than once: give it once (see --help)\n", name.c_str());
            return 2;
        }
    }
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::CallForHelp& e)
    {
        return app.exit(e);
    }
    catch (const CLI::CallForVersion& e)
    {
        return app.exit(e);
    }
    catch (const CLI::ParseError& e)
    {
        std::fprintf(stderr, "error: %s (see --help)\n", e.what());
        return 2;
    }
    try
    {
        return body();
    }
    catch (const Error& e)
    {
        std::fprintf(stderr, "error: %s\n", e.what());
        return e.exitCode();
    }
    catch (const std::bad_alloc&)
    {
        // Past the up-front estimate (Render/MemoryBudget.h), e.g. memory taken by another process meanwhile.
        std::fprintf(stderr, "error: out of memory (the render needed more than the machine could give)\n");
        return 1;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
} // namespace rt
