#include "Compare/AutoStrategy.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>

#include "Cli/ValueParsing.h"
#include "Compare/Measurement.h"
#include "Error.h"
#include "HostThreads.h"
#include "Image/Metrics.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
namespace
{
/// The least lead in efficiency over the scene's own for which the pilot switches (pilotSwitches says why).
constexpr double kMinimumLead = 1.05;

/// "light-sampler, light-selection": the strategy settings in which `b` differs from `a`.
std::string differences(const Strategy& a, const Strategy& b)
{
    std::vector<std::string> names;
    for (const Setting* s : strategySettings())
        if (s->text(a.settings) != s->text(b.settings))
            names.emplace_back(s->name);
    return fmt::format("{}", fmt::join(names, ", "));
}

/// A width of `request`'s aspect holding about `pixels` pixels, at least 16 and at most the request's.
int widthFor(const RenderSettings& settings, double pixels)
{
    const double full = double(settings.width) * double(settings.height());
    const double scale = std::sqrt(std::clamp(pixels / full, 0.0, 1.0));
    return std::clamp(static_cast<int>(std::lround(settings.width * scale)), std::min(16, settings.width),
                      settings.width);
}

double pixelsOf(const RenderSettings& s) { return double(s.width) * double(s.height()); }

} // namespace

double RenderCost::ms(double pixels, double spp) const
{
    return fixedMs + msPerPixel * pixels + msPerPath * pixels * spp;
}

double RenderCost::pixelsFor(double ms, double spp) const
{
    return std::max(ms - fixedMs, 0.0) / (msPerPixel + msPerPath * spp);
}

double RenderCost::sppFor(double ms, double pixels) const
{
    return std::max(ms - fixedMs - msPerPixel * pixels, 0.0) / (msPerPath * pixels);
}

RenderCost fitRenderCost(const std::array<ProbeTiming, 3>& probes)
{
    const auto& [large, more, small] = probes;
    if (large.pixels <= 0.0 || more.spp < large.spp || small.pixels > large.pixels || large.spp != small.spp)
        throw UsageError("fitRenderCost: probes of P pixels at s and s' >= s spp, and of at most P pixels at s spp");
    // The bound: all of a render's time as its paths'. A term the clocks' noise hides (a difference below a quarter
    // of the bound's share of it, or negative) is left out, and the bound takes its place.
    RenderCost cost;
    const double bound = std::max(more.ms, 1e-9) / (more.pixels * double(more.spp));
    const double extraPaths = large.pixels * double(more.spp - large.spp);
    const double slope = extraPaths > 0.0 ? (more.ms - large.ms) / extraPaths : 0.0;
    if (slope <= 0.25 * bound)
    {
        cost.msPerPath = bound;
        return cost;
    }
    cost.msPerPath = slope;
    const double extraPixels = large.pixels - small.pixels;
    const double perPixelAndPaths = extraPixels > 0.0 ? (large.ms - small.ms) / extraPixels : 0.0;
    cost.msPerPixel = std::max(perPixelAndPaths - cost.msPerPath * double(large.spp), 0.0);
    cost.fixedMs = std::max(more.ms - cost.msPerPixel * more.pixels - cost.msPerPath * more.pixels * double(more.spp),
                            0.0);
    return cost;
}

StrategyLists autoCandidates(const Scene& scene, const StrategyLists& given, const std::vector<std::string>& fixed)
{
    const std::uint32_t emitters = scene.emitterCount();
    bool polygonLights = false;
    for (std::uint32_t i = 0; i < emitters && i < scene.lightSources.size(); ++i)
        polygonLights |= scene.lightSources[i].kind == LightSource::Kind::Quad ||
                         scene.lightSources[i].kind == LightSource::Kind::Triangle;
    StrategyLists lists;
    for (const Setting* s : strategySettings())
    {
        const std::string flag(s->compareFlag);
        if (const auto it = given.find(flag); it != given.end() && !it->second.empty())
        {
            lists[flag] = it->second;
            continue;
        }
        if (std::find(fixed.begin(), fixed.end(), s->name) != fixed.end())
            continue;
        if (s->name == "estimator")
            // Book 3's mixture samples lights at diffuse vertices only: at a microfacet one it is BSDF sampling
            // alone, a single strategy whose rare paths a pilot does not see (veach-mis, 2 cores: a pilot of 4 spp
            // over 45 x 30 pixels chose it, 0.002x nee-mis's efficiency at 1 s).
            lists[flag] = scene.hasMicrofacetMaterial() ? "nee-mis" : "nee-mis,mixture";
        else if (s->name == "light-sampler" && emitters > 0)
            lists[flag] = polygonLights ? "projected,solid-angle,area,projected-exact" : "projected,solid-angle,area";
        else if (s->name == "light-selection" && emitters > 1)
            lists[flag] = "bvh,power,uniform";
        else if (s->name == "sampling" && scene.defaults.sampling == PixelSampling::Random)
            // A scene of random samples (the books' keep PCG's; a scene file may ask for them) has Owen-scrambled
            // Sobol as a candidate beside them (rtrol-cornell-box, 2 cores, 64 spp: the pilot chose area sampling
            // with random samples, 2.30x Cycles' efficiency, 3.13x with Sobol a candidate: notebook §53).
            lists[flag] = "random,sobol";
    }
    return lists;
}

std::optional<StrategyLists> pilotCandidates(const StrategyLists& lists, const RenderSettings& settings)
{
    if (settings.estimator == Estimator::RestirDi)
        return std::nullopt;
    StrategyLists candidates = lists;
    // The GPU window's accumulation is its passes' random samples (progressiveSampling): it stands for random in a
    // books' scene's "random,sobol", so that Sobol is measured beside it there too.
    if (const std::string flag(findSetting("sampling")->compareFlag);
        settings.sampling == PixelSampling::Accumulate && candidates.count(flag))
    {
        std::vector<std::string> words = splitCommas(candidates[flag]);
        std::replace(words.begin(), words.end(), std::string("random"), std::string("accumulate"));
        candidates[flag] = fmt::format("{}", fmt::join(words, ","));
    }
    // An estimator or a pixel sampling the lists do not hold is kept (a window's stratified samples against a books'
    // scene's "random,sobol"): the request's own would otherwise be measured as the list's first and replaced.
    for (const char* name : {"estimator", "sampling"})
    {
        const Setting& setting = *findSetting(name);
        if (const std::vector<std::string> words = listedWords(candidates, setting, settings);
            std::find(words.begin(), words.end(), setting.text(settings)) == words.end())
            candidates.erase(std::string(setting.compareFlag));
    }
    return candidates;
}

namespace
{
/// setSeedBlock(samples) on `engine` while it lives, its block before after.
class SeedBlockScope
{
public:
    SeedBlockScope(RenderEngine& engine, std::uint32_t samples) : m_engine(engine), m_before(engine.seedBlock())
    {
        m_engine.setSeedBlock(samples);
    }
    ~SeedBlockScope() { m_engine.setSeedBlock(m_before); }
    SeedBlockScope(const SeedBlockScope&) = delete;
    SeedBlockScope& operator=(const SeedBlockScope&) = delete;

private:
    RenderEngine& m_engine;
    std::uint32_t m_before;
};

/// The two halves of a frame of two seed blocks (RenderEngine::setSeedBlock) of `pixels` pixels each: its top and its
/// bottom. Throws Error where the frame holds another number of pixels (an engine that ignored its seed blocks).
std::pair<Image, Image> seedBlockHalves(const Image& frame, double pixels)
{
    if (double(frame.pixelCount()) != 2.0 * pixels || frame.height() % 2 != 0)
        throw Error(fmt::format("a pilot's frame of two seed blocks came back {}x{}, not two blocks of {} pixels",
                                frame.width(), frame.height(), pixels));
    const int height = frame.height() / 2;
    Image top(frame.width(), height), bottom(frame.width(), height);
    const auto half = static_cast<std::ptrdiff_t>(top.pixelCount());
    std::copy(frame.pixels().begin(), frame.pixels().begin() + half, top.pixels().begin());
    std::copy(frame.pixels().begin() + half, frame.pixels().end(), bottom.pixels().begin());
    return {std::move(top), std::move(bottom)};
}

/// fn(i) for every i < count, spread over the host's cores (runInParallel: an exception reaches the caller).
template <class F>
void onHostCores(std::size_t count, F&& fn)
{
    if (count == 0)
        return;
    const int parts = static_cast<int>(std::min<std::size_t>(count, static_cast<std::size_t>(usableCores())));
    runInParallel(parts, [&](int part) {
        for (std::size_t i = static_cast<std::size_t>(part); i < count; i += static_cast<std::size_t>(parts))
            fn(i);
    });
}

/// Throws UsageError (its message naming `caller`) unless `halves` and `denominator` are there, the halves of
/// `width` x `height` pixels and the denominator of their values.
void checkMeasurement(const char* caller, const PilotHalves* halves, const std::vector<float>* denominator, int width,
                      int height)
{
    if (!halves || !denominator)
        throw UsageError(fmt::format("{}: a measurement without its halves or denominator", caller));
    for (const Image* image : {&halves->a, &halves->b})
        if (image->width() != width || image->height() != height)
            throw UsageError(fmt::format("{}: pilot images differ in size ({}x{} and {}x{})", caller, width, height,
                                         image->width(), image->height()));
    if (denominator->size() != 3 * std::size_t(width) * std::size_t(height))
        throw UsageError(fmt::format("{}: a denominator of {} values for {}x{} pixels", caller, denominator->size(),
                                     width, height));
}

/// Pixel p's relMSE term of one measurement: the variance of its halves' mean, (a - b)^2 / 4, over denominator^2 +
/// epsilon, summed over the pixel's three channels (in double: a firefly's square spans float's range).
double pixelTerm(const PilotHalves& halves, const std::vector<float>& denominator, std::size_t p)
{
    const float* a = &halves.a.data()[p].x;
    const float* b = &halves.b.data()[p].x;
    const float* d = denominator.data() + 3 * p;
    double term = 0.0;
    for (std::size_t c = 0; c < 3; ++c)
    {
        const double difference = double(a[c]) - double(b[c]);
        term += difference * difference * (0.25 / (double(d[c]) * double(d[c]) + kRelMseEpsilon));
    }
    return term;
}
} // namespace

