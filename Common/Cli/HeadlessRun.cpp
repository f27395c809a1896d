#include "Cli/HeadlessRun.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <thread>

#include <spdlog/fmt/fmt.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "Cli/Interrupt.h"
#include "Cluster/SplitRender.h"
#include "Error.h"
#include "Format.h"
#include "IO/AtomicFile.h"
#include "IO/FileExtension.h"
#include "IO/OutputSet.h"
#include "Image/Heatmap.h"
#include "Image/ImageIO.h"
#include "PrintableLine.h"
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
    checkDistinctOutputs({{"--output", &o.output}, {"--hdr", &o.hdr}, {"--stats", &o.stats}, {"--heatmap", &o.heatmap}});
}

void checkDistinctOutputs(std::initializer_list<std::pair<const char*, const std::string*>> outputs)
{
    std::vector<std::pair<const char*, std::filesystem::path>> seen;
    for (const auto& [flag, path] : outputs)
    {
        if (path->empty())
            continue;
        std::filesystem::path target;
        outputTargetProblem(*path, target); // a problem is checkWritable's to name
        std::error_code ec;
        const std::filesystem::path resolved = resolvedPath(target, ec);
        for (const auto& [other, otherPath] : seen)
            if (!ec && resolved == otherPath)
                throw UsageError(fmt::format("{} and {} name the same file '{}': give each its own", other, flag,
                                             *path));
        seen.emplace_back(flag, resolved);
    }
}

namespace
{
/// Root of a split render: the shares' sums added (Cluster/Job.h's sumToRoot) and divided as one process's
/// engine divides its own (CpuEngine::estimate), and the stats of the whole job from every rank's.
void mergeShares(std::vector<double> sums, cluster::Job& job, const cluster::Verdict& verdict, RenderResult& result,
                 std::uint32_t frameSamples)
{
    job.sumToRoot(sums);
    if (!job.root())
        return;
    RenderStats& st = result.stats;
    Image image(st.width, st.height);
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        image.data()[i] = vec3(dvec3(sums[3 * i], sums[3 * i + 1], sums[3 * i + 2]) / double(frameSamples));
    result.image = std::move(image);
    st.trueSpp = static_cast<int>(frameSamples);
    st.paths = st.nanSamples = st.infSamples = 0;
    st.rays = {};
    st.lightSamples = {};
    st.raysCounted = !verdict.ranks.empty();
    st.threadsUsed = 0;
    st.renderSeconds = 0.0;
    for (const nlohmann::json& r : verdict.ranks)
    {
        st.paths += r.at("paths").get<std::uint64_t>();
        // The job's rays are every rank's, counted only where every rank counted them.
        st.raysCounted = st.raysCounted && r.contains("rays");
        if (r.contains("rays"))
        {
            st.rays += rayCountsFromJson(r.at("rays"));
            st.lightSamples += lightSampleCountsFromJson(r.at("light_samples"));
        }
        st.nanSamples += r.at("nan_samples").get<std::uint64_t>();
        st.infSamples += r.at("inf_samples").get<std::uint64_t>();
        st.threadsUsed += r.at("threads_used").get<int>();
        // The job's render takes as long as its slowest share.
        st.renderSeconds = std::max(st.renderSeconds, r.at("render_seconds").get<double>());
        if (st.gpuSeconds >= 0.0)
            st.gpuSeconds =
                r.contains("gpu_seconds") ? std::max(st.gpuSeconds, r.at("gpu_seconds").get<double>()) : -1.0;
    }
    st.ranks = verdict.ranks;
}
} // namespace

