#include "Compare/AutoStrategy.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>

#include "Cli/ValueParsing.h"
#include "Compare/Measurement.h"
#include "Error.h"
#include "Image/Metrics.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
namespace
{
/// A setting the search varies and its candidate words (two or more).
struct SearchedSetting
{
    const Setting* setting;
    std::vector<std::string> words;
};

std::vector<std::string> candidateWords(const StrategyLists& candidates, const Setting& setting)
{
    const auto it = candidates.find(setting.compareFlag);
    if (it == candidates.end())
        return {};
    std::vector<std::string> words;
    for (const std::string& word : splitCommas(it->second))
    {
        if (!setting.accepts(word))
            throw UsageError(fmt::format("--strategy auto: {} takes {} (got '{}')", setting.compareFlag,
                                         setting.expected(), word));
        if (std::find(words.begin(), words.end(), word) == words.end())
            words.push_back(word);
    }
    return words;
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

/// A 5 x 5 box blur of an RGB image of doubles (width x height x 3, row-major), clamped at the borders.
std::vector<double> boxBlur(const std::vector<double>& image, int width, int height)
{
    constexpr int r = 2;
    auto pass = [&](const std::vector<double>& in, bool horizontal) {
        std::vector<double> out(in.size(), 0.0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c)
                {
                    double sum = 0.0;
                    int count = 0;
                    for (int d = -r; d <= r; ++d)
                    {
                        const int xx = horizontal ? x + d : x, yy = horizontal ? y : y + d;
                        if (xx < 0 || yy < 0 || xx >= width || yy >= height)
                            continue;
                        sum += in[(std::size_t(yy) * width + xx) * 3 + c];
                        ++count;
                    }
                    out[(std::size_t(y) * width + x) * 3 + c] = sum / count;
                }
        return out;
    };
    return pass(pass(image, true), false);
}
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
            lists[flag] = "nee-mis,nee,mixture,bsdf";
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
    std::vector<double> sumX(values, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < values; ++k)
        {
            const double a = candidates[i].a.data()[k / 3][int(k % 3)], b = candidates[i].b.data()[k / 3][int(k % 3)];
            x[i][k] = 0.5 * (a + b);
            v[i][k] = 0.25 * (a - b) * (a - b);
            sumX[k] += x[i][k];
        }
    // relMSE's denominator for candidate i: the others' mean, blurred. Never candidate i's own image: a firefly
    // divided by itself would make the spikiest estimator look the best (measured: bsdf chosen over nee-mis, which
    // is 2x as efficient, on cornell-box-lights at 2 spp).
    auto othersNorm = [&](std::size_t i) {
        std::vector<double> mean(values);
        for (std::size_t k = 0; k < values; ++k)
            mean[k] = n > 1 ? (sumX[k] - x[i][k]) / double(n - 1) : x[i][k];
        mean = boxBlur(mean, width, height);
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
    std::vector<std::vector<double>> norms(n);
    std::vector<PilotError> own(n);
    std::vector<double> w(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        norms[i] = othersNorm(i);
        own[i] = relative(v[i], norms[i]);
        w[i] = 1.0 / std::max(own[i].relMse, 1e-300);
    }
    if (n == 1)
        return own;
    // The others' inverse-error weighted combination r_-i, independent of x_i: E[(x_i - r_-i)^2] = Var x_i +
    // bias_i^2 + Var r_-i, the last known from the others' halves and removed.
    double W = 0.0;
    std::vector<double> sumWX(values, 0.0), sumW2V(values, 0.0);
    for (std::size_t i = 0; i < n; ++i)
    {
        W += w[i];
        for (std::size_t k = 0; k < values; ++k)
        {
            sumWX[k] += w[i] * x[i][k];
            sumW2V[k] += w[i] * w[i] * v[i][k];
        }
    }
    std::vector<PilotError> relMse(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const double rest = W - w[i];
        std::vector<double> error(values);
        for (std::size_t k = 0; k < values; ++k)
        {
            const double d = x[i][k] - (sumWX[k] - w[i] * x[i][k]) / rest;
            error[k] = d * d - (sumW2V[k] - w[i] * w[i] * v[i][k]) / (rest * rest);
        }
        // The halves' own variance is the quieter estimate (the others' noise is not in it) and right for an
        // unbiased candidate; the error against the others replaces it where it is higher by more than twice its
        // standard error: a bias.
        const PilotError against = relative(error, norms[i]);
        relMse[i] = against.relMse - own[i].relMse > 2.0 * against.standardError ? against : own[i];
    }
    return relMse;
}

AutoChoice chooseStrategy(RenderEngine& engine, const RenderRequest& request, const StrategyLists& candidates,
                          const PilotBudget& budget)
{
    const auto start = std::chrono::steady_clock::now();
    AutoChoice choice;
    RenderSettings best = request.settings;
    std::vector<SearchedSetting> searched;
    for (const Setting* s : strategySettings())
    {
        const std::vector<std::string> words = candidateWords(candidates, *s);
        if (words.empty())
            continue;
        if (std::find(words.begin(), words.end(), s->text(best)) == words.end())
            s->set(best, words.front(), s->compareFlag);
        if (words.size() > 1)
            searched.push_back({s, words});
    }
    choice.chosen = Strategy::of(best);
    std::size_t planned = 1;
    for (const SearchedSetting& s : searched)
        planned += s.words.size() - 1;
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
    // Every candidate's two halves share the budget equally; below one sample of the whole image, a smaller image.
    const double pathsPerHalf = choice.budgetSeconds * 1e3 / msPerPath / double(planned) / 2.0;
    // At least kPilotPixels pixels (relMSE's terms: its standard error falls with their count), the rest as samples
    // per pixel, up to half the render's: stratification (Sobol's points, the spherical samplers' warps) gains
    // with the spp, and a pilot of 2 spp cannot see it (it chose random over sobol on rect-light-closeup, where
    // sobol is 3.5x as efficient at 1 s).
    constexpr double kPilotPixels = 1024.0;
    const int sppCap = std::max(1, request.settings.trueSpp() / 2);
    RenderSettings pilot = request.settings;
    pilot.spp = std::clamp(static_cast<int>(pathsPerHalf / kPilotPixels), 1, sppCap);
    pilot.width = widthFor(request.settings, pathsPerHalf / pilot.spp);
    pilot.spp = std::clamp(static_cast<int>(pathsPerHalf / pixelsOf(pilot)), pilot.spp, sppCap);
    choice.width = pilot.width;
    choice.height = pilot.height();

    // A half that runs past 4x its share is stopped: the candidate is too slow to win (it would need 4x less
    // error per path than the probe's strategy), and the budget holds (book 3's mixture over 1000 lights took
    // 15x its share on many-lights).
    const double shareMs = pathsPerHalf * msPerPath;
    const auto timeLimit = std::chrono::nanoseconds(static_cast<std::int64_t>(std::max(4.0 * shareMs, 5.0) * 1e6));
    std::vector<PilotHalves> images;
    std::vector<std::size_t> imageRows; // the row of each entry of images
    auto measureCandidate = [&](const RenderSettings& strategy, const std::string& varied) {
        RenderRequest half = request;
        half.settings = Strategy::of(strategy).applyTo(pilot);
        half.settings.seed = request.settings.seed + 7919u * std::uint32_t(2 * choice.rows.size() + 1);
        Measurement a = measure(engine, half, nullptr, timeLimit);
        ++half.settings.seed;
        Measurement b = a.cancelled ? Measurement{.cancelled = a.cancelled, .timedOut = a.timedOut}
                                    : measure(engine, half, nullptr, timeLimit);
        if (b.cancelled && !b.timedOut)
            return false;
        choice.pilotMs += a.ms() + b.ms();
        if (b.timedOut)
        {
            choice.rows.push_back({Strategy::of(strategy), varied, a.timedOut ? a.wallMs : a.ms() + b.wallMs});
            choice.rows.back().tooSlow = true;
            return true;
        }
        choice.spp = a.spp + b.spp;
        // The halves are the same work: the faster one's time twice, so that a one-off stall of either (a pool's
        // first use, a clock ramping up: 2x on the first candidate after the probe, measured) does not decide.
        choice.rows.push_back({Strategy::of(strategy), varied, 2.0 * std::min(a.ms(), b.ms())});
        imageRows.push_back(choice.rows.size() - 1);
        images.push_back({std::move(a.image), std::move(b.image)});
        return true;
    };
    // The best so far stays unless a candidate's efficiency is above it by more than twice the standard error of
    // their ratio (the relMSEs' errors; the times' are smaller): a pilot's noise alone does not move the choice
    // away from the scene's strategy, and a tie keeps the first measured.
    auto rescore = [&] {
        const std::vector<PilotError> errors = pilotRelMse(images);
        for (std::size_t i = 0; i < images.size(); ++i)
        {
            PilotRow& row = choice.rows[imageRows[i]];
            row.relMse = errors[i].relMse;
            row.relMseError = errors[i].standardError;
            row.efficiency = row.relMse > 0.0 && row.ms > 0.0 ? 1.0 / (row.relMse * row.ms * 1e-3) : 0.0;
        }
        const Strategy current = Strategy::of(best);
        const PilotRow* incumbent = nullptr;
        for (const PilotRow& row : choice.rows)
            if (row.strategy == current && !row.tooSlow)
                incumbent = &row;
        const PilotRow* winner = incumbent;
        auto relative = [](const PilotRow& r) { return r.relMse > 0.0 ? r.relMseError / r.relMse : 0.0; };
        for (const PilotRow& row : choice.rows)
        {
            if (row.tooSlow)
                continue;
            if (!incumbent)
            {
                if (!winner || row.efficiency > winner->efficiency)
                    winner = &row;
                continue;
            }
            const double margin = 2.0 * std::hypot(relative(row), relative(*incumbent));
            if (row.efficiency > winner->efficiency && std::log(row.efficiency / incumbent->efficiency) > margin)
                winner = &row;
        }
        if (winner)
            best = winner->strategy.applyTo(best);
    };

    bool finished = true;
    for (const SearchedSetting& s : searched)
    {
        if (!s.setting->used(best))
            continue; // e.g. the light sampler once bsdf has won
        for (const std::string& word : s.words)
        {
            RenderSettings candidate = best;
            s.setting->set(candidate, word, s.setting->compareFlag);
            const Strategy strategy = Strategy::of(candidate);
            if (std::any_of(choice.rows.begin(), choice.rows.end(), [&](const PilotRow& r) { return r.strategy == strategy; }))
                continue;
            if (!(finished = measureCandidate(candidate, std::string(s.setting->name))))
                break;
        }
        if (!finished)
            break;
        rescore();
    }
    choice.pilotWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!finished)
    {
        choice.cancelled = true;
        choice.chosen = Strategy::of(request.settings);
        return choice;
    }
    choice.chosen = Strategy::of(best);
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
    j["relmse_epsilon"] = kRelMseEpsilon;
    j["candidates"] = nlohmann::json::array();
    for (const PilotRow& r : rows)
        j["candidates"].push_back({{"strategy", r.strategy.name()},
                                   {"varied", r.varied},
                                   {"ms", r.ms},
                                   {"relmse", r.relMse},
                                   {"relmse_standard_error", r.relMseError},
                                   {"efficiency", r.efficiency},
                                   {"too_slow", r.tooSlow}});
    return j;
}

std::string AutoChoice::table() const
{
    std::string text = fmt::format("{:<44} {:>16} {:>9} {:>10} {:>8} {:>12}\n", "strategy", "varied", "ms", "relMSE",
                                   "±1 s.e.", "1/(relMSE s)");
    for (const PilotRow& r : rows)
        text += fmt::format("{:<44} {:>16} {:>9.2f} {:>10.3g} {:>8.2g} {:>12.4g}{}\n", r.strategy.name(), r.varied,
                            r.ms, r.relMse, r.relMseError, r.efficiency,
                            r.tooSlow ? "  stopped: 4x its share" : r.strategy == chosen ? "  <- chosen" : "");
    return text;
}
} // namespace rt::compare