void PilotSums::add(const Image& imageA, const Image& imageB)
{
    if (count > 0 && (imageA.width() != width || imageA.height() != height))
        throw UsageError(fmt::format("pilot measurements differ in size ({}x{} and {}x{})", width, height,
                                     imageA.width(), imageA.height()));
    if (imageB.width() != imageA.width() || imageB.height() != imageA.height())
        throw UsageError(fmt::format("a pilot measurement's halves differ in size ({}x{} and {}x{})", imageA.width(),
                                     imageA.height(), imageB.width(), imageB.height()));
    if (count++ == 0)
    {
        width = imageA.width();
        height = imageA.height();
        halfSums.assign(imageA.pixelCount() * 3, 0.0);
    }
    const float* a = &imageA.data()->x;
    const float* b = &imageB.data()->x;
    for (std::size_t k = 0; k < halfSums.size(); ++k)
        halfSums[k] += double(a[k]) + double(b[k]);
}

PilotError measuredRelMse(std::span<const PilotMeasurement> measurements)
{
    if (measurements.empty())
        throw UsageError("measuredRelMse: no measurement");
    const PilotHalves* first = measurements.front().halves;
    const int width = first ? first->a.width() : 0;
    const int height = first ? first->a.height() : 0;
    for (const PilotMeasurement& m : measurements)
        checkMeasurement("measuredRelMse", m.halves, m.denominator, width, height);
    const std::size_t pixels = std::size_t(width) * std::size_t(height), values = 3 * pixels;
    if (pixels == 0)
        throw UsageError("measuredRelMse: images of no pixel");
    const std::size_t k = measurements.size();
    double sum = 0.0, spread = 0.0, squares = 0.0;
    std::vector<double> t(k);
    for (std::size_t p = 0; p < pixels; ++p)
    {
        double pixelSum = 0.0;
        for (std::size_t m = 0; m < k; ++m)
        {
            t[m] = pixelTerm(*measurements[m].halves, *measurements[m].denominator, p);
            pixelSum += t[m];
        }
        sum += pixelSum;
        squares += pixelSum * pixelSum;
        if (k >= 2)
        {
            const double mean = pixelSum / double(k);
            for (std::size_t m = 0; m < k; ++m)
                spread += (t[m] - mean) * (t[m] - mean);
        }
    }
    const double scale = 1.0 / (double(k) * double(k) * double(values));
    // Var(sum over the pixels): with k >= 2, each pixel's k / (k - 1) spread; with one, P / (P - 1) times the pixels'.
    const double variance =
        k >= 2 ? double(k) / double(k - 1) * spread
               : (pixels > 1 ? double(pixels) / double(pixels - 1) * std::max(squares - sum * sum / double(pixels), 0.0)
                             : 0.0);
    return {sum * scale, std::sqrt(variance) * scale};
}

PairedRelMse pairedRelMse(std::span<const PilotPair> pairs)
{
    if (pairs.empty())
        throw UsageError("pairedRelMse: no pair");
    const int width = pairs.front().own ? pairs.front().own->a.width() : 0;
    const int height = pairs.front().own ? pairs.front().own->a.height() : 0;
    for (const PilotPair& pair : pairs)
        for (const PilotHalves* halves : {pair.own, pair.challenger})
            checkMeasurement("pairedRelMse", halves, pair.denominator, width, height);
    const std::size_t pixels = std::size_t(width) * std::size_t(height), values = 3 * pixels;
    if (pixels == 0)
        throw UsageError("pairedRelMse: images of no pixel");
    const std::size_t k = pairs.size();
    PairedRelMse r;
    r.ownPerPair.assign(k, 0.0);
    std::vector<double> challengerPerPair(k, 0.0), x(k), y(k);
    // Per pixel, the spread over the pairs of x, of y and their covariance, summed over the pixels: the variance of
    // sum (y - R x) is then k / (k - 1) (Cyy - 2 R Cxy + R^2 Cxx), one pass for any R. With one pair, the pixels'
    // spread: their raw moments (sum (y - R x) is 0), P / (P - 1) (Syy - 2 R Sxy + R^2 Sxx).
    double cxx = 0.0, cyy = 0.0, cxy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (std::size_t p = 0; p < pixels; ++p)
    {
        double meanX = 0.0, meanY = 0.0;
        for (std::size_t m = 0; m < k; ++m)
        {
            const double xm = pixelTerm(*pairs[m].own, *pairs[m].denominator, p);
            const double ym = pixelTerm(*pairs[m].challenger, *pairs[m].denominator, p);
            x[m] = xm;
            y[m] = ym;
            r.ownPerPair[m] += xm;
            challengerPerPair[m] += ym;
            meanX += xm;
            meanY += ym;
        }
        sxx += meanX * meanX;
        syy += meanY * meanY;
        sxy += meanX * meanY;
        meanX /= double(k);
        meanY /= double(k);
        for (std::size_t m = 0; m < k; ++m)
        {
            cxx += (x[m] - meanX) * (x[m] - meanX);
            cyy += (y[m] - meanY) * (y[m] - meanY);
            cxy += (x[m] - meanX) * (y[m] - meanY);
        }
    }
    const double sumX = std::accumulate(r.ownPerPair.begin(), r.ownPerPair.end(), 0.0);
    const double sumY = std::accumulate(challengerPerPair.begin(), challengerPerPair.end(), 0.0);
    const double scale = 1.0 / (double(k) * double(k) * double(values));
    const double n = double(pixels);
    const double spread = k > 1 ? double(k) / double(k - 1) : pixels > 1 ? n / (n - 1.0)
                                                                          : std::numeric_limits<double>::infinity();
    r.own = sumX * scale;
    r.challenger = sumY * scale;
    r.ratio = sumX > 0.0 ? sumY / sumX : 0.0;
    const double ratioSpread = k > 1 ? cyy - 2.0 * r.ratio * cxy + r.ratio * r.ratio * cxx
                                     : syy - 2.0 * r.ratio * sxy + r.ratio * r.ratio * sxx;
    if (k == 1)
    {
        cxx = sxx - sumX * sumX / n;
        cyy = syy - sumY * sumY / n;
    }
    r.ownError = std::sqrt(spread * std::max(cxx, 0.0)) * scale;
    r.challengerError = std::sqrt(spread * std::max(cyy, 0.0)) * scale;
    r.ratioError = sumX > 0.0 && std::isfinite(spread) ? std::sqrt(std::max(spread * ratioSpread, 0.0)) / sumX
                                                       : std::numeric_limits<double>::infinity();
    return r;
}