int runHeadless(RenderEngine& engine, const Scene& scene, const RenderRequest& asked, const CommonOptions& o,
                const RequestChooser& chooser)
{
    cluster::Job& job = cluster::job();
    if (job.root())
        checkOutputPaths(o); // root alone writes (on its host's folders)
    RequestChooser choose = chooser;
    if (job.distributed() && choose)
    {
        // A pilot measures one process's engine; the ranks must render one strategy, so none chooses.
        if (o.strategyGiven)
            throw UsageError("--strategy auto chooses on one process: run it without mpirun, then render the "
                             "strategy it names on the ranks");
        if (job.root())
            spdlog::info("over {} ranks: the scene's own strategy (--strategy auto chooses on one process)",
                         job.size());
        choose = {};
    }
    if (job.distributed() && 3ull * std::uint64_t(asked.settings.width) * std::uint64_t(asked.settings.height()) >
                                 std::uint64_t(std::numeric_limits<int>::max()))
        throw UsageError(fmt::format("a {}x{} image is more values than one MPI reduction holds (2^31 - 1): split it "
                                     "over mpirun's ranks in tiles of your own, or render it as one process",
                                     asked.settings.width, asked.settings.height()));
    if (!o.heatmap.empty())
    {
        if (job.root())
            checkOutputPath(o.heatmap, "--heatmap", {".png", ".pfm", ".exr"});
        if (job.distributed())
            throw UsageError("--heatmap times each pixel on one process: run it without mpirun");
    }
    if (job.distributed() && asked.settings.estimator == Estimator::RestirDi)
        throw UsageError("restir-di's reservoirs carry each sample to the next, so its samples cannot be split over "
                         "mpirun's ranks: run it as one process");
    spdlog::info("scene {}: {} primitives, {} lights; {} engine on {}", scene.id, scene.primitiveCount(),
                 scene.lights.size(), toString(engine.kind()), engine.deviceName());
    const double build = engine.setScene(scene);
    spdlog::info("acceleration structures built in {:.3f} s", build);

    RenderControl control;
    RenderResult result;
    ChosenRequest chosen{asked, nullptr, false};
    std::optional<cluster::SplitRender> split;
    FramePart part;
    const auto frameSamples = static_cast<std::uint32_t>(asked.settings.trueSpp());
    if (job.distributed())
    {
        split.emplace(job, control);
        part = cluster::shareOf(frameSamples, job.rank(), job.size());
        part.beforeBatch = [&] { split->beforeBatch(); };
        spdlog::info("{} ranks: samples {}..{} of {} on this one", job.size(), part.firstSample,
                     part.firstSample + *part.samples, frameSamples);
    }
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
        if (!o.heatmap.empty())
        {
            if (const std::string why = engine.costUnavailable(chosen.request.settings); !why.empty())
                throw UsageError("--heatmap: " + why);
            engine.setCostRecording(true);
        }
        InterruptScope::route(&control);
        ProgressPrinter progress(control, !o.quiet && job.root());
        result = render(engine, chosen.request, control, {}, part);
        if (split)
        {
            using Status = cluster::PartEnd::Status;
            cluster::PartEnd mine{.status = result.stats.cancelled ? Status::Cancelled : Status::Finished,
                                  .stats = cluster::rankStats(job, part, result.stats)};
            std::vector<double> sums; // read before the verdict: a rank that cannot is a failed part, not a hang
            if (mine.status == Status::Finished)
            {
                try
                {
                    sums = engine.radianceSums();
                }
                catch (const Error& e)
                {
                    mine = {.status = Status::Failed, .message = e.what(), .exitCode = e.exitCode()};
                }
            }
            const cluster::Verdict verdict = split->end(mine);
            if (verdict.status == Status::Failed)
                return cluster::endFailedJob(job, verdict);
            if (verdict.status == Status::Cancelled)
            {
                if (job.root())
                    spdlog::warn("render cancelled after {:.1f} s: no file written", result.stats.renderSeconds);
                // mpirun, ending the job, no longer lets MPI_Finalize finish: exit before its SIGKILL.
                job.leave(130);
            }
            try
            {
                mergeShares(std::move(sums), job, verdict, result, frameSamples);
            }
            catch (const std::exception& e)
            {
                // Past the verdict the ranks are in the reduction: one that fails there ends the job.
                std::fprintf(stderr, "error: %s: %s\n", job.name(job.rank()).c_str(), printableLine(e.what()).c_str());
                job.abandon(1);
            }
            if (!job.root())
                return 0;
        }
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
    if (!o.heatmap.empty())
    {
        const CostMap cost = engine.costMap();
        if (cost.empty())
            throw Error("--heatmap: the engine recorded no cost"); // costUnavailable said it would
        result.stats.heatmap = toJson(cost, summarize(cost));
        // By --heatmap's extension, not the temporary's.
        outputs.add(o.heatmap, [cost, format = heatmapFormatOf(o.heatmap)](const std::filesystem::path& tmp) {
            writeHeatmap(tmp, cost, format);
        });
    }
    if (!o.stats.empty())
        outputs.add(o.stats, [&](const std::filesystem::path& tmp) { writeStatsJson(tmp, result.stats); });
    outputs.commit();
    const RenderStats& s = result.stats;
    const RenderSettings& settings = request.settings;
    std::string written;
    for (const std::string& file : {o.output, o.hdr, o.heatmap, o.stats})
        if (!file.empty())
            written += (written.empty() ? ", wrote " : ", ") + file;
    const std::string ranks = job.distributed() ? fmt::format(" on {} ranks", job.size()) : std::string();
    // The GPU's pipeline creation and a first launch of each new one, where a driver may finish compiling (on
    // its first use of them, seconds on lavapipe; then from its cache), are named apart from the render's time.
    std::string setup = fmt::format("{:.3f} s", s.buildSeconds);
    if (const auto compile = s.stageSeconds.find("pipeline_host"); compile != s.stageSeconds.end())
        setup += fmt::format(", pipelines {:.3f} s", compile->second);
    std::string rays = s.raysCounted ? fmt::format(" ({:.2f} Mrays/s: camera {:.2f}, extension {:.2f}, shadow {:.2f})",
                                                    s.mraysPerSecond(s.rays.total()), s.mraysPerSecond(s.rays.camera),
                                                    s.mraysPerSecond(s.rays.extension), s.mraysPerSecond(s.rays.shadow))
                                     : std::string();
    // The samplers' shortcuts are said where they were taken (LightSample.h): share of NEE's samples.
    const LightSampleCounts& ls = s.lightSamples;
    if (s.raysCounted && ls.drawn > 0 && ls.fallback + ls.declined > 0)
        rays += fmt::format(", light samples {:.2f} % by a fallback sampler, {:.2g} % declined",
                            100.0 * double(ls.fallback) / double(ls.drawn), 100.0 * double(ls.declined) / double(ls.drawn));
    std::printf("%s: %dx%d, %d spp (%s, %s), depth %d, %s engine%s: render %.3f s, build %s, %.2f Mpaths/s%s, "
                "NaN %llu, Inf %llu%s\n",
                request.scene.id.c_str(), s.width, s.height, s.trueSpp, toString(settings.sampling), estimatorLabel(settings).c_str(),
                settings.depth, toString(s.engine), ranks.c_str(), s.renderSeconds, setup.c_str(), s.mpathsPerSecond(),
                rays.c_str(), static_cast<unsigned long long>(s.nanSamples), static_cast<unsigned long long>(s.infSamples),
                written.c_str());
    return 0;
}

