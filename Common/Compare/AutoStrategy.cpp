#include "Compare/AutoStrategy.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>

#include "Compare/Measurement.h"
#include "Error.h"
#include "Image/Metrics.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
namespace
{
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
            lists[flag] = "nee-mis,mixture";
        else if (s->name == "light-sampler" && emitters > 0)
            lists[flag] = polygonLights ? "projected,solid-angle,area,projected-exact" : "projected,solid-angle,area";
        else if (s->name == "light-selection" && emitters > 1)
            lists[flag] = "bvh,power,uniform";
    }
    return lists;
}

std::vector<PilotError> pilotRelMse(const std::vector<PilotHalves>& candidates)
{
    const std::size_t n = candidates.size();
    if (n == 0)
        return {};
    const int width = candidates.front().a.width(), height = candidates.front().a.height();
    for (const PilotHalves& c : candidates)
        for (const Image* image : {&c.a, &c.b})
            if (image->width() != width || image->height() != height)
                throw UsageError(fmt::format("pilot images differ in size ({}x{} and {}x{})", width, height,
                                             image->width(), image->height()));
    const std::size_t values = std::size_t(width) * std::size_t(height) * 3;
    if (values == 0)
        return std::vector<PilotError>(n);
    // x: each candidate's estimate (the halves' mean); v: its variance, (a - b)^2 / 4 (Image/Metrics.h).
    std::vector<std::vector<double>> x(n, std::vector<double>(values)), v(n, std::vector<double>(values));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < values; ++k)
        {
            const double a = candidates[i].a.data()[k / 3][int(k % 3)], b = candidates[i].b.data()[k / 3][int(k % 3)];
            x[i][k] = 0.5 * (a + b);
            v[i][k] = 0.25 * (a - b) * (a - b);
        }
    // relMSE's denominator for candidate i: the others' estimate, per pixel. Never candidate i's own image: a firefly
    // divided by itself would make the spikiest estimator look the best (measured: bsdf chosen over nee-mis, which
    // is 2x as efficient, on cornell-box-lights at 2 spp).
    // (Not blurred: over 5 x 5 pixels of a 40 x 27 pilot a light's bright pixels took their dark neighbours' values,
    // and their antialiasing noise over those read as relMSE 100x the render's on veach-mis.)
    auto othersNorm = [&](std::size_t i, const std::vector<double>& w) {
        std::vector<double> mean(values, 0.0);
        double weight = 0.0;
        for (std::size_t j = 0; j < n; ++j)
            if (j != i || n == 1)
            {
                weight += w[j];
                for (std::size_t k = 0; k < values; ++k)
                    mean[k] += w[j] * x[j][k];
            }
        for (double& m : mean)
            m /= weight;
        for (double& m : mean)
            m = m * m + kRelMseEpsilon;
        return mean;
    };
    // The mean of squared / norm over the values, and its standard error.
    auto relative = [&](const std::vector<double>& squared, const std::vector<double>& norm) {
        double sum = 0.0, sumSquares = 0.0;
        for (std::size_t k = 0; k < values; ++k)
        {
            const double t = squared[k] / norm[k];
            sum += t;
            sumSquares += t * t;
        }
        const double mean = sum / double(values);
        const double variance = std::max(sumSquares / double(values) - mean * mean, 0.0);
        return PilotError{mean, std::sqrt(variance / double(values))};
    };
    // Twice: the others' plain mean gives every candidate's error, whose inverses weight the others' mean of the
    // second pass, so that a noisy candidate does not make its neighbours' denominators noisy.
    std::vector<double> w(n, 1.0);
    std::vector<PilotError> errors(n);
    for (int pass = 0; pass < 2; ++pass)
    {
        for (std::size_t i = 0; i < n; ++i)
            errors[i] = relative(v[i], othersNorm(i, w));
        for (std::size_t i = 0; i < n; ++i)
            w[i] = 1.0 / std::max(errors[i].relMse, 1e-300);
    }
    return errors;
}