AutoChoice chooseStrategy(RenderEngine& engine, const RenderRequest& request, const StrategyLists& candidates,
                          const PilotBudget& budget)
{
    const auto start = std::chrono::steady_clock::now();
    AutoChoice choice;
    // Ctrl-C: the request's own strategy, unmeasured.
    auto cancelled = [&] {
        choice.cancelled = true;
        choice.chosen = Strategy::of(request.settings);
        return choice;
    };
    // Every combination of the lists (what a strategy does not use kept once: strategyGrid), the request's own
    // first: it is the one to beat.
    std::vector<Strategy> grid = strategyGrid(candidates, request.settings);
    RenderSettings best = request.settings;
    for (const Setting* s : strategySettings())
        if (const std::vector<std::string> words = listedWords(candidates, *s, request.settings);
            std::find(words.begin(), words.end(), s->text(best)) == words.end())
            s->set(best, words.front(), s->compareFlag); // the request's value is no candidate: the list's first
    const Strategy own = Strategy::of(best);
    if (const auto it = std::find(grid.begin(), grid.end(), own); it != grid.end())
        grid.erase(it);
    grid.insert(grid.begin(), own);
    // The candidates of the own's pixel sampling first: the default's bound on their preparation (prepareFraction)
    // leaves out the grid's last, and then the other sampling's (a books' scene's Sobol twins, which double a GPU's
    // pipelines) before any light sampler or selection.
    std::stable_partition(grid.begin() + 1, grid.end(),
                          [&](const Strategy& s) { return s.settings.sampling == own.settings.sampling; });
    choice.chosen = own;
    const std::size_t planned = grid.size();
    if (planned == 1)
        return choice;

    // Every frame of the pilot, the probe's too, runs what the render will run (RenderEngine::setRepresentedPaths):
    // the GPU's integrator for the render's paths, not the pilot's. (--compare's equal-time auto row passes its base
    // request, whose spp is not the one its time will give: in every GPU comparison of docs/RESULTS.md both are far
    // above the wavefront's 2^20 paths.)
    struct Represented
    {
        RenderEngine& engine;
        Represented(RenderEngine& e, std::uint64_t paths) : engine(e) { engine.setRepresentedPaths(paths); }
        ~Represented() { engine.setRepresentedPaths(0); }
        Represented(const Represented&) = delete;
        Represented& operator=(const Represented&) = delete;
    } represented(engine, static_cast<std::uint64_t>(pixelsOf(request.settings)) *
                              static_cast<std::uint64_t>(request.settings.trueSpp()));

    // The probe: the starting strategy timed on three renders, for the three terms of a render's time (RenderCost):
    // the pilot's pixels at 1 and kProbeSpp spp, and a quarter of them at 1 spp. The pilot's renders are small, so
    // the terms but the paths' matter: from one render of 1 spp over the whole image a GPU's pilot planned its
    // renders at 6x the H200's time per path, measured 1 spp a half and used half its budget; with the fixed cost
    // and no cost per pixel, the same image's clearing and read-back counted as fixed and left an H200 no path to
    // measure within a half's share of a 1 s render. A pilot of 1 spp a half sees none of what stratification
    // (Sobol's points, the samplers' warps) gains at the render's spp (it chose solid-angle sampling with uniform
    // selection on an H200's cornell-box-lights, 0.8x the scene's own there).
    // The pilot's pixels: at least the engine's concurrent paths (a 45 x 45 pilot on an H100 took 100x the time per
    // path of a 600 x 600 render) and 1024 (relMSE's terms: its standard error falls with their count).
    const double pilotPixels = std::max(1024.0, double(engine.concurrentPaths()));
    constexpr int kProbeSpp = 4;
    RenderSettings large = best, small = best;
    large.width = widthFor(request.settings, pilotPixels);
    small.width = widthFor(request.settings, pixelsOf(large) / 4.0);
    std::array<ProbeTiming, 3> probes{ProbeTiming{pixelsOf(large), 1},
                                      ProbeTiming{pixelsOf(large), std::clamp(request.settings.trueSpp(), 1, kProbeSpp)},
                                      ProbeTiming{pixelsOf(small), 1}};
    // The first render after a scene is set is the slower (2-3 ms against 0.7-0.9 ms for 1024 paths on 2 cores: a
    // pool's first dispatch, cold caches): every probe is rendered twice, the faster kept. The second's time over the
    // first's is the paths' cost: on 2 cores one slow render of its 3 ms put that at 1.75x the render's, and the
    // pilot planned a CPU's cornell-box-lights at 2 spp a half where 4 fitted, used half its budget and kept the own,
    // 0.87x the best, in 2 of 6 seeds. The third's, of a quarter of the pixels, gives the fixed cost: rendered once,
    // one slow render of it fitted 0.87 ms of fixed and per-pixel cost to a CPU's many-lights halves (the other
    // seeds' 0-0.08 ms), taken off every measurement of 1.3-2 ms, and the pilot timed area sampling with power
    // selection at 0.31x the own's time per path (the render 0.59x) and took it, 0.72x the own.
    double hostExtraMs = std::numeric_limits<double>::infinity(); // AutoChoice::hostExtraMs
    for (const std::size_t i : {0, 1, 2, 0, 1, 2})
    {
        RenderRequest probe = request;
        probe.settings = i == 2 ? small : large;
        probe.settings.spp = probes[i].spp;
        const auto probeStart = std::chrono::steady_clock::now();
        const Measurement probed = measure(engine, probe, nullptr, {}, true);
        const double hostMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - probeStart).count();
        if (probed.cancelled)
            return cancelled();
        choice.pilotMs += probed.ms();
        choice.probeMs += probed.ms();
        probes[i].ms = probes[i].ms > 0.0 ? std::min(probes[i].ms, probed.ms()) : probed.ms();
        hostExtraMs = std::min(hostExtraMs, std::max(hostMs - probed.ms(), 0.0));
    }
    choice.hostExtraMs = hostExtraMs;
    choice.probes.assign(probes.begin(), probes.end());
    choice.frameConfiguration = engine.frameConfiguration();
    const RenderCost cost = fitRenderCost(probes);
    choice.cost = cost;
    choice.estimatedRenderSeconds =
        budget.renderSeconds > 0.0 ? budget.renderSeconds
                                   : cost.ms(pixelsOf(request.settings), request.settings.trueSpp()) * 1e-3;
    choice.budgetSeconds = std::min(budget.maxSeconds, budget.fraction * choice.estimatedRenderSeconds);
    // Successive halving (Jamieson & Talwalkar 2016): every candidate measured once, then the better half again,
    // and so on down to two, the scene's own (the one to beat) in every round. A candidate whose first
    // measurement was lucky (a pilot sees few of the rare paths that carry a glossy scene's light) is measured
    // again before it can win: measured once each, uniform light selection won veach-mis's pilot at 6x nee-mis
    // with the BVH, which the full comparison puts at 0.9x. The final round, the scene's own and one challenger,
    // is measured kFinalMeasurements times, and only those measurements speak for the challenger (pilotSwitches).
    // Every measurement of every round is the same size.
    constexpr int kFinalMeasurements = 3;
    std::size_t measurements = 0, ownMeasurements = 0;
    for (std::size_t m = planned;; m = (m + 1) / 2)
    {
        measurements += m == planned ? 1 : 0; // the first round's own twice (kOwnSeedSlot)
        ownMeasurements += (m == planned ? 1 : 0) + (m <= 2 ? kFinalMeasurements : 1);
        if (m <= 2)
        {
            measurements += m * kFinalMeasurements;
            break;
        }
        measurements += m;
    }
    // The plan's time per path: the candidates', not the own's alone, by a render of each at the probe's second size,
    // each weighed by its share of the search's measurements (the own's known, the others' alike), on a CPU (a GPU
    // compiles a pipeline for each strategy's first render, and its renders cost its host 7-14 ms each) where the
    // host adds little to each render and the renders take a quarter of the budget at most. Planned by the own's, a
    // search whose own is cheap per path ran past its budget: on a CPU's rtrol-cornell-box (book 3's mixture; the
    // nee-mis candidates 2-3.5x its time per path) 0.35-0.41 s of the engine's clock for a budget of 0.2 s, and auto
    // lost 12 % to its pilot, though it chose the best 4 of 4. Each candidate's ratio is held to [1/4, 4], and a
    // candidate's render stopped at 4x the own's time counts 4: one past 4x the own's share is stopped in the search
    // too (timeLimit below). (A bound on both costs together, a tenth of the budget, sat at a CPU's veach-mis pilots'
    // size: two seeds of four took the cost probes and planned 40 spp a measurement, both halves, two did not and
    // planned 14-16.)
    RenderCost planCost = cost;
    if (const double n = double(planned), budgetMs = choice.budgetSeconds * 1e3;
        engine.kind() != EngineKind::Gpu && n * hostExtraMs <= 0.05 * budgetMs &&
        n * 2.0 * probes[1].ms <= 0.25 * budgetMs)
    {
        RenderSettings ownProbe = large;
        ownProbe.spp = probes[1].spp;
        auto perPath = [&](double renderMs, int trueSpp) {
            return std::max(renderMs - cost.ms(probes[1].pixels, 0.0), 0.25 * renderMs) /
                   (probes[1].pixels * double(std::max(trueSpp, 1)));
        };
        const double ownPerPath = perPath(probes[1].ms, ownProbe.trueSpp());
        const auto limit = std::chrono::nanoseconds(static_cast<std::int64_t>(std::max(4.0 * probes[1].ms, 1.0) * 1e6));
        double others = 0.0;
        for (std::size_t k = 1; k < grid.size(); ++k)
        {
            RenderRequest probe = request;
            probe.settings = grid[k].applyTo(ownProbe);
            const Measurement probed = measure(engine, probe, nullptr, limit, true);
            if (probed.cancelled && !probed.timedOut)
                return cancelled();
            const double ms = probed.cancelled ? probed.wallMs : probed.ms();
            choice.pilotMs += ms;
            choice.probeMs += ms;
            if (probed.timedOut)
                others += 4.0;
            else
                others += ownPerPath > 0.0 ? std::clamp(perPath(ms, probed.spp) / ownPerPath, 0.25, 4.0) : 1.0;
        }
        others /= n - 1.0;
        const double ownShare = double(ownMeasurements) / double(measurements);
        choice.candidatesCostScale = ownShare + (1.0 - ownShare) * others;
        planCost.msPerPath *= choice.candidatesCostScale;
    }
    // A half's share of the budget on the engine's clock, but no more than the search's guard (twice the budget, on
    // the host's clock) leaves it beside each render's host time beyond the engine's (its set-up and read-back, the
    // waits between a GPU's submissions: 9-12 ms a render of 512 x 512 on an H200 against its 2-7 ms on the GPU's
    // clock, when the guard stopped every search before its final round). Not less: the scoring between rounds
    // (0.2 s of an H200 host's clock for 12 candidates of 512 x 512) can then pass the guard as the final round
    // begins, but a quarter of the guard kept for it left an H200's --compare auto rows at 10 s, whose renders
    // cost the host 12-14 ms beyond the GPU's, no share at all (3 of 4 pilots too short to measure).
    // The probe's pixels where the share holds them at 1 spp, fewer where not; the rest of the share as samples per
    // pixel, up to half the render's: stratification gains with the spp, and a pilot of 2 spp cannot see it (it
    // chose random over sobol on rect-light-closeup, where sobol is 3.5x as efficient at 1 s). A render held to a
    // time (--compare's equal-time auto row) has no spp of its own: the spp its time gives by the probe's model (its
    // request's, the scene's few, held an H200's glossy-cornell pilots at 2 spp a half for a render of 8,600).
    int renderSpp = request.settings.trueSpp();
    if (budget.renderSeconds > 0.0)
    {
        const double spp = cost.sppFor(budget.renderSeconds * 1e3, pixelsOf(request.settings));
        renderSpp = spp >= 1.0 ? static_cast<int>(std::min(spp, double(kMaxSpp))) : 1; // NaN: 1
    }
    const int sppCap = std::max(1, renderSpp / 2);
    // Where the engine stays busy on fewer pixels at more spp (RenderEngine::busyPixels: a GPU's wavefront), the
    // halves take the pixels their share holds at kPilotSpp spp (or the request's half, if fewer), never fewer than
    // 1024 or the engine's busy pixels at that spp for any candidate (where the share cannot fill those at that spp,
    // they take fewer spp, and the device is then partly idle, as the probe's pixels at 1 spp would leave it too): a
    // candidate's error per path over the own's grows with the spp (Sobol's stratification gains more for some
    // samplers: solid-angle sampling with uniform selection over the own on cornell-box-lights 1.26 at 2 spp, 1.37
    // from 128 on), and an H200's halves of 512 x 512 at 2 spp paired it at 1.15 where its render is 1.41 (notebook
    // §44). Elsewhere (a CPU's 1024 pixels, a GPU's megakernel) the most pixels first, as before.
    constexpr int kPilotSpp = 16;
    auto busyPixels = [&](int spp) {
        RenderSettings s = request.settings;
        s.width = large.width;
        s.spp = spp;
        std::uint64_t most = 0;
        for (const Strategy& strategy : grid)
            most = std::max(most, engine.busyPixels(strategy.applyTo(s)));
        return std::max(1024.0, double(most));
    };
    const int pilotSpp = std::min(kPilotSpp, sppCap);
    // On a GPU a measurement's two halves are one frame's two seed blocks (RenderEngine::setSeedBlock), where the
    // candidate's sampling allows them (frameHoldsBothHalves): a wavefront frame ends in a tail of its last segments,
    // a few paths each, and an H200's pilots, a frame a half, ran 1.17-1.44x past their budget on the engine's clock
    // (halves of 11.2 ms where 7.1 were planned: notebook §54). One frame pays it once. The plan then shares the
    // budget out by frames of both halves: each measurement one frame of twice a half's spp. Not on a CPU: a frame
    // there costs a pool's dispatch, and each half apart keeps the faster one's time against a loaded machine's
    // stalls.
    choice.halvesInOneFrame = engine.kind() == EngineKind::Gpu && !seedBlocksRefusal(best);
    const int halvesPerFrame = choice.halvesInOneFrame ? 2 : 1;
    const double floorPixels = busyPixels(halvesPerFrame * pilotSpp);
    const bool bySpp = floorPixels < pilotPixels; // the engine's own answer, not the probe's rounded width
    auto planHalves = [&](double budgetMs, double hostBudgetMs) {
        const double frames = double(measurements) * 2.0 / halvesPerFrame;
        double shareMs = std::min(budgetMs / frames, hostBudgetMs / frames - choice.hostExtraMs); // a frame's
        if (!(shareMs > 0.0))
            shareMs = 0.0; // NaN too: nothing fits, and the plan is too short to measure
        RenderSettings half = request.settings;
        // Never more pixels than the share holds at 1 spp a half.
        const double pixels =
            std::min({bySpp ? std::max(planCost.pixelsFor(shareMs, halvesPerFrame * pilotSpp), floorPixels)
                            : pixelsOf(large),
                      pixelsOf(large), planCost.pixelsFor(shareMs, halvesPerFrame)});
        half.width = widthFor(request.settings, std::max(pixels, 1.0));
        half.spp = std::clamp(static_cast<int>(planCost.sppFor(shareMs, pixelsOf(half)) / halvesPerFrame), 1, sppCap);
        return half;
    };
    // Timing frames: where a half holds fewer paths than kThroughputFactor x the engine's concurrent paths, its
    // device runs partly idle, waiting on the longest paths, and its time per path hides part of what a costlier
    // candidate costs in the render: on an H200's glossy-cornell the pilot's halves of 512 x 512 at 1-17 spp put
    // projected sampling with the BVH at 1.35-1.57x the time per path of solid-angle sampling with uniform selection,
    // the render at 2x, and at 10 s the pilot kept the own, 0.65x the best. The final round then times each of its
    // two candidates on frames of the probe's pixels with up to that many paths, once per measurement, the second at
    // twice the spp (a quarter of the budget holds the six; a stalled one's fourth is outside it: timingStalled), and
    // decides on their least times' slope (timingMsPerPath). Frames of no more than twice a half's paths tell nothing
    // the halves do not.
    constexpr double kThroughputFactor = 16.0;
    const double timingBudgetMs = 0.25 * choice.budgetSeconds * 1e3 / 8.0; // two candidates' frames of 1, 2 and 1 units
    const double timingPaths = std::min(kThroughputFactor * double(engine.concurrentPaths()),
                                        pixelsOf(large) * cost.sppFor(timingBudgetMs, pixelsOf(large)));
    RenderSettings timing = large;
    timing.width = widthFor(request.settings, std::min(timingPaths, pixelsOf(large)));
    timing.spp = std::clamp(static_cast<int>(timingPaths / pixelsOf(timing)), 1, renderSpp);
    // The halves for `budgetMs` on the engine's clock, and whether the timing frames fit beside them.
    struct PilotPlan
    {
        RenderSettings halves;
        bool timed = false;
        double paths() const { return pixelsOf(halves) * double(halves.spp); } // a half's
    };
    auto planPilot = [&](double budgetMs) {
        PilotPlan plan{planHalves(budgetMs, 2.0 * choice.budgetSeconds * 1e3)};
        if (pixelsOf(timing) * 2.0 * timing.spp > 2.0 * plan.paths())
        {
            const double timingMs =
                2.0 * (2.0 * cost.ms(pixelsOf(timing), timing.spp) + cost.ms(pixelsOf(timing), 2 * timing.spp));
            const PilotPlan timed{planHalves(budgetMs - timingMs, 2.0 * choice.budgetSeconds * 1e3 -
                                                                      (timingMs + 6.0 * choice.hostExtraMs)),
                                  true};
            // Not where the budget left to the halves would then measure nothing (kMinimumPilotPaths below).
            if (timed.paths() >= kMinimumPilotPaths)
                plan = timed;
        }
        return plan;
    };
    PilotPlan plan = planPilot(choice.budgetSeconds * 1e3);
    // On a GPU the plan is made again from two frames of the own at its depth. The probe's frames are wide and
    // shallow (512 x 512 at 1-4 spp on an H200) and the halves' frames narrow and deep (140-180 px square at 30 spp,
    // both halves), where a wavefront frame's cost is another line: on many-lights' own 7.9 ms a frame and 4.8 ns a
    // path (its last segments, a few paths each, take longer; its paths, a pixel's samples together, less), against
    // the probe's 1.9 ms and 8.5 ns. Planned by the probe, with the probe's six frames outside the plan (35 ms of a
    // 400 ms budget), its pilots ran 1.22-1.37x their budget; with the plan's time per path scaled by one frame's,
    // 1.15-1.19x, the halves then smaller and their fixed cost a larger part (notebook §57). The two frames are the
    // own's measurement as planned (both halves, two seed blocks) and one of half its pixels, that one first (a first
    // frame's extra time then lowers the slope and raises the fixed cost: smaller halves, not larger); their line is
    // the plan's model at that depth, and the halves are planned again for the budget less the probe's and these
    // frames' time. Where the line is not one (noise: a slope or a fixed cost below 0), the larger frame's paths'
    // time over the probe's model scales its time per path instead (never down). Not on a CPU, whose pilots end
    // within their budget (0.6-1.05x on 2 cores: notebook §53) and whose frames at the pilot's size are the probe's
    // kind.
    if (choice.halvesInOneFrame && plan.paths() >= kMinimumPilotPaths)
    {
        RenderSettings atPlan = grid.front().applyTo(plan.halves);
        const int halfSpp = atPlan.trueSpp();
        atPlan.spp = 2 * halfSpp;
        RenderSettings fewer = atPlan;
        fewer.width = widthFor(request.settings, pixelsOf(atPlan) / 2.0);
        // Not where half the pixels leave the device partly idle (RenderEngine::busyPixels): that frame's time would
        // be nearly the planned one's, a line of no slope. The planned frame alone then.
        const bool line = pixelsOf(fewer) < pixelsOf(atPlan) && pixelsOf(fewer) >= double(engine.busyPixels(fewer));
        const SeedBlockScope blocks(engine, static_cast<std::uint32_t>(halfSpp));
        double frameMs[2] = {0.0, 0.0}; // fewer's, the planned one's
        for (int k = line ? 0 : 1; k < 2; ++k)
        {
            RenderRequest frame = request;
            frame.settings = k == 0 ? fewer : atPlan;
            const Measurement calibration = measure(engine, frame, nullptr, {}, true);
            if (calibration.cancelled)
                return cancelled();
            frameMs[k] = calibration.ms();
            choice.calibrationMs += calibration.ms();
            choice.pilotMs += calibration.ms();
        }
        const double paths = pixelsOf(atPlan) * double(atPlan.trueSpp());
        const double extraPaths = paths - pixelsOf(fewer) * double(fewer.trueSpp());
        const double msPerPath = line && extraPaths > 0.0 ? (frameMs[1] - frameMs[0]) / extraPaths : 0.0;
        const double fixedMs = frameMs[1] - msPerPath * paths;
        // The line where its slope is at least a quarter of the planned frame's time a path (fitRenderCost's rule: a
        // flatter one is the frames' noise, or a stall of the first, and would plan halves of every pixel).
        if (msPerPath >= 0.25 * frameMs[1] / paths && fixedMs >= 0.0)
            planCost = RenderCost{.fixedMs = fixedMs, .msPerPixel = 0.0, .msPerPath = msPerPath};
        else if (const double frameOverheadMs = planCost.ms(pixelsOf(atPlan), 0.0),
                 modelMs = planCost.ms(pixelsOf(atPlan), atPlan.trueSpp()) - frameOverheadMs;
                 modelMs > 0.0)
            planCost.msPerPath *= std::clamp((frameMs[1] - frameOverheadMs) / modelMs, 1.0, 4.0);
        // Never less than half the budget: a probe that costs more (a slow device's, beside a short render) would leave
        // nothing to measure, where the plan before this one measured.
        const double budgetMs = choice.budgetSeconds * 1e3;
        const PilotPlan replanned =
            planPilot(std::max(budgetMs - choice.probeMs - choice.calibrationMs, 0.5 * budgetMs));
        // Never more paths a half than the first plan (the budget left is smaller), nor too few to measure where the
        // first plan measured (a fixed cost near the share): the first plan then stays, as before the calibration.
        if (replanned.paths() <= plan.paths() && replanned.paths() >= kMinimumPilotPaths)
            plan = replanned;
    }
    choice.planCost = planCost;
    const RenderSettings& pilot = plan.halves;
    choice.timingWidth = plan.timed ? timing.width : 0;
    choice.timingSpp = plan.timed ? timing.spp : 0;
    choice.width = pilot.width;
    choice.height = pilot.height();
    // What a half costs beyond its paths (the probe's fixed and per-pixel terms), taken off each measurement's
    // time: the render spreads them over its many more paths, so a candidate's efficiency is its paths' (with a
    // launch chain of about 1 ms in each of an H200's wavefront halves of 2-4 ms, a candidate 1.25x as fast per path
    // would measure 1.1x by its halves' whole time).
    choice.overheadMs = cost.ms(pixelsOf(pilot), 0.0);
    // A half of fewer paths than that measures nothing: the relMSE of a few hundred pixel samples misses the rare
    // paths that make a strategy's error, and so does its standard error. On many-lights (1,000 lights, 2 cores, a
    // 1 s render: 484 paths a half over 13 candidates) such pilots chose power or uniform selection by leads of
    // "more than two standard errors", 0.64x the scene's own over 12 seeds. The render is too short to choose for:
    // the scene's own stays. (Not 4,096: on triangle-lights at 4 s on 2 cores, pilots of 1,024-2,048 paths a half
    // chose area sampling with power selection in 11 of 12 seeds, 1.8x the own; on veach-mis at 1 s, pilots of
    // about 2,000 left the own in 7 of 12 seeds, once for 0.13x its efficiency: notebook §35.)
    if (pixelsOf(pilot) * double(pilot.spp) < kMinimumPilotPaths)
    {
        choice.tooShort = true;
        choice.spp = 2 * pilot.spp;
        choice.pilotWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return choice;
    }

    // Every candidate prepared at the pilot's size before the search's clock starts: a GPU compiles a pipeline per
    // strategy (1.3 s each on an H100 with the driver's cache cold; with the cache warm still more than a short
    // render's budget), which no engine clock sees and which, held to the budget, left the search no time to
    // measure (a cold pilot on an H200 kept rtrol-cornell-box's mixture, 0.5x nee-mis). The strategies' rows of
    // --compare are compiled before they are timed too; the host's time for it is in pilotWallSeconds, and alone in
    // prepareSeconds.
    const auto prepareStart = std::chrono::steady_clock::now();
    choice.probeSeconds = std::chrono::duration<double>(prepareStart - start).count();
    // Under PilotBudget::prepareFraction the preparation stops at its bound, checked before each group of the
    // candidates the engine compiles at once (RenderEngine::concurrentCompiles: one group may pass it), and the
    // candidates not prepared are left out; the own, prepared by the probe, always stays.
    const double prepareBound = budget.prepareFraction > 0.0
                                    ? std::min(budget.maxSeconds, budget.prepareFraction * choice.estimatedRenderSeconds)
                                    : std::numeric_limits<double>::infinity();
    choice.prepareBoundSeconds = prepareBound;
    const std::size_t group = std::max<std::size_t>(engine.concurrentCompiles(), 1);
    std::size_t prepared = 0;
    while (prepared < grid.size())
    {
        if (prepared > 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - prepareStart).count() > prepareBound)
            break;
        const std::size_t end = std::min(grid.size(), prepared + group);
        std::vector<RenderSettings> frames;
        for (std::size_t i = prepared; i < end; ++i)
            frames.push_back(grid[i].applyTo(pilot));
        const auto compileStart = std::chrono::steady_clock::now();
        engine.compileAhead(frames);
        choice.prepareCompileSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - compileStart).count();
        for (const RenderSettings& frame : frames)
            engine.beginFrame(frame);
        prepared = end;
    }
    choice.unprepared = static_cast<int>(grid.size() - prepared);
    // The plan above stays: a pilot of fewer candidates measures each at the planned size and leaves the rest of
    // its budget unspent (re-planning would prepare them again at another size).
    grid.resize(prepared);
    if (grid.size() == 1)
    {
        choice.spp = 2 * pilot.spp;
        choice.prepareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - prepareStart).count();
        choice.pilotWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return choice;
    }
    // The search's own clock: the probe and the preparation are not part of the budget the measurements fill.
    const auto searchStart = std::chrono::steady_clock::now();
    choice.prepareSeconds = std::chrono::duration<double>(searchStart - prepareStart).count();

    // A half of another strategy than the scene's that runs past 4x its planned time is stopped (or, where the engine
    // cannot stop it, not measured further): the candidate is too
    // slow to win (it would need 4x less error per path than the probe's strategy), and the budget holds (book 3's
    // mixture over 1000 lights took 15x its share on many-lights). Or past 4x the own's slower half of the round, on
    // the host's clock, where that is more: a machine loaded by other work slows every candidate (lavapipe beside
    // a test suite took every nee-mis candidate of rtrol-cornell-box past 4x its share, and the pilot kept the
    // mixture, half as efficient).
    const double shareMs = cost.ms(pixelsOf(pilot), pilot.spp); // the own's half, by the probe (not planCost)
    double ownHalfWallMs = 0.0; // the own's slower half in the round (half its frame, where one holds both)
    auto timeLimit = [&] {
        return std::chrono::nanoseconds(
            static_cast<std::int64_t>(std::max(4.0 * std::max(shareMs, ownHalfWallMs), 5.0) * 1e6));
    };
    // Whether a measurement of these settings takes one frame for both halves (a stratified candidate of --samplings
    // takes a frame a half).
    auto frameHoldsBothHalves = [&](const RenderSettings& half) {
        return choice.halvesInOneFrame && !seedBlocksRefusal(half);
    };

    /// A candidate's measurements: their sums, and each one's halves by its seeds' slot.
    struct Candidate
    {
        PilotRow row;
        PilotSums all;
        /// Every measurement's halves by their slot, those of the final round apart; the earlier ones dropped once
        /// the halving leaves the candidate out (their slots kept: they share seeds with the others').
        std::vector<std::pair<std::uint32_t, PilotHalves>> finals, earlier;
        std::vector<std::uint32_t> slots;
        double finalLeastMs = 0.0; // the least of its final round's measurements' time
        double timingLeastMs[2] = {0.0, 0.0}; // the least of its timing frames' times, at the timing spp and twice it
        double leastMs = 0.0; // of all its measurements
        int repeatFrames = 0; // its timing frames of the final round's repeats (measureOnce)
    };
    const double halfPaths = pixelsOf(pilot) * double(pilot.spp);
    std::vector<Candidate> runs;
    for (const Strategy& strategy : grid)
        runs.push_back({PilotRow{strategy, differences(own, strategy)}, {}, {}});
    std::uint32_t measured = 0; // measurements made
    // Every candidate's measurement of a round (and of each of the final round's repeats) takes that slot's seeds:
    // common random numbers (see the header).
    auto seedOf = [&](std::uint32_t slot) { return request.settings.seed + 7919u * (2u * slot + 1u); };
    // The first round's own once more, on seeds no other candidate takes: the first round's denominator (every other
    // candidate is measured on that round's seeds alone; see PilotMeasurement).
    constexpr std::uint32_t kOwnSeedSlot = 1u << 20, kNoSeedSlot = ~0u;
    // A path's time from the timing frames' least times at the timing spp (one) and twice it (two): their slope, as
    // every frame of a GPU's wavefront has a cost of its own that the probe's small frames do not show (its last
    // segments, a few paths each: on an H200's glossy-cornell at 600 px 5.4 ms a frame for every light sampler,
    // against 3.2 ns a path of the own and 1.7 of solid-angle sampling with uniform selection; the frames' whole
    // time, less the probe's fixed cost, put that ratio at 0.8, the render's 0.53, and the pilot kept the own at
    // 0.63x the best). Not below a tenth of the larger frame's time a path (a slope of noise); with one frame, or
    // where the two hold the same paths (stratified sampling's square spp), its time less the probe's fixed and
    // per-pixel terms, as before. A frame's paths are its candidate's: the sampling may be one of its settings
    // (--compare's --samplings), and stratified sampling rounds the spp to a square.
    RenderSettings twiceTiming = timing;
    twiceTiming.spp = 2 * timing.spp;
    auto framePaths = [&](const Candidate& c, const RenderSettings& frame) {
        return pixelsOf(frame) * double(c.row.strategy.applyTo(frame).trueSpp());
    };
    auto timingMsPerPath = [&](const Candidate& c) {
        const double one = c.timingLeastMs[0], two = c.timingLeastMs[1];
        const double oncePaths = framePaths(c, timing), twicePaths = framePaths(c, twiceTiming);
        if (one > 0.0 && two > 0.0 && twicePaths > oncePaths)
            return std::max((two - one) / (twicePaths - oncePaths), 0.1 * two / twicePaths);
        return one > 0.0 ? std::max(one - cost.ms(pixelsOf(timing), 0.0), 0.1 * one) / oncePaths : 0.0;
    };
    // The engine's stages of a search's render, into searchStageSeconds.
    auto addStages = [&](const Measurement& m) {
        for (const auto& [stage, seconds] : m.stageSeconds)
            choice.searchStageSeconds[stage] += seconds;
    };
    // A candidate's next timing frame, of three: the timing spp, twice it, then the timing spp again, so that a one-off
    // stall (the first render after a round's scoring meets one) is not the least; and a fourth at twice the spp where
    // the second stalled (timingStalled). False where cancelled.
    auto timingFrame = [&](Candidate& c, std::uint32_t slot) {
        const int level = c.row.timingFrames++ % 2;
        RenderRequest frame = request;
        frame.settings = c.row.strategy.applyTo(level == 1 ? twiceTiming : timing);
        frame.settings.seed = seedOf(slot) + 3u;
        const auto frameStart = std::chrono::steady_clock::now();
        const Measurement t = measure(engine, frame, nullptr, {}, true);
        choice.renderHostSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
        choice.tracingHostSeconds += t.wallMs * 1e-3;
        addStages(t);
        if (t.cancelled)
            return false;
        choice.pilotMs += t.ms();
        double& least = c.timingLeastMs[level];
        least = least > 0.0 ? std::min(least, t.ms()) : t.ms();
        c.row.timingMsPerPath = timingMsPerPath(c);
        return true;
    };
    // Whether the frame at twice the spp stalled: its least time more than 1.1x the paths' ratio (twice) times the
    // least at the timing spp, a slope well above the smaller frame's whole time per path, which a frame's fixed cost,
    // never negative, cannot give (the 10 % for a device whose time per path grows a little with a frame's fill). Its
    // one frame was the slope's: an H200's pilots of cornell-box-lights timed the own at 4.8-7.2 ns a path in 3 of 8
    // (2.6-2.9 in the others; stalls of 10-17 ms beside frames of 7-8 ms), and two of them chose strategies 0.95x and
    // 0.90x the own (notebook §52). A shorter stall is not seen. Taking four frames from every candidate instead cost
    // the halves a sixth of their paths, and two pilots of four then took book 3's mixture, 0.44x the own, to the
    // final round. The fourth frame is outside the plan (two units, four where both finalists stalled, beside the eight
    // planned for the frames).
    auto timingStalled = [&](const Candidate& c) {
        const double oncePaths = framePaths(c, timing), twicePaths = framePaths(c, twiceTiming);
        return c.timingLeastMs[0] > 0.0 && c.timingLeastMs[1] > 0.0 && twicePaths > oncePaths &&
               c.timingLeastMs[1] > 1.1 * c.timingLeastMs[0] * (twicePaths / oncePaths);
    };
    // Whether `c` takes another timing frame: its first three (one a measurement of the final round), and the fourth,
    // right after the third (in the guard's fallback, after the other candidate's next), where timingStalled.
    auto timingFrameDue = [&](const Candidate& c) {
        return c.row.timingFrames < 3 || (c.row.timingFrames == 3 && timingStalled(c));
    };
    // Each repeat of the final round past its kFinalMeasurements takes one more timing frame of each finalist, at
    // the level after its last (timingFrame alternates them): a frame at twice the spp delayed by less than
    // timingStalled sees is its level's least while it is the only one, and its slope then carries the delay (an
    // H200's pilots of cornell-box-lights put solid-angle sampling with the BVH at 0.94-0.95x the own's time per path
    // in 2 of 4, 0.80-0.84x in the others, the comparison 0.83x, and those two kept the own: notebook §63). The
    // repeats' test of the budget counts these frames with the rest of a repeat.
    auto measureOnce = [&](Candidate& c, bool finalRound, std::uint32_t slot) {
        const bool repeat = c.finals.size() >= std::size_t(kFinalMeasurements);
        if (finalRound && choice.timingSpp > 0 && (c.row.timingFrames < 3 || repeat))
        {
            if (!timingFrame(c, slot))
                return false;
            c.repeatFrames += repeat ? 1 : 0;
            if (c.row.timingFrames == 3 && timingStalled(c) && !timingFrame(c, slot))
                return false;
        }
        RenderRequest half = request;
        half.settings = c.row.strategy.applyTo(pilot);
        half.settings.seed = seedOf(slot);
        ++measured;
        // The scene's own strategy is the one to beat (and the probe's): never stopped, or nothing would compare
        // (a loaded machine took it past 4x its share of a 3 ms render's pilot).
        const bool isOwn = &c == &runs.front();
        const auto limit = isOwn ? std::chrono::nanoseconds(0) : timeLimit();
        const auto renderStart = std::chrono::steady_clock::now();
        // A candidate of another estimator than the own's takes a frame a half until it has run within its limit
        // once: its cost is unknown, the engine cannot stop a frame part way, and apart the guard stops it after its
        // first half (book 3's mixture over triangle-lights' lights ran a frame of both halves at 17x its share on an
        // H200, 126 ms of a 400 ms budget; the samplers and selections of one estimator differ far less).
        const bool costKnown = isOwn || c.row.measurements > 0 ||
                               half.settings.estimator == runs.front().row.strategy.applyTo(pilot).estimator;
        const bool oneFrame = costKnown && frameHoldsBothHalves(half.settings);
        Measurement a, b;
        double measuredMs = 0.0; // both halves on the engine's clock
        if (oneFrame)
        {
            RenderRequest both = half;
            both.settings.spp = 2 * half.settings.trueSpp();
            const SeedBlockScope blocks(engine, static_cast<std::uint32_t>(half.settings.trueSpp()));
            Measurement frame = measure(engine, both, nullptr, 2 * limit, true);
            addStages(frame);
            a = Measurement{.spp = frame.spp / 2, .wallMs = frame.wallMs, .cancelled = frame.cancelled,
                            .timedOut = frame.timedOut};
            b = a;
            measuredMs = frame.ms();
            choice.tracingHostSeconds += frame.wallMs * 1e-3;
            if (isOwn)
                ownHalfWallMs = 0.5 * frame.wallMs;
            if (!frame.cancelled)
                std::tie(a.image, b.image) = seedBlockHalves(frame.image, pixelsOf(half.settings));
        }
        else
        {
            a = measure(engine, half, nullptr, limit, true);
            addStages(a);
            ++half.settings.seed;
            b = a.cancelled || a.timedOut ? Measurement{.cancelled = a.cancelled, .timedOut = a.timedOut}
                                          : measure(engine, half, nullptr, limit, true);
            addStages(b);
            // The halves are the same work: the faster one's time twice, so that a one-off stall of either (a
            // pool's first use, a clock ramping up: 2x on the first candidate after the probe, measured) does not
            // decide.
            measuredMs = 2.0 * std::min(a.ms(), b.ms());
            choice.tracingHostSeconds += (a.wallMs + b.wallMs) * 1e-3;
            if (isOwn)
                ownHalfWallMs = std::max(a.wallMs, b.wallMs);
        }
        choice.renderHostSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();
        if (b.cancelled && !b.timedOut)
            return false;
        choice.pilotMs += oneFrame ? measuredMs : a.ms() + b.ms();
        if (b.timedOut)
        {
            c.row.tooSlow = true;
            c.row.ms += oneFrame || a.timedOut ? a.wallMs : a.ms() + b.wallMs; // what it ran, not a measurement
            return true;
        }
        if (measured == 1 && budget.renderSeconds <= 0.0)
        {
            // The first candidate is the probe's strategy on more paths: a better time per path (one probe of 1 spp
            // overestimated a 1 s render 2.7x on 2 cores), hence the render's time and the budget. Never above the
            // probe's estimate: both err long (small frames; a device slow to wake), and the first measurement
            // after the candidates' preparation can meet a GPU whose clocks fell while the host compiled (an
            // H200, 11 s of cold compiles: the render estimated at 66.6 s against the probe's 25 s, the strategy
            // it chose rendered in 8.5 s).
            const double frameMs = oneFrame ? measuredMs : 0.5 * measuredMs; // a frame's, of one or both halves
            const double paths = pixelsOf(half.settings) * half.settings.trueSpp() * (oneFrame ? 2.0 : 1.0);
            RenderCost measuredCost = cost;
            measuredCost.msPerPath =
                std::max(frameMs - cost.ms(pixelsOf(half.settings), 0), 0.25 * frameMs) / paths;
            choice.estimatedRenderSeconds =
                std::min(choice.estimatedRenderSeconds,
                         measuredCost.ms(pixelsOf(request.settings), request.settings.trueSpp()) * 1e-3);
            choice.budgetSeconds = std::min(budget.maxSeconds, budget.fraction * choice.estimatedRenderSeconds);
        }
        choice.spp = a.spp + b.spp;
        // Less the overhead of each frame, but never below a tenth of the time (the probe's terms are estimates; a
        // half planned to its share at 1 spp has paths of a quarter of it where the fixed cost is half).
        const double frames = oneFrame ? 1.0 : 2.0;
        const double ms = std::max(measuredMs - frames * choice.overheadMs, 0.1 * measuredMs);
        c.row.ms += ms;
        ++c.row.measurements;
        c.all.add(a.image, b.image);
        c.leastMs = c.leastMs > 0.0 ? std::min(c.leastMs, ms) : ms;
        c.slots.push_back(slot);
        if (finalRound)
            c.finalLeastMs = c.finalLeastMs > 0.0 ? std::min(c.finalLeastMs, ms) : ms;
        (finalRound ? c.finals : c.earlier).emplace_back(slot, PilotHalves{std::move(a.image), std::move(b.image)});
        return true;
    };
    // Every candidate measured: their halves' means over all their measurements, in runs' order.
    auto scored = [&] {
        std::vector<Candidate*> out;
        for (Candidate& c : runs)
            if (c.row.measurements > 0 && !c.row.tooSlow)
                out.push_back(&c);
        return out;
    };
    auto halvesAt = [](const Candidate& c, std::uint32_t at) -> const PilotHalves* {
        for (const auto* list : {&c.finals, &c.earlier})
            for (const auto& [s, halves] : *list)
                if (s == at)
                    return &halves;
        return nullptr;
    };
    const std::size_t values = 3 * std::size_t(pixelsOf(pilot));
    // The estimate without one seed's measurements (`leftOut`'s slot): every candidate's estimate without its
    // measurement of that seed (a candidate left out of the halving whose halves of that seed are gone: not at all),
    // weighted by its inverse relMSE (its measurements' count, less the one left out, over one measurement's relMSE),
    // or, where `plain`, by its measurements' count. None where no other seed's measurement is left.
    auto otherSeeds = [&](const std::vector<Candidate*>& measuredRuns, std::uint32_t leftOut, bool plain) {
        std::vector<double> total(values, 0.0);
        double weight = 0.0;
        for (Candidate* c : measuredRuns)
        {
            const PilotHalves* left = halvesAt(*c, leftOut);
            if (!left && std::find(c->slots.begin(), c->slots.end(), leftOut) != c->slots.end())
                continue;
            const std::vector<double>& sums = c->all.sums();
            const double k = double(c->all.count), kept = left ? k - 1.0 : k;
            if (kept <= 0.0)
                continue;
            const double w = plain ? kept : kept / k / std::max(c->row.relMse, 1e-300);
            weight += w;
            if (!left)
                for (std::size_t v = 0; v < values; ++v)
                    total[v] += w * sums[v] / (2.0 * k);
            else
            {
                const float* a = &left->a.data()->x;
                const float* b = &left->b.data()->x;
                for (std::size_t v = 0; v < values; ++v)
                    total[v] += w * (sums[v] - double(a[v]) - double(b[v])) / (2.0 * kept);
            }
        }
        std::vector<float> d(weight > 0.0 ? values : 0, 0.0f);
        for (std::size_t v = 0; v < d.size(); ++v)
            d[v] = float(total[v] / weight);
        return d;
    };
    // The relMSE of each candidate whose measurements' halves are kept (one left out of the halving keeps its row's),
    // each measurement normalised by the estimate from every other seed's (measuredRelMse): the table's figures and
    // the halving's order. Twice: the first with the estimates' plain mean, whose errors then weight the second.
    auto rescore = [&] {
        const auto scoringStart = std::chrono::steady_clock::now();
        const std::vector<Candidate*> measuredRuns = scored();
        std::vector<Candidate*> kept;
        std::vector<std::uint32_t> seeds;
        for (Candidate* c : measuredRuns)
            if (!c->finals.empty() || !c->earlier.empty())
            {
                kept.push_back(c);
                for (const auto* list : {&c->finals, &c->earlier})
                    for (const auto& measurement : *list)
                        if (std::find(seeds.begin(), seeds.end(), measurement.first) == seeds.end())
                            seeds.push_back(measurement.first);
            }
        std::vector<std::vector<float>> denominators(seeds.size());
        // Where no other seed was measured (the guard passed before the own's second seed: no challenger was
        // measured, and nothing is decided), the table's figures against the estimate of every measurement.
        std::vector<float> everySeed;
        for (int pass = 0; pass < 2; ++pass)
        {
            onHostCores(seeds.size(),
                        [&](std::size_t i) { denominators[i] = otherSeeds(measuredRuns, seeds[i], pass == 0); });
            if (std::any_of(denominators.begin(), denominators.end(), [](const auto& d) { return d.empty(); }))
                everySeed = otherSeeds(measuredRuns, kNoSeedSlot, pass == 0);
            std::vector<PilotError> errors(kept.size());
            onHostCores(kept.size(), [&](std::size_t i) {
                std::vector<PilotMeasurement> terms;
                for (const auto* list : {&kept[i]->finals, &kept[i]->earlier})
                    for (const auto& [seed, halves] : *list)
                    {
                        const std::vector<float>& d =
                            denominators[std::size_t(std::find(seeds.begin(), seeds.end(), seed) - seeds.begin())];
                        terms.push_back({&halves, d.empty() ? &everySeed : &d});
                    }
                errors[i] = measuredRelMse(terms);
            });
            for (std::size_t i = 0; i < kept.size(); ++i)
            {
                PilotRow& row = kept[i]->row;
                row.relMse = errors[i].relMse;
                row.relMseError = errors[i].standardError;
                row.efficiency = row.relMse > 0.0 && row.ms > 0.0 ? 1.0 / (row.relMse * row.ms * 1e-3) : 0.0;
            }
        }
        choice.scoringSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - scoringStart).count();
    };

    bool finished = true;
    // Whether the final round began its challenger's first measurement: where it did, the final round decides (a
    // challenger stopped there as too slow keeps the own, whatever the host's clock did next).
    bool challengerInFinal = false;
    std::vector<std::size_t> active(runs.size());
    for (std::size_t i = 0; i < active.size(); ++i)
        active[i] = i;
    std::uint32_t slot = 0; // the round's (its repeat's) seeds
    // The final round repeats past kFinalMeasurements while the engine's clock leaves room for one more repeat (by the
    // costlier of the last two: a repeat's timing frames alternate their sizes), up to kMostFinalMeasurements, and
    // while the challenger leads the own by the switch's 5 % on all their measurements (scored again after each
    // repeat): a plan made by a slow probe (a 2-core machine's thread pool waking late: the time per path at 1.5x the
    // render's) leaves part of the budget unspent, and the decision is what it serves best. On the CI kind's 4 s
    // renders such pilots ended at 0.39-0.56x their 0.2 s budget at 6-8 spp a measurement where 12-14 fitted, and one
    // took area sampling with uniform selection on glossy-cornell, 0.94x the own, on a lead of 1.49 (notebook §61). A
    // challenger behind the own by then would not be taken on more measurements: the repeats would only cost time (a
    // rect-light-closeup's pilots, the own the best, took 0.92-1.12x their budget where 0.48-0.74x without the lead's
    // test). A plan that fills the budget has no room left and repeats kFinalMeasurements times, as before. The budget
    // is read at each repeat (the search's first measurement may lower it: chooseStrategy's estimate), and the host's
    // clock must leave the repeat room within the guard too, which the host's own time per render (a GPU's 7-14 ms)
    // would otherwise pass.
    constexpr int kMostFinalMeasurements = 8 * kFinalMeasurements;
    // The engine's and the host's time of the last two repeats, by the repeat's parity.
    double repeatMs[2] = {0.0, 0.0}, repeatHostSeconds[2] = {0.0, 0.0};
    auto finalRepeatFits = [&](int repeat) {
        if (repeat < kFinalMeasurements)
            return true;
        const double lastRepeatMs = std::max(repeatMs[0], repeatMs[1]);
        const double lastRepeatHostSeconds = std::max(repeatHostSeconds[0], repeatHostSeconds[1]);
        const double searchSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - searchStart).count();
        if (active.size() != 2 || runs[active[1]].row.tooSlow || repeat >= kMostFinalMeasurements ||
            choice.pilotMs + lastRepeatMs > choice.budgetSeconds * 1e3 ||
            searchSeconds + lastRepeatHostSeconds > 2.0 * choice.budgetSeconds)
            return false;
        rescore();
        return runs[active[1]].row.efficiency > kMinimumLead * runs[active[0]].row.efficiency;
    };
    while (finished && !choice.budgetSpent)
    {
        const bool finalRound = active.size() <= 2;
        for (int repeat = 0; finished && !choice.budgetSpent && (finalRound ? finalRepeatFits(repeat) : repeat < 1);
             ++repeat, ++slot)
        {
            const double repeatStartMs = choice.pilotMs;
            const auto repeatStart = std::chrono::steady_clock::now();
            // The round's measurements: every active candidate on the slot's seeds, and in the first round (a final
            // one of two candidates too) the own once more on seeds of its own (kOwnSeedSlot), not one of the final
            // round's.
            struct Entry
            {
                std::size_t i;
                std::uint32_t seeds;
                bool final;
            };
            std::vector<Entry> round;
            for (const std::size_t i : active)
            {
                round.push_back({i, slot, finalRound});
                if (i == 0 && slot == 0)
                    round.push_back({i, kOwnSeedSlot, false});
            }
            for (const auto& [i, seeds, final] : round)
            {
                if (runs[i].row.tooSlow)
                    continue;
                // The host's clock holds the search to twice its budget: the measurements are planned to fill the
                // budget on the engine's clock, and the host adds what no engine clock sees (each render's set-up,
                // a pipeline a GPU had not compiled).
                // Held to the budget itself, with the probe inside it, the search never reached its final round
                // (rect-light-closeup, 2 cores: 3 measurements of 5 candidates). What is left is not measured.
                if (measured > 0 &&
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - searchStart).count() >
                        2.0 * choice.budgetSeconds)
                {
                    choice.budgetSpent = true;
                    break;
                }
                challengerInFinal |= finalRound && i != 0;
                if (!(finished = measureOnce(runs[i], final, seeds)))
                    break;
            }
            repeatMs[repeat % 2] = choice.pilotMs - repeatStartMs;
            repeatHostSeconds[repeat % 2] =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - repeatStart).count();
        }
        if (!finished || finalRound)
            break;
        rescore();
        // Half go on: the scene's own (never stopped) and the most efficient of the others. (Own added after the
        // better half, where it was not in it, kept three candidates at three for good: the pilot measured them
        // until the host's clock passed its budget.)
        const std::size_t keep = (active.size() + 1) / 2;
        std::vector<std::size_t> next;
        for (const std::size_t i : active)
            if (i != 0 && !runs[i].row.tooSlow && runs[i].row.measurements > 0)
                next.push_back(i);
        std::sort(next.begin(), next.end(),
                  [&](std::size_t x, std::size_t y) { return runs[x].row.efficiency > runs[y].row.efficiency; });
        next.resize(std::min(next.size(), keep - 1));
        next.insert(next.begin(), 0);
        for (const std::size_t i : active)
            if (std::find(next.begin(), next.end(), i) == next.end())
                runs[i].earlier = {};
        active = std::move(next);
        if (active.size() <= 1)
            break;
    }
    auto stopClocks = [&] {
        choice.pilotWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        choice.searchSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - searchStart).count();
    };
    auto cancelledChoice = [&] {
        stopClocks();
        return cancelled();
    };
    if (!finished)
        return cancelledChoice();
    rescore();
    // The decision: a challenger against the scene's own, on their measurements paired by seed. Where the final round
    // ran, its challenger on its final measurements alone: its earlier ones chose it for that round, so they are the
    // luckiest of their round (the winner's curse: on the CPU's cornell-box-lights, whose 13 candidates are within
    // 10 % of each other, deciding on them switched with 3 seeds of 3, to three different strategies).
    const std::vector<Candidate*> measuredRuns = scored();
    Candidate& ownRun = runs.front();
    // `rival` against the own over the seeds both measured (the final round's alone, where `finalOnly`), each at
    // its measurement's time (ownMs, rivalMs): false where they share no seed. The switch needs the lead on all the
    // pairs and, where there are two or more, without the own's worst: a firefly in the own's renders is one pair's,
    // and a lead that stands on it alone is no measurement of the own's tail.
    auto decidePaired = [&](Candidate& rival, bool finalOnly, double ownMs, double rivalMs) {
        std::vector<std::vector<float>> denominators;
        std::vector<PilotPair> pairs;
        denominators.reserve(ownRun.slots.size());
        for (const std::uint32_t shared : ownRun.slots)
        {
            const bool inFinal = std::any_of(ownRun.finals.begin(), ownRun.finals.end(),
                                             [&](const auto& f) { return f.first == shared; });
            const PilotHalves* ownHalves = halvesAt(ownRun, shared);
            const PilotHalves* rivalHalves = halvesAt(rival, shared);
            if ((inFinal || !finalOnly) && ownHalves && rivalHalves)
            {
                std::vector<float>& d = denominators.emplace_back(otherSeeds(measuredRuns, shared, false));
                if (!d.empty())
                    pairs.push_back({ownHalves, rivalHalves, &d});
            }
        }
        if (pairs.empty())
            return false;
        PilotRow& row = rival.row;
        PilotRow& incumbent = ownRun.row;
        const PairedRelMse paired = pairedRelMse(pairs);
        const double k = double(pairs.size());
        auto fill = [&](PilotRow& r, double relMse, double error, double ms) {
            r.finalMeasurements = int(pairs.size());
            r.finalRelMse = relMse;
            r.finalRelMseError = error;
            r.finalEfficiency = relMse > 0.0 ? 1.0 / (relMse * k * ms * 1e-3) : 0.0;
        };
        fill(incumbent, paired.own, paired.ownError, ownMs);
        fill(row, paired.challenger, paired.challengerError, rivalMs);
        row.relMseRatio = paired.ratio;
        row.relMseRatioError = paired.ratioError;
        auto switches = [&](double ratio, double error) {
            return ratio > 0.0 && rivalMs > 0.0 && pilotSwitches(ownMs / (ratio * rivalMs), error / ratio);
        };
        bool switching = switches(paired.ratio, paired.ratioError);
        if (pairs.size() >= 2)
        {
            std::vector<PilotPair> trimmed = pairs;
            trimmed.erase(trimmed.begin() + (std::max_element(paired.ownPerPair.begin(), paired.ownPerPair.end()) -
                                             paired.ownPerPair.begin()));
            const PairedRelMse rest = pairedRelMse(trimmed);
            row.trimmedRelMseRatio = rest.ratio;
            row.trimmedRelMseRatioError = rest.ratioError;
            switching = switching && switches(rest.ratio, rest.ratioError);
        }
        if (switching)
            choice.chosen = row.strategy;
        return true;
    };
    const auto challenger = std::find_if(measuredRuns.begin(), measuredRuns.end(), [&](const Candidate* c) {
        return c != &ownRun && !c->finals.empty();
    });
    // Whether the final round decided: one cut to a single pair by the host's clock (lavapipe beside other work:
    // 48 s of a pilot held to 20 s, nee-mis 4x as efficient as the own) decides as a search without one.
    bool decided = false;
    // The timing frames `first` and the own have not taken (their three, and a stalled one's fourth), in turns,
    // `first` first: where the host's clock cut the final round, its frames were cut with it (after the own's third
    // measurement, before the challenger's, a stalled frame at twice the spp was the challenger's slope: 0.25x the
    // own's where 1.39x). False where cancelled.
    // A repeat the guard cut between the finalists (or within the own's measurement, after its timing frame) left the
    // own a timing frame more: the other takes it, so that both least times stand on as many frames at each level.
    auto completeTimingFrames = [&](Candidate& first) {
        for (int frame = 0; frame < 4 && choice.timingSpp > 0; ++frame)
            for (Candidate* c : {&first, &ownRun})
                if (timingFrameDue(*c) && !timingFrame(*c, slot))
                    return false;
        for (Candidate* c : {&first, &ownRun})
        {
            const Candidate& other = c == &ownRun ? first : ownRun;
            for (; c->repeatFrames < other.repeatFrames; ++c->repeatFrames)
                if (!timingFrame(*c, slot))
                    return false;
        }
        return true;
    };
    if (challenger != measuredRuns.end() && measuredRuns.front() == &ownRun && ownRun.finals.size() >= 2 &&
        (*challenger)->finals.size() >= 2)
    {
        // A measurement's time: from the timing frames where the final round had them, else the least of the final
        // round's measurements of each (they take turns; a stall only adds time: on 2 cores one measurement of the
        // own's 6 ms renders took 7.9 ms where its others took 5.6-6.6).
        Candidate& rival = **challenger;
        if (!completeTimingFrames(rival)) // a final round that ran whole has them all
            return cancelledChoice();
        const bool timed = rival.row.timingMsPerPath > 0.0 && ownRun.row.timingMsPerPath > 0.0;
        decided = decidePaired(rival, true, timed ? 2.0 * halfPaths * ownRun.row.timingMsPerPath : ownRun.finalLeastMs,
                               timed ? 2.0 * halfPaths * rival.row.timingMsPerPath : rival.finalLeastMs);
    }
    if (!decided && choice.budgetSpent && (!challengerInFinal || challenger != measuredRuns.end()) &&
        measuredRuns.size() > 1 && measuredRuns.front() == &ownRun)
    {
        // The search stopped before its final round decided: the host's clock passed the budget first (a GPU
        // compiling the candidates' pipelines; the host's set-up of each render, 7.9 ms on an H200's; or right as
        // the final round began, before its challenger's first measurement: an H200's glossy-cornell at 10 s then
        // kept the own, 0.65x the best, whose lead of 1.3x its measurements had shown). The most efficient of the
        // last round's candidates measured most often, against the own on every seed they share, by the same rule:
        // those measurements chose it, but paired with the own's they hold little of the luck a lone measurement
        // does (with independent seeds, the leader taken among candidates of one measurement, which a heavy-tailed
        // error most often puts below its mean, chose area sampling with uniform selection on an H200's
        // glossy-cornell at 8 s, 0.77x the best, and unpaired, solid-angle uniform on its cornell-box-lights, 0.90x
        // the own).
        int most = 0;
        for (const std::size_t i : active)
            if (i != 0 && !runs[i].row.tooSlow)
                most = std::max(most, runs[i].row.measurements);
        Candidate* leader = nullptr;
        for (const std::size_t i : active)
            if (i != 0 && !runs[i].row.tooSlow && most > 0 && runs[i].row.measurements == most &&
                (!leader || runs[i].row.efficiency > leader->row.efficiency))
                leader = &runs[i];
        // A leader was measured after the own's two seeds of the first round, so it has a pair at least. Timed by
        // its and the own's timing frames where the plan had them, taken now if the final round did not: its halves
        // hide what the frames show (an H200's glossy-cornell at 8 s, whose guard passed before the final round in
        // one pilot of four: solid-angle sampling with uniform selection 0.83x the own's time by the halves, 0.51x by
        // the timing frames, 0.54x in the render; the pilot kept the own, 0.66x the best). That passes the guard
        // by up to the frames' planned quarter of the budget (and a stalled frame's second take), which buys the
        // decision the search was for. The two take turns, the leader first: the first render after the scoring meets
        // a stall where one comes, and the leader's first frame is at the timing spp, which its third repeats (the
        // own, stopped after its first final measurement, would render its only frame at twice the spp there).
        if (leader)
        {
            if (!completeTimingFrames(*leader))
                return cancelledChoice();
            const bool timed = leader->row.timingMsPerPath > 0.0 && ownRun.row.timingMsPerPath > 0.0;
            decidePaired(*leader, false, timed ? 2.0 * halfPaths * ownRun.row.timingMsPerPath : ownRun.leastMs,
                         timed ? 2.0 * halfPaths * leader->row.timingMsPerPath : leader->leastMs);
        }
    }
    stopClocks();
    for (const Candidate& c : runs)
        choice.rows.push_back(c.row);
    return choice;
}

