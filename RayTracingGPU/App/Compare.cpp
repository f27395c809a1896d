#include "App/Compare.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "IO/AtomicFile.h"
#include "Image/ImageIO.h"
#include "Image/Metrics.h"
#include "Render/RenderDriver.h"

namespace rt::app
{
namespace
{
std::vector<std::string> split(const std::string& text)
{
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');)
        parts.push_back(part);
    return parts;
}

struct Run
{
    double renderMs = 0.0; // host clock around the tracing
    double gpuMs = -1.0; // GPU timestamps, when the engine has them
    double mpaths = 0.0;
    ErrorMetrics error;
    Image image;
};

/// `request` with `spp` samples per pixel and `seedOffset` added to its seed.
RenderRequest withSpp(RenderRequest request, int spp, std::uint32_t seedOffset = 0)
{
    request.settings.spp = spp;
    request.settings.seed += seedOffset;
    return request;
}

Run timedRender(RenderEngine& engine, const RenderRequest& request)
{
    RenderControl control;
    RenderResult r = render(engine, request, control);
    if (r.stats.nanSamples + r.stats.infSamples > 0)
        spdlog::warn("{} engine: {} NaN and {} Inf samples", toString(engine.kind()), r.stats.nanSamples,
                     r.stats.infSamples);
    return {r.stats.renderSeconds * 1e3, r.stats.gpuSeconds >= 0 ? r.stats.gpuSeconds * 1e3 : -1.0,
            r.stats.mpathsPerSecond(), {}, std::move(r.image)};
}
} // namespace

std::vector<int> parseSppList(const std::string& text)
{
    std::vector<int> spps;
    for (const std::string& part : split(text))
    {
        const auto value = parseInteger(part);
        if (!value || *value < 1 || *value > std::numeric_limits<int>::max())
            throw UsageError(fmt::format("--spp-list must be positive integers separated by commas (got '{}')", text));
        spps.push_back(static_cast<int>(*value));
    }
    if (spps.empty())
        throw UsageError("--spp-list is empty");
    return spps;
}

std::vector<EngineKind> parseEngineList(const std::string& text)
{
    std::vector<EngineKind> engines;
    for (const std::string& part : split(text))
    {
        const auto e = parseEngine(part);
        if (!e)
            throw UsageError(fmt::format("--engines takes single, multi and gpu (got '{}')", part));
        engines.push_back(*e);
    }
    if (engines.empty())
        throw UsageError("--engines is empty");
    return engines;
}

int runComparison(const Scene& scene, const RenderRequest& baseRequest, const CompareOptions& options,
                  const std::function<std::unique_ptr<RenderEngine>(EngineKind)>& makeEngine)
{
    const RenderSettings& base = baseRequest.settings;
    // One engine of each kind, its acceleration structures built once.
    std::vector<std::pair<EngineKind, std::unique_ptr<RenderEngine>>> engines;
    for (const EngineKind kind : options.engines)
    {
        try
        {
            auto engine = makeEngine(kind);
            const double build = engine->setScene(scene);
            spdlog::info("{} engine on {}: acceleration structures in {:.3f} s", toString(kind), engine->deviceName(),
                         build);
            engines.emplace_back(kind, std::move(engine));
        }
        catch (const DeviceError& e)
        {
            spdlog::warn("{} engine left out: {}", toString(kind), e.what());
        }
    }
    if (engines.empty())
        throw DeviceError("no engine could start");

    // The reference: a file, or the last engine (the GPU when there is one) at referenceSpp with an
    // independent seed.
    Image reference;
    if (!options.referencePath.empty())
    {
        reference = readPfm(options.referencePath);
        if (reference.width() != base.width || reference.height() != base.height())
            throw UsageError(fmt::format("--reference {} is {}x{}; the comparison renders {}x{}",
                                         options.referencePath, reference.width(), reference.height(), base.width,
                                         base.height()));
        spdlog::info("reference: {}", options.referencePath);
    }
    else
    {
        RenderEngine& refEngine = *engines.back().second;
        const RenderRequest refRequest = withSpp(baseRequest, options.referenceSpp, 1000);
        spdlog::info("reference: {} spp on the {} engine", options.referenceSpp, toString(refEngine.kind()));
        reference = timedRender(refEngine, refRequest).image;
    }

    nlohmann::json json;
    json["scene"] = scene.id;
    json["width"] = base.width;
    json["height"] = base.height();
    json["depth"] = base.depth;
    json["estimator"] = toString(base.estimator);
    json["sampling"] = toString(base.sampling);
    json["light_sampler"] = toString(base.lightSampler);
    json["light_selection"] = toString(base.lightSelection);
    json["russian_roulette"] = base.russianRoulette;
    if (options.referencePath.empty())
        json["reference_spp"] = options.referenceSpp;
    else
        json["reference"] = options.referencePath;
    json["relmse_epsilon"] = kRelMseEpsilon;
    for (const auto& [kind, engine] : engines)
        json["devices"][toString(kind)] = engine->deviceName();

    std::string header = fmt::format("{:>6}", "spp");
    for (const auto& [kind, engine] : engines)
        header += fmt::format(" | {:>9} {:>9}", fmt::format("{} ms", toString(kind)), "relMSE");
    const bool ratio = engines.size() > 1 && engines.back().first == EngineKind::Gpu;
    if (ratio)
        header += fmt::format(" | {:>10} | {:>11}", "CPU/GPU", "relMSE C-G");

    // Each engine runs all its rows back to back, after half a second of untimed warm-up renders: a GPU
    // idle through the CPU's turn drops its clocks, and an H100 then ran its first rows 3-10x slower; row
    // by row interleaving with 16-thread CPU renders cost it 2-3x (docs/PERFORMANCE.md).
    std::vector<std::vector<Run>> runs(options.spps.size());
    for (const auto& [kind, engine] : engines)
    {
        const RenderRequest warmUp = withSpp(baseRequest, 4);
        const auto warmStart = std::chrono::steady_clock::now();
        for (int i = 0; i < 1000 && std::chrono::steady_clock::now() - warmStart < std::chrono::milliseconds(500); ++i)
            timedRender(*engine, warmUp);
        for (std::size_t row = 0; row < options.spps.size(); ++row)
        {
            const RenderRequest request = withSpp(baseRequest, options.spps[row]);
            Run run = timedRender(*engine, request);
            run.error = compareImages(run.image, reference);
            spdlog::info("{} engine, {} spp: {:.1f} ms", toString(kind), request.settings.trueSpp(),
                         run.gpuMs >= 0 ? run.gpuMs : run.renderMs);
            runs[row].push_back(std::move(run));
        }
    }

    const std::string against = options.referencePath.empty() ? fmt::format("{} spp", options.referenceSpp)
                                                              : options.referencePath;
    std::printf("\n%s: %dx%d, depth %d, %s estimator (%s light sampler, %s selection, roulette %s), %s "
                "sampling; relMSE against %s (epsilon %g)\n",
                scene.id.c_str(), base.width, base.height(), base.depth, toString(base.estimator),
                toString(base.lightSampler), toString(base.lightSelection), base.russianRoulette ? "on" : "off",
                toString(base.sampling), against.c_str(), kRelMseEpsilon);
    std::printf("%s\n%s\n", header.c_str(), std::string(header.size(), '-').c_str());
    for (std::size_t rowIndex = 0; rowIndex < options.spps.size(); ++rowIndex)
    {
        const RenderSettings s = withSpp(baseRequest, options.spps[rowIndex]).settings;
        std::string row = fmt::format("{:>6}", s.trueSpp());
        nlohmann::json jrow;
        jrow["spp"] = s.trueSpp();
        const Run* gpu = nullptr;
        const Run* cpu = nullptr; // the fastest CPU engine of the row
        for (std::size_t e = 0; e < engines.size(); ++e)
        {
            const EngineKind kind = engines[e].first;
            const Run& run = runs[rowIndex][e];
            const double ms = run.gpuMs >= 0 ? run.gpuMs : run.renderMs;
            row += fmt::format(" | {:>9.1f} {:>9.2e}", ms, run.error.relMse);
            jrow[toString(kind)] = {{"render_ms", run.renderMs},
                                    {"gpu_ms", run.gpuMs},
                                    {"mpaths_per_second", run.mpaths},
                                    {"relmse", run.error.relMse},
                                    {"rmse", run.error.rmse}};
            if (kind == EngineKind::Gpu)
                gpu = &run;
            else if (!cpu || run.renderMs < cpu->renderMs)
                cpu = &run;
        }
        if (ratio && gpu && cpu)
        {
            const double gpuMs = gpu->gpuMs >= 0 ? gpu->gpuMs : gpu->renderMs;
            const double between = compareImages(cpu->image, gpu->image).relMse;
            row += fmt::format(" | {:>9.1f}x | {:>11.2e}", cpu->renderMs / gpuMs, between);
            jrow["cpu_over_gpu"] = cpu->renderMs / gpuMs;
            jrow["relmse_cpu_gpu"] = between;
        }
        std::printf("%s\n", row.c_str());
        json["rows"].push_back(jrow);
    }
    std::printf("(GPU ms from timestamp queries around the trace dispatches; CPU ms from the host clock; "
                "CPU/GPU uses the fastest CPU engine of the row)\n");
    if (!options.json.empty())
        writeFileAtomically(options.json, json.dump(2) + "\n");
    return 0;
}
} // namespace rt::app
