#include "Compare/ComparisonRun.h"

#include <algorithm>
#include <numeric>

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "Compare/PythonScript.h"
#include "Compare/ReferenceCache.h"
#include "Compare/ReferenceRequest.h"
#include "Error.h"
#include "Image/Flip.h"
#include "Image/ImageIO.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
namespace
{
RenderRequest referenceRequest(const RenderRequest& base, const CompareOptions& options)
{
    return compare::referenceRequest(base, options.referenceSpp);
}

int halfSpp(const CompareOptions& options)
{
    return referenceHalfSpp(options.referenceSpp);
}
} // namespace

std::optional<Reference> givenReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                                        EngineKind last)
{
    if (!options.referencePath.empty())
    {
        Image reference = readLinearImage(options.referencePath);
        if (reference.width() != base.settings.width || reference.height() != base.settings.height())
            throw UsageError(fmt::format("--reference {} is {}x{}; the comparison renders {}x{}", options.referencePath,
                                         reference.width(), reference.height(), base.settings.width,
                                         base.settings.height()));
        std::size_t notFinite = 0;
        for (std::size_t i = 0; i < reference.pixelCount(); ++i)
            notFinite += isFinite(reference.data()[i]) ? 0 : 1;
        if (notFinite > 0)
            throw UsageError(fmt::format("--reference {}: {} of its pixels are not finite (NaN or Inf): no relMSE can "
                                         "be measured against it",
                                         options.referencePath, notFinite));
        spdlog::info("reference: {}", options.referencePath);
        return Reference{std::move(reference), std::nullopt, options.referencePath, 0};
    }
    const std::string description = fmt::format("{} spp", 2 * halfSpp(options));
    const ReferenceCache cache(options.referenceCache);
    std::optional<TwoHalfReference> cached = cache.find(scene, referenceRequest(base, options), last);
    if (!cached)
        return std::nullopt;
    std::fprintf(stderr, "reference: %s on the %s engine, from the cache (%s)\n", description.c_str(), toString(last),
                 options.referenceCache.string().c_str());
    return Reference{std::move(cached->mean), cached->ownRelMse, description, 2 * halfSpp(options)};
}

RenderRequest referenceHalf(const RenderRequest& base, const CompareOptions& options, int half)
{
    return referenceHalfRequest(base, options.referenceSpp, half);
}

Reference finishReference(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                          EngineKind last, const Measurement& a, const Measurement& b)
{
    TwoHalfReference combined = combineReferenceHalves(a.image, b.image);
    std::fprintf(stderr, "reference: %.1f s; its own relMSE %.3g (from its halves)\n", (a.wallMs + b.wallMs) * 1e-3,
                 combined.ownRelMse);
    const ReferenceCache cache(options.referenceCache);
    const auto stored = cache.store(scene, referenceRequest(base, options), last, combined);
    if (!stored.empty())
        std::fprintf(stderr, "reference: cached as %s\n", stored.string().c_str());
    return Reference{std::move(combined.mean), combined.ownRelMse, fmt::format("{} spp", 2 * halfSpp(options)),
                     2 * halfSpp(options)};
}

void warnNearReferenceNoise(const Reference& reference, const std::vector<double>& relMses)
{
    if (!reference.ownRelMse)
        return;
    const double floor = *reference.ownRelMse;
    const auto near = std::count_if(relMses.begin(), relMses.end(), [&](double e) { return e < 3.0 * floor; });
    if (near == 0)
        return;
    spdlog::warn("{} of {} renders have a relMSE below 3x the reference's own ({:.3g}; the smallest {:.3g}): a "
                 "third or more of their error is the reference's noise; raise --reference-spp",
                 near, relMses.size(), floor, *std::min_element(relMses.begin(), relMses.end()));
}