bool pilotSwitches(double lead, double logLeadError)
{
    if (!(lead > 0.0) || !std::isfinite(logLeadError))
        return false;
    // Two standard errors, though the challenger's final measurements are fresh: a heavy tail its few renders did not
    // meet is in no standard error, and its measured lead is then high more often than low. At one, CPU pilots of
    // veach-mis (4 s, 12 seeds) left the own for area sampling with uniform selection once, 0.2x its efficiency, and
    // on cornell-box-lights and glossy-cornell, whose best leads the own by 10-15 %, gained nothing a 0.2 s pilot
    // could show (auto 0.85x and 0.86x the best, as at two): notebook §41. The lead must also be 5 %: the relMSE's
    // standard error leaves the times out, and a pilot's renders of a few milliseconds are timed to a few percent; a
    // smaller lead would also gain less than the pilot cost. Not 10 %, as it was: an H200's pilots of
    // cornell-box-lights time its best (solid-angle sampling, 0.82x the own's time per path at 600 px) at 0.87-0.92x,
    // see a lead of 1.07-1.10 where the render's is 1.11-1.14, and kept the own in 3 of 4 seeds, 0.86x the best
    // (notebook §52); over the 130 recorded pilots of both engines, the 5 % changed 7 choices, 6 to a better strategy
    // (leads of 1.11-1.49) and one to a worse (0.95x).
    return std::log(lead) > std::max(std::log(kMinimumLead), 2.0 * logLeadError);
}