int guardedMain(CLI::App& app, int argc, char** argv, const std::function<int()>& body)
{
    // Every log line (info, warnings, errors) on stderr: stdout carries only what a script reads (the summary
    // line, the tables of --compare, --list-scenes).
    spdlog::set_default_logger(spdlog::stderr_color_mt("rt"));
    // Joins mpirun's job, when it started this process, before any thread (docs/SCALING.md).
    std::optional<cluster::JobScope> joined;
    try
    {
        joined.emplace();
    }
    catch (const Error& e)
    {
        std::fprintf(stderr, "error: %s\n", printableLine(e.what()).c_str());
        return e.exitCode();
    }
    cluster::Job& job = cluster::job();
    configureLogging(false);
    // The other ranks' stdout (help, lists, summaries) is root's.
    if (!job.root() && !std::freopen("/dev/null", "w", stdout))
        std::fclose(stdout);
    // An error on one of a job's ranks ends the job (Cluster/SplitRender.h): root prints the one line, naming the
    // rank unless every rank failed alike (a bad flag).
    const auto fail = [&](const std::string& message, int exitCode) {
        if (const std::optional<cluster::Verdict> verdict =
                cluster::SplitRender::endAfterError(job, message, exitCode))
            return cluster::endFailedJob(job, *verdict);
        std::fprintf(stderr, "error: %s%s\n", job.distributed() ? (job.name(job.rank()) + ": ").c_str() : "",
                     printableLine(message).c_str());
        return exitCode;
    };
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
            return fail(name + " is given more than once: give it once (see --help)", 2);
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
    catch (const CLI::ExtrasError&)
    {
        // CLI11 lists them last first ("32 -w"): in the order given.
        std::string given;
        for (const std::string& extra : app.remaining())
            given += (given.empty() ? "" : " ") + extra;
        return fail(fmt::format("not a flag of this app, or a value no flag takes: '{}' (see --help)", given), 2);
    }
    catch (const CLI::ParseError& e)
    {
        return fail(std::string(e.what()) + " (see --help)", 2);
    }
    try
    {
        return body();
    }
    catch (const Error& e)
    {
        return fail(e.what(), e.exitCode());
    }
    catch (const std::bad_alloc&)
    {
        // Past the up-front estimate (Render/MemoryBudget.h), e.g. memory taken by another process meanwhile.
        return fail("out of memory (the render needed more than the machine could give)", 1);
    }
    catch (const std::exception& e)
    {
        return fail(e.what(), 1);
    }
}
} // namespace rt