nlohmann::json tableHead(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                         const std::vector<EngineUnderTest>& engines, const Reference& reference)
{
    const RenderSettings& b = base.settings;
    nlohmann::json json = toJson(b);
    json.erase("spp");
    json["scene"] = scene.id;
    json["height"] = b.height();
    if (options.referencePath.empty())
        json["reference_spp"] = reference.spp;
    else
        json["reference"] = options.referencePath;
    json["relmse_epsilon"] = kRelMseEpsilon;
    json["metric"] = toString(options.metric);
    json["reference_relmse"] = reference.ownRelMse ? nlohmann::json(*reference.ownRelMse) : nlohmann::json();
    for (const EngineUnderTest& e : engines)
        json["devices"][toString(e.kind)] = e.engine->deviceName();
    return json;
}

std::string describeStrategy(const RenderSettings& settings)
{
    std::vector<std::string> parts;
    for (const Setting* s : strategySettings())
        parts.push_back(fmt::format("{} {}", s->name, s->text(settings)));
    return fmt::format("{}", fmt::join(parts, ", "));
}

std::string againstReference(const Reference& reference, ErrorMetric metric)
{
    std::string text = fmt::format("{} against {} (", displayName(metric), reference.description);
    text += metric == ErrorMetric::Flip ? std::string("HDR-FLIP, exposures from the reference")
                                        : fmt::format("epsilon {:g}", kRelMseEpsilon);
    if (reference.ownRelMse)
        text += fmt::format("; the reference's own relMSE {:.2e} is part of every relMSE", *reference.ownRelMse);
    return text + ")";
}

std::vector<std::size_t> measurementOrder(const std::vector<EngineUnderTest>& engines)
{
    std::vector<std::size_t> order(engines.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t e) { return engines[e].kind == EngineKind::Gpu; });
    return order;
}

void warmUpStrategies(RenderEngine& engine, const RenderRequest& base, const std::vector<Strategy>& strategies)
{
    warmUp(engine, strategies.front().request(base, 4));
    for (std::size_t s = 1; s < strategies.size(); ++s)
        if (measure(engine, strategies[s].request(base, 1), nullptr).cancelled)
            return;
}

void chargePilot(Measurement& m, const AutoChoice& choice)
{
    m.wallMs += choice.pilotWallSeconds * 1e3;
    if (m.gpuMs >= 0.0)
        m.gpuMs += choice.pilotMs;
}

std::string autoLabel(const std::vector<Strategy>& grid, const Strategy& chosen)
{
    std::vector<Strategy> all = grid;
    all.push_back(chosen);
    return "auto: " + distinctLabels(all).back();
}

void measureFlip(const CompareOptions& options, int round, const Reference& reference, Measurement& m)
{
    if (options.metric == ErrorMetric::Flip && round == 0)
        m.error.flip = meanHdrFlip(m.image, reference.image);
}

ConvergenceRow csvRow(const std::string& scene, EngineKind engine, const std::string& device, const Strategy& strategy,
                      const std::string& label, const Measurement& m, const Reference& reference, std::uint32_t seed,
                      int round, int rank)
{
    return {scene, toString(engine), device, strategy.name(), label, m.spp, m.wallMs, m.gpuMs,
            m.mpathsPerSecond, m.error.mse, m.error.relMse, m.error.rmse, reference.ownRelMse.value_or(-1.0), seed,
            round, m.error.trimmedRelMse, m.error.mape, m.error.flip, rank, m.mraysPerSecond.camera,
            m.mraysPerSecond.extension, m.mraysPerSecond.shadow};
}

std::string plusMinus(const Interval& i)
{
    return i.count > 1 ? fmt::format(" ±{:<8.2g}", 0.5 * (i.hi - i.lo)) : std::string();
}

void drawFigures(const CompareOptions& options, const ImageFolder& images)
{
    if (!options.plot.empty())
    {
        drawFigure(options.plot, scriptPath("plot_convergence.py"), {options.csv, toString(options.metric)});
        std::printf("wrote %s\n", options.plot.c_str());
    }
    if (!options.grid.empty() && !(options.equalTimeMs > 0.0))
    {
        drawFigure(options.grid, scriptPath("ladder_grid.py"), {images.indexPath().string()});
        std::printf("wrote %s\n", options.grid.c_str());
    }
}
} // namespace rt::compare