nlohmann::json AutoChoice::toJson() const
{
    nlohmann::json j;
    j["chosen"] = chosen.name();
    j["pilot_width"] = width;
    j["pilot_height"] = height;
    j["pilot_spp"] = spp;
    j["estimated_render_seconds"] = estimatedRenderSeconds;
    j["budget_seconds"] = budgetSeconds;
    j["pilot_ms"] = pilotMs;
    j["pilot_wall_seconds"] = pilotWallSeconds;
    j["prepare_seconds"] = prepareSeconds;
    j["probe_seconds"] = probeSeconds;
    j["search_seconds"] = searchSeconds;
    j["search_scoring_seconds"] = scoringSeconds;
    j["probe_host_extra_ms"] = hostExtraMs;
    j["probe_ms"] = probeMs;
    j["candidates_cost_scale"] = candidatesCostScale;
    j["calibration_ms"] = calibrationMs;
    j["plan_cost"] = {{"fixed_ms", planCost.fixedMs},
                      {"ms_per_pixel", planCost.msPerPixel},
                      {"ms_per_path", planCost.msPerPath}};
    j["timing_width"] = timingWidth;
    j["timing_spp"] = timingSpp;
    j["search_render_host_seconds"] = renderHostSeconds;
    j["search_tracing_host_seconds"] = tracingHostSeconds;
    j["search_stage_seconds"] = searchStageSeconds;
    j["prepare_compile_seconds"] = prepareCompileSeconds;
    j["probes"] = nlohmann::json::array();
    for (const ProbeTiming& p : probes)
        j["probes"].push_back({{"pixels", p.pixels}, {"spp", p.spp}, {"ms", p.ms}});
    j["render_cost"] = {{"fixed_ms", cost.fixedMs}, {"ms_per_pixel", cost.msPerPixel}, {"ms_per_path", cost.msPerPath}};
    j["half_overhead_ms"] = overheadMs;
    j["halves_in_one_frame"] = halvesInOneFrame;
    j["pilot_frame_configuration"] = frameConfiguration;
    j["budget_spent"] = budgetSpent;
    j["too_short"] = tooShort;
    j["unprepared_candidates"] = unprepared;
    if (std::isfinite(prepareBoundSeconds))
        j["prepare_bound_seconds"] = prepareBoundSeconds;
    j["relmse_epsilon"] = kRelMseEpsilon;
    j["candidates"] = nlohmann::json::array();
    for (const PilotRow& r : rows)
        j["candidates"].push_back({{"strategy", r.strategy.name()},
                                   {"differs_from_own", r.differs},
                                   {"ms", r.ms},
                                   {"relmse", r.relMse},
                                   {"relmse_standard_error", r.relMseError},
                                   {"efficiency", r.efficiency},
                                   {"measurements", r.measurements},
                                   {"final_measurements", r.finalMeasurements},
                                   {"final_relmse", r.finalRelMse},
                                   {"final_relmse_standard_error", r.finalRelMseError},
                                   {"final_efficiency", r.finalEfficiency},
                                   {"final_relmse_ratio_to_own", r.relMseRatio},
                                   {"final_relmse_ratio_standard_error", r.relMseRatioError},
                                   {"final_relmse_ratio_without_owns_worst", r.trimmedRelMseRatio},
                                   {"final_relmse_ratio_without_owns_worst_standard_error", r.trimmedRelMseRatioError},
                                   {"timing_ms_per_path", r.timingMsPerPath},
                                   {"timing_frames", r.timingFrames},
                                   {"too_slow", r.tooSlow}});
    return j;
}