AutoChoice chooseStrategy(RenderEngine& engine, const RenderRequest& request, const StrategyLists& candidates,
                          const PilotBudget& budget)
{
    const auto start = std::chrono::steady_clock::now();
    AutoChoice choice;
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
    choice.chosen = own;
    const std::size_t planned = grid.size();
    if (planned == 1)
        return choice;

    // The probe: the starting strategy at 1 spp, on about a 32nd of the render's paths (the whole image at most).
    const double renderPaths = pixelsOf(request.settings) * double(request.settings.trueSpp());
    RenderRequest probe = request;
    probe.settings = best;
    probe.settings.spp = 1;
    probe.settings.width = widthFor(request.settings, std::max(1024.0, renderPaths / 32.0));
    const Measurement probed = measure(engine, probe, nullptr);
    if (probed.cancelled)
    {
        choice.cancelled = true;
        choice.chosen = Strategy::of(request.settings);
        return choice;
    }
    choice.pilotMs += probed.ms();
    const double msPerPath = std::max(probed.ms(), 1e-6) / pixelsOf(probe.settings);
    choice.estimatedRenderSeconds = budget.renderSeconds > 0.0 ? budget.renderSeconds : msPerPath * renderPaths * 1e-3;
    choice.budgetSeconds = std::min(budget.maxSeconds, budget.fraction * choice.estimatedRenderSeconds);
    // Successive halving (Jamieson & Talwalkar 2016): every candidate measured once, then the better half again,
    // and so on down to two (the scene's own stays in every round, as the one to beat). A candidate whose first
    // measurement was lucky (a pilot sees few of the rare paths that carry a glossy scene's light) is measured
    // again before it can win: measured once each, uniform light selection won veach-mis's pilot at 6x nee-mis
    // with the BVH, which the full comparison puts at 0.9x. Every measurement of every round is the same size.
    std::size_t measurements = 0;
    for (std::size_t m = planned;; m = (m + 1) / 2)
    {
        measurements += m;
        if (m <= 2)
            break;
    }
    const double pathsPerHalf = choice.budgetSeconds * 1e3 / msPerPath / double(measurements) / 2.0;
    // At least 1024 pixels (relMSE's terms: its standard error falls with their count), the rest as samples
    // per pixel, up to half the render's: stratification (Sobol's points, the spherical samplers' warps) gains
    // with the spp, and a pilot of 2 spp cannot see it (it chose random over sobol on rect-light-closeup, where
    // sobol is 3.5x as efficient at 1 s).
    // A GPU needs more pixels than that to run at its speed (a 45 x 45 pilot on an H100 took 100x the time per
    // path of the 600 x 600 probe): at least the engine's concurrent paths.
    const double pilotPixels = std::max(1024.0, double(engine.concurrentPaths()));
    const int sppCap = std::max(1, request.settings.trueSpp() / 2);
    RenderSettings pilot = request.settings;
    pilot.spp = std::clamp(static_cast<int>(pathsPerHalf / pilotPixels), 1, sppCap);
    pilot.width = widthFor(request.settings, pathsPerHalf / pilot.spp);
    pilot.spp = std::clamp(static_cast<int>(pathsPerHalf / pixelsOf(pilot)), pilot.spp, sppCap);
    choice.width = pilot.width;
    choice.height = pilot.height();

    // A half of another strategy than the scene's that runs past 4x its share is stopped: the candidate is too
    // slow to win (it would need 4x less error per path than the probe's strategy), and the budget holds (book 3's
    // mixture over 1000 lights took 15x its share on many-lights).
    const double shareMs = pathsPerHalf * msPerPath;
    const auto timeLimit = std::chrono::nanoseconds(static_cast<std::int64_t>(std::max(4.0 * shareMs, 5.0) * 1e6));

    /// A candidate's measurements so far: the sums of its A and B halves, each measurement of the same size.
    struct Candidate
    {
        PilotRow row;
        Image sumA, sumB;
    };
    std::vector<Candidate> runs;
    for (const Strategy& strategy : grid)
        runs.push_back({PilotRow{strategy, differences(own, strategy)}, Image(), Image()});
    std::uint32_t measured = 0; // measurements made, for their seeds
    auto measureOnce = [&](Candidate& c) {
        RenderRequest half = request;
        half.settings = c.row.strategy.applyTo(pilot);
        half.settings.seed = request.settings.seed + 7919u * (2u * measured++ + 1u);
        // The scene's own strategy is the one to beat (and the probe's): never stopped, or nothing would compare
        // (a loaded machine took it past 4x its share of a 3 ms render's pilot).
        const auto limit = &c == &runs.front() ? std::chrono::nanoseconds(0) : timeLimit;
        Measurement a = measure(engine, half, nullptr, limit);
        ++half.settings.seed;
        Measurement b = a.cancelled ? Measurement{.cancelled = a.cancelled, .timedOut = a.timedOut}
                                    : measure(engine, half, nullptr, limit);
        if (b.cancelled && !b.timedOut)
            return false;
        choice.pilotMs += a.ms() + b.ms();
        if (b.timedOut)
        {
            c.row.tooSlow = true;
            c.row.ms += a.timedOut ? a.wallMs : a.ms() + b.wallMs;
            return true;
        }
        if (measured == 1 && budget.renderSeconds <= 0.0)
        {
            // The first candidate is the probe's strategy on many more paths: a better time per path (the probe's
            // small render overestimated a 1 s render 2.7x on 2 cores), hence the render's time and the budget.
            const double perPath = std::min(a.ms(), b.ms()) / (pixelsOf(half.settings) * half.settings.trueSpp());
            choice.estimatedRenderSeconds = perPath * renderPaths * 1e-3;
            choice.budgetSeconds = std::min(budget.maxSeconds, budget.fraction * choice.estimatedRenderSeconds);
        }
        choice.spp = a.spp + b.spp;
        // The halves are the same work: the faster one's time twice, so that a one-off stall of either (a pool's
        // first use, a clock ramping up: 2x on the first candidate after the probe, measured) does not decide.
        c.row.ms += 2.0 * std::min(a.ms(), b.ms());
        ++c.row.measurements;
        if (c.sumA.empty())
        {
            c.sumA = std::move(a.image);
            c.sumB = std::move(b.image);
        }
        else
            for (std::size_t k = 0; k < c.sumA.pixelCount(); ++k)
            {
                c.sumA.data()[k] += a.image.data()[k];
                c.sumB.data()[k] += b.image.data()[k];
            }
        return true;
    };
    // relMSE of each candidate's mean over its measurements (its cost: their summed time), and the winner: the
    // most efficient where its lead over the scene's own is more than twice the standard error of their ratio (the
    // relMSEs' errors; the times' are smaller): a tie, or a lead within the pilot's noise, keeps the scene's
    // strategy. With one standard error, the best of 12 candidates beat the scene's own by noise alone: on an H100
    // the pilot chose uniform light selection on cornell-box-lights, 0.85x the BVH's efficiency. (Measured one
    // setting at a time and once each, twice the error had kept book 3's mixture on rtrol-cornell-box at 0.46x;
    // the grid measures nee-mis with its cheaper samplers, 20 standard errors ahead there.)
    auto rescore = [&] {
        std::vector<PilotHalves> halves;
        std::vector<Candidate*> scored;
        for (Candidate& c : runs)
            if (c.row.measurements > 0 && !c.row.tooSlow)
            {
                Image a = c.sumA, b = c.sumB;
                for (std::size_t k = 0; k < a.pixelCount(); ++k)
                {
                    a.data()[k] /= float(c.row.measurements);
                    b.data()[k] /= float(c.row.measurements);
                }
                halves.push_back({std::move(a), std::move(b)});
                scored.push_back(&c);
            }
        const std::vector<PilotError> errors = pilotRelMse(halves);
        for (std::size_t i = 0; i < scored.size(); ++i)
        {
            PilotRow& row = scored[i]->row;
            row.relMse = errors[i].relMse;
            row.relMseError = errors[i].standardError;
            row.efficiency = row.relMse > 0.0 && row.ms > 0.0 ? 1.0 / (row.relMse * row.ms * 1e-3) : 0.0;
        }
    };
    auto winner = [&]() -> const PilotRow* {
        const PilotRow* incumbent = runs.front().row.measurements > 0 && !runs.front().row.tooSlow ? &runs.front().row
                                                                                                    : nullptr;
        const PilotRow* leader = incumbent;
        auto relative = [](const PilotRow& r) { return r.relMse > 0.0 ? r.relMseError / r.relMse : 0.0; };
        for (const Candidate& c : runs)
        {
            const PilotRow& row = c.row;
            if (row.tooSlow || row.measurements == 0)
                continue;
            if (!incumbent)
            {
                if (!leader || row.efficiency > leader->efficiency)
                    leader = &row;
                continue;
            }
            if (row.efficiency > leader->efficiency &&
                std::log(row.efficiency / incumbent->efficiency) >
                    2.0 * std::hypot(relative(row), relative(*incumbent)))
                leader = &row;
        }
        return leader;
    };

    bool finished = true;
    std::vector<std::size_t> active(runs.size());
    for (std::size_t i = 0; i < active.size(); ++i)
        active[i] = i;
    while (finished && !choice.budgetSpent)
    {
        for (const std::size_t i : active)
        {
            // The budget on the host's clock: a GPU compiles each candidate's pipeline (1.3 s each on an H100 with
            // the driver's cache cold), which no engine clock sees. What is left is not measured.
            if (measured > 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > choice.budgetSeconds)
            {
                choice.budgetSpent = true;
                break;
            }
            if (!(finished = measureOnce(runs[i])))
                break;
        }
        if (!finished || active.size() <= 2)
            break;
        rescore();
        // The better half by efficiency goes on, the scene's own with it.
        std::vector<std::size_t> next;
        for (const std::size_t i : active)
            if (!runs[i].row.tooSlow && runs[i].row.measurements > 0)
                next.push_back(i);
        std::sort(next.begin(), next.end(),
                  [&](std::size_t x, std::size_t y) { return runs[x].row.efficiency > runs[y].row.efficiency; });
        next.resize(std::min(next.size(), (active.size() + 1) / 2));
        if (std::find(next.begin(), next.end(), std::size_t(0)) == next.end() && !runs.front().row.tooSlow)
            next.push_back(0);
        active = std::move(next);
        if (active.size() <= 1)
            break;
    }
    choice.pilotWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!finished)
    {
        choice.cancelled = true;
        choice.chosen = Strategy::of(request.settings);
        return choice;
    }
    rescore();
    for (const Candidate& c : runs)
        choice.rows.push_back(c.row);
    if (const PilotRow* leader = winner())
        choice.chosen = leader->strategy;
    return choice;
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
    j["budget_spent"] = budgetSpent;
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
                                   {"too_slow", r.tooSlow}});
    return j;
}

std::string AutoChoice::table() const
{
    std::string text = fmt::format("{:<44} {:>30} {:>3} {:>9} {:>10} {:>8} {:>12}\n", "strategy", "differs from own",
                                   "n", "ms", "relMSE", "±1 s.e.", "1/(relMSE s)");
    for (const PilotRow& r : rows)
        text += fmt::format("{:<44} {:>30} {:>3} {:>9.2f} {:>10.3g} {:>8.2g} {:>12.4g}{}\n", r.strategy.name(),
                            r.differs, r.measurements, r.ms, r.relMse, r.relMseError, r.efficiency,
                            r.tooSlow                ? "  stopped: 4x its share"
                            : r.measurements == 0    ? "  not measured: the budget was spent"
                            : r.strategy == chosen   ? "  <- chosen"
                                                     : "");
    return text;
}
} // namespace rt::compare