std::string AutoChoice::table() const
{
    std::string text = fmt::format("{:<44} {:>30} {:>3} {:>9} {:>10} {:>8} {:>12}\n", "strategy", "differs from own",
                                   "n", "paths ms", "relMSE", "±1 s.e.", "1/(relMSE s)");
    for (const PilotRow& r : rows)
    {
        const std::string timed =
            r.timingMsPerPath > 0.0 ? fmt::format(" (timing frames: {:.3g} ns a path)", r.timingMsPerPath * 1e6) : "";
        std::string decided;
        if (r.finalMeasurements > 0)
            decided = fmt::format("  decided on {} seeds' x2 halves: relMSE {:.3g} ±{:.2g}, 1/(relMSE s) {:.4g}",
                                  r.finalMeasurements, r.finalRelMse, r.finalRelMseError, r.finalEfficiency);
        if (r.relMseRatio > 0.0)
            decided += fmt::format("; relMSE over the own's, paired: {:.3g} ±{:.2g}{}{}", r.relMseRatio,
                                   r.relMseRatioError,
                                   r.finalMeasurements >= 2
                                       ? fmt::format(", without the own's worst pair {:.3g} ±{:.2g}",
                                                     r.trimmedRelMseRatio, r.trimmedRelMseRatioError)
                                       : std::string(),
                                   r.strategy == chosen ? ": chosen" : ": not enough to switch");
        text += fmt::format("{:<44} {:>30} {:>3} {:>9.2f} {:>10.3g} {:>8.2g} {:>12.4g}{}{}{}\n", r.strategy.name(),
                            r.differs, r.measurements, r.ms, r.relMse, r.relMseError, r.efficiency,
                            r.tooSlow                                        ? "  stopped: 4x its share"
                            : r.measurements == 0                            ? "  not measured: the budget was spent"
                            : r.strategy == chosen && r.relMseRatio == 0.0     ? "  <- chosen"
                                                                             : "",
                            decided, timed);
    }
    return text;
}
} // namespace rt::compare
