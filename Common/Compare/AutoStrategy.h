// --strategy auto: the light-sampling strategy (estimator x light sampler x light selection; pixel sampling where the
// scene's is random, or where asked)
// chosen for a scene by measurement on the engine that will render it, since which one wins depends on the
// scene, the engine and the build (issue 37: the project's own tables changed their verdict as the code got
// faster).
//
// The pilot: three probe renders of the scene's strategy (each twice, the faster kept) time a render's fixed cost, a
// pixel's and a path's (RenderCost), and so estimate the render and plan the pilot's renders; the budget is a
// fraction of that estimate (5 % by default), at most a few seconds. On a CPU engine, where its renders cost little
// beside the budget, one more render of each other candidate scales the plan's time per path to the candidates',
// each weighed by its share of the search's measurements (candidatesCostScale). Every frame of the pilot runs what the render will run (the GPU's
// integrator for the render's paths: RenderEngine::setRepresentedPaths), each in one batch. Every candidate is
// prepared (a GPU's pipelines compiled) before the budget's clock starts. Then every combination of the candidates
// (strategyGrid: a setting a strategy does not use is not varied), the scene's own first, each rendered as two
// independent halves of the same small render (the pilot's size and spp are the same for every candidate, so that
// their images combine: about 1024 pixels, or the engine's concurrent paths, the rest of the budget, less each
// render's fixed cost, as spp), by
// successive halving: all once, the better half again, and so on down to two, the scene's own in every round; the
// final two are measured three times (more, while the engine's clock leaves the budget room for another repeat: a
// plan made by a slow probe), the first three with a timing frame each where the halves are too small to keep the
// engine's device busy (a GPU's: their time per path then hides part of a costlier candidate's cost; the decision
// takes the timing frames' time per path: the slope between frames of one and two times their spp, since each
// frame of a GPU's wavefront also has a cost of its own; a fourth frame where the one at twice the spp stalled).
// Not one setting at a time: the estimator compared at the scene's light sampler kept book 3's mixture on
// rtrol-cornell-box, where an estimator with NEE and a cheaper sampler is 2x as efficient.
//
// Every candidate of a round is rendered with the round's seeds (common random numbers): the strategies share a
// seed's camera rays and BSDF directions, so their fireflies, and the ratio of two candidates' errors is 5-10x
// tighter than with seeds of their own (notebook §43: with independent seeds a pilot's ratio to the own spanned a
// factor of 3-6 at one measurement on glossy-cornell). A candidate's error is the variance of its estimate from its
// measurements' halves, as relMSE; between rounds (the halving's order, the table) each measurement's denominator is
// the estimate of every other seed's measurements (weighted by their inverse errors; measuredRelMse), never one
// that holds its own seed: the candidates of a round share that seed's fireflies, and an estimate of them pulled
// every ratio toward 1 (1.06 where it was 1.25), so that the halving went by time alone. The first round's own is
// measured twice, the second time on seeds no other candidate takes, to be the first round's denominator (a firefly
// over itself, the candidate's own image, is about 1). Every candidate is unbiased (the engines' agreement tests), so its variance is
// its error: the error against the others' estimate would add their noise, and on a glossy scene's heavy tails
// (veach-mis) its correction for that noise failed and read as a bias. Its efficiency is 1 / (relMSE x seconds),
// twice the faster half's time on the engine's clock (Compare/Measurement.h) less the half's fixed and per-pixel
// cost, or on a GPU, whose halves are one frame's two seed blocks (RenderEngine::setSeedBlock: a wavefront frame's
// tail paid once; a candidate of another estimator than the own's a frame a half until its cost is known), that
// frame's time less its fixed and per-pixel cost (the render's paths' time; in the decision every measurement at the least of its final round's, or of all
// its measurements where the search stopped before that, since a stall only adds time; or by the timing frames where
// the plan has them, taken after the guard for the leader and the own where the final round did not).
// The decision pairs the final round's measurements of the scene's own and the challenger, seed by seed
// (pairedRelMse): the ratio of their errors, each normalised by the estimate of every other seed's measurements (an
// estimate from the same seeds shares their fireflies and pulled the ratio toward 1: 1.01x where it was 1.14x), its
// standard error from the pairs' differences pixel by pixel (their covariance counted). The challenger wins where
// its lead in efficiency is more than twice that standard error and 5 % (pilotSwitches), on all the pairs and on
// the pairs left without the own's worst (a firefly in one of a small pilot's renders of the own is not a
// measurement of a tail: one in the own's six renders of veach-mis once made a pilot leave it for 0.13x its
// efficiency); otherwise the scene's own stays. The final round's measurements alone decide: the earlier ones
// chose the challenger, and are lucky. The measurements are
// planned to fill the budget on the engine's clock (on a GPU the budget less the probe's frames and two calibration
// frames, at least half of it, by the line through those two frames of the own at the halves' depth, whose frames cost
// more than the probe's model says: AutoChoice::planCost; never more paths a half than the probe's plan); the search
// stops once its time on the host's clock passes twice
// the budget (each render's set-up on the host): the candidates left are not measured, and without a final
// round (or with one pair of it) the most efficient of the last round's candidates measured most often, paired with
// the own on every seed they share, by the same rule (the scene's own stays where the final round stopped its
// challenger as too slow). A budget that gives a half fewer than kMinimumPilotPaths measures nothing: the scene's own stays.
// The halves: about 1024 pixels or the engine's concurrent paths (above), and where the engine stays busy on fewer
// pixels at more spp (RenderEngine::busyPixels), the pixels their share holds at 16 spp (at most the render's half),
// never fewer than 1024 or the engine's busy pixels at 16 spp.
// A half of a candidate other than the scene's own that runs past 4x its share of the budget (or 4x the own's
// slower half in its round, where a loaded machine slowed that) is stopped: too slow to win.
//
// The choice depends on timings, so two runs may choose differently where candidates are close: the record names
// the strategy chosen, and giving its flags renders it again, bit for bit (headless, the choice is kept for the
// next render of the same settings: Compare/StrategyCache.h).
#pragma once

#include <array>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Compare/Strategy.h"
#include "Image/Image.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"
#include "Scene/Scene.h"

namespace rt::compare
{
struct PilotBudget
{
    double fraction = 0.05; // of the render's estimated time
    double maxSeconds = 2.0; // at most, whatever the render
    double renderSeconds = 0.0; // > 0: the render's time, known (--compare --equal-time), instead of the estimate
    /// > 0: the candidates' preparation (a GPU's pipelines compiled, on the host's clock) stops once it has taken this
    /// fraction of the render's estimated time, or maxSeconds if less, and the candidates left unprepared are not
    /// measured: the default --strategy auto's bound (lavapipe compiles cornell-box-lights' 13 candidates in 34 s cold,
    /// 5 s warm, for a render of 20 s; an H200 in 17 s cold). 0: every candidate prepared, outside the budget.
    double prepareFraction = 0.0;
};

/// The fewest camera paths a half of a pilot's measurement must trace (its pixels x spp), below which the pilot
/// measures nothing and keeps the scene's own strategy (AutoChoice::tooShort).
inline constexpr double kMinimumPilotPaths = 1024.0;

/// One of the probe's renders: its pixels, spp and time on the engine's clock.
struct ProbeTiming
{
    double pixels = 0.0;
    int spp = 0;
    double ms = 0.0;
};

/// A render's time on the engine's clock as fixedMs + msPerPixel x pixels + msPerPath x pixels x spp: a render's
/// launches and dispatch, its image's clearing and read-back, its paths.
struct RenderCost
{
    double fixedMs = 0.0;
    double msPerPixel = 0.0;
    double msPerPath = 0.0;

    double ms(double pixels, double spp) const;
    /// The pixels a render of `spp` spp can have in `ms` (0 where the fixed cost is more).
    double pixelsFor(double ms, double spp) const;
    /// The spp a render of `pixels` pixels can have in `ms` (0 where the other terms are more).
    double sppFor(double ms, double pixels) const;
};

/// The three terms from three probes: P pixels at s spp, P pixels at s' > s spp, fewer pixels at s spp (in that
/// order). Terms the timings' noise hides are 0 and the paths' cost is then the bound: the second render's time over
/// its paths (it plans fewer paths, never more). Throws UsageError for probes not of that form.
RenderCost fitRenderCost(const std::array<ProbeTiming, 3>& probes);

/// One candidate the pilot rendered.
struct PilotRow
{
    Strategy strategy;
    std::string differs; // the settings in which it differs from the scene's own ("estimator, light-sampler")
    int measurements = 0; // pairs of halves rendered (successive halving measures the better candidates again)
    /// Every measurement's: twice its faster half's, on the engine's clock (Measurement::ms), less the half's
    /// overhead (AutoChoice::overheadMs): its paths' time, what the render's time grows with.
    double ms = 0.0;
    /// The relMSE of its mean over its measurements (see above).
    double relMse = 0.0;
    double relMseError = 0.0; // relMse's standard error (over the pixels' terms)
    double efficiency = 0.0; // 1 / (relMse x seconds)
    bool tooSlow = false; // a half ran past 4x its share of the budget and was stopped: efficiency 0
    /// The decision's two (the scene's own and the challenger): the same figures from the pairs that decide
    /// (pairedRelMse; relMSE as that of their mean): the final round's, or where the search stopped before it
    /// decided, every seed the own and the last round's leader share.
    int finalMeasurements = 0;
    double finalRelMse = 0.0;
    double finalRelMseError = 0.0;
    double finalEfficiency = 0.0;
    /// The challenger: its final relMSE over the own's, paired seed by seed, and the ratio's standard error; the same
    /// without the pair where the own's error was largest (with two pairs, the one left's error from its pixels).
    double relMseRatio = 0.0;
    double relMseRatioError = 0.0;
    double trimmedRelMseRatio = 0.0;
    double trimmedRelMseRatioError = 0.0;
    /// The final round's two (or, where the guard stopped the search before it decided, the leader and the own,
    /// timed then) where the plan has timing frames (AutoChoice::timingSpp and twice it): a path's time on the
    /// engine's clock, the slope between the least times at the two spp, which the decision's final efficiencies
    /// take instead of the halves' times (with one frame, a search the guard stopped: its time less the probe's fixed
    /// and per-pixel terms, a path's; never what decides).
    double timingMsPerPath = 0.0;
    /// Its timing frames rendered: three for a finalist (four where the second stalled), fewer where the search was
    /// cancelled, 0 for a candidate the final round (or the guard's fallback) did not time.
    int timingFrames = 0;
};

/// What the pilot measured and chose: --stats' "strategy_choice", the log's table, --compare's auto row.
struct AutoChoice
{
    Strategy chosen;
    int width = 0; // the pilot's image
    int height = 0;
    int spp = 0; // per candidate, both halves together
    double estimatedRenderSeconds = 0.0; // from the probe
    std::vector<ProbeTiming> probes; // the probe's renders, and the time model fitted to them
    std::string frameConfiguration; // what the probe's frames ran (RenderEngine::frameConfiguration)
    RenderCost cost;
    double overheadMs = 0.0; // a frame's fixed and per-pixel cost by the time model, taken off the candidates' times
    /// A measurement's two halves are one frame's two seed blocks (a GPU's; RenderEngine::setSeedBlock), not a frame
    /// each: its time is the frame's, less one overhead.
    bool halvesInOneFrame = false;
    double hostExtraMs = 0.0; // a probe's render on the host's clock less the engine's (the least of the probe's)
    double probeMs = 0.0; // the probe's renders (each twice) and the candidates' cost probes, on the engine's clock
    /// The candidates' time per path over the own's, by a render of each at the probe's second size, weighed by
    /// their shares of the search's measurements: the plan's scale (1 on a GPU, or where those renders would cost
    /// too much beside the budget).
    double candidatesCostScale = 1.0;
    /// On a GPU (halvesInOneFrame): the own's two calibration frames at the first plan's depth, on the engine's clock
    /// (0 where there were none).
    double calibrationMs = 0.0;
    /// The time model the halves were planned by: the probe's (`cost`) with candidatesCostScale, or on a GPU the line
    /// through the calibration frames (or the probe's scaled by the larger frame, where they give none).
    RenderCost planCost;
    int timingWidth = 0; // the timing frames (the final round's, or the guard's fallback's), where planned (0: none);
                         // their height is the image's
    int timingSpp = 0; // the first and third; the second (and a stalled second's fourth) twice it
    double budgetSeconds = 0.0;
    /// The probe's, the calibration frames' and every candidate's render time, on the engine's clock.
    double pilotMs = 0.0;
    double pilotWallSeconds = 0.0; // the whole pilot on the host's clock (GPU pipelines compiled included)
    double prepareSeconds = 0.0; // of which: every candidate prepared (a GPU's pipelines compiled), on the host's clock
    double probeSeconds = 0.0; // of which: the set-up, the probe and the calibration frames, on the host's clock
    double searchSeconds = 0.0; // of which: the search (every candidate's measurements and their scoring)
    double scoringSeconds = 0.0; // of the search: the candidates' relMSE between its rounds, on the host's clock
    /// Of the search, on the host's clock: its renders (Compare/Measurement.h's measure calls), of which their
    /// tracing (the rest: each frame's set-up and read-back; the rest of the search is the pilot's own arithmetic).
    double renderHostSeconds = 0.0;
    double tracingHostSeconds = 0.0;
    /// The engine's stages of the search's renders (RenderEngine::frameStageSeconds), summed: where a GPU's host
    /// time beside its clock went (setup_host, trace_host beside trace_gpu, readback_host, resolve_host).
    std::map<std::string, double> searchStageSeconds;
    /// Of prepareSeconds: the engine's compileAhead calls (the rest: each candidate's frame begun, a warm-up launch).
    double prepareCompileSeconds = 0.0;
    std::vector<PilotRow> rows; // in the order measured
    bool cancelled = false; // Ctrl-C stopped the pilot
    /// The search stopped when the pilot's wall time passed the budget, before every candidate was measured.
    bool budgetSpent = false;
    /// The budget gave a candidate's half fewer than kMinimumPilotPaths: nothing was measured, the scene's own kept.
    bool tooShort = false;
    /// Candidates not measured because their preparation would have passed PilotBudget::prepareFraction's bound (all
    /// but the own: the own kept, nothing measured).
    int unprepared = 0;
    /// The preparation's bound on the host's clock (PilotBudget::prepareFraction), seconds; infinity: none.
    double prepareBoundSeconds = std::numeric_limits<double>::infinity();

    nlohmann::json toJson() const;
    /// The table of rows, one per line, the chosen one marked: what the headless run logs.
    std::string table() const;
};

/// The values auto may choose among, by --compare's list flag ("--estimators" -> "nee-mis,nee"): `given` where it
/// names a list, else the defaults for the scene, of which a setting given on the command line (`fixed`, by
/// setting name: "estimator") keeps only its value. The defaults: the estimators that combine strategies, nee-mis
/// and book 3's mixture (a single strategy, nee or bsdf, can be unboundedly worse where its rare paths carry the
/// light, which a pilot does not sample: on veach-mis a pilot chose nee, 0.05x nee-mis's efficiency; they are
/// candidates when a list names them), the mixture only where the scene has no microfacet material (there it is
/// BSDF sampling alone: a pilot chose it on veach-mis, 0.002x nee-mis's efficiency); area, solid-angle and projected
/// light sampling, and projected-exact where the scene has quad or triangle lights (on spheres it is projected),
/// none but the request's when it has no emitter; every light selection where the scene has two emitters or more.
/// Where the scene's pixel sampling is random (the books' scenes, a scene file's), Sobol is a candidate too: its gain
/// over random grows with the spp, which a pilot of few spp per pixel sees only in part (at 2 spp a pilot chose random
/// over Sobol on rect-light-closeup, where Sobol is 3.5x as efficient), and the random samples are the scene's own,
/// kept where the pilot sees no lead. Otherwise the pixel sampling, and always Russian roulette, stay the request's
/// (a list given varies them).
StrategyLists autoCandidates(const Scene& scene, const StrategyLists& given, const std::vector<std::string>& fixed);

/// The candidates a pilot of `settings` measures: `lists` (autoCandidates') without the estimators' list where
/// the settings' estimator is not in it (a single strategy, bsdf or nee, stays as asked: the pilot's estimators
/// combine strategies), and without the samplings' where its pixel sampling is not (a window's stratified samples
/// or accumulation stay); nothing for restir-di, whose pixels are correlated (reservoirs reused across pixels and
/// iterations), which one seed's error, all a pilot's measurement has, does not score (--compare takes the mean of
/// several seeds for it). Every pilot of the apps (headless, the windows') takes it.
std::optional<StrategyLists> pilotCandidates(const StrategyLists& lists, const RenderSettings& settings);
/// What the apps say where pilotCandidates gives nothing.
inline constexpr const char* kNoPilotForRestirDi =
    "restir-di's pixels are correlated, which a pilot's error of one seed does not score: no pilot";

/// Runs the pilot for `request` (whose strategy settings start the search) on `engine`, whose scene is set to
/// `scene`, over `candidates` (autoCandidates' form; a setting without a list keeps the request's value).
/// Cancellable by Ctrl-C while an InterruptScope lives (Cli/Interrupt.h): then `cancelled` is set and `chosen` is
/// the request's. Throws UsageError for a bad candidate word, what the engine throws.
AutoChoice chooseStrategy(RenderEngine& engine, const RenderRequest& request, const StrategyLists& candidates,
                          const PilotBudget& budget = {});

/// A pilot candidate's two independent halves (the same size).
struct PilotHalves
{
    Image a;
    Image b;
};

/// A candidate's measurements of the same size summed as they come: their halves' values (in double: a firefly's
/// spans float's range, and so do its sums), from which the search's denominators are made (an estimate without one
/// seed's measurement: the sums less its halves).
class PilotSums
{
public:
    /// One measurement: its halves (the same size as every earlier one's; throws UsageError otherwise).
    void add(const Image& a, const Image& b);
    /// Per value (Image's order), the sum of every measurement's two halves: 2 x count renders.
    const std::vector<double>& sums() const { return halfSums; }

    int count = 0; // measurements

private:
    std::vector<double> halfSums;
    int width = 0;
    int height = 0;
};

struct PilotError
{
    double relMse = 0.0;
    double standardError = 0.0; // of relMse (measuredRelMse)
};

/// One measurement of a candidate, as the search scores it between rounds: its halves and its relMSE's denominator,
/// an estimate from other seeds than the measurement's (per value, Image's order, the halves' size). Not an estimate
/// that holds the measurement's seed: with common seeds every candidate of a round shares that seed's camera rays
/// and BSDF directions, hence its fireflies, and normalised by an estimate of them the candidates' errors all come
/// out alike (CPU, cornell-box-lights at 32 x 32 px and 14 spp, 20 seeds: solid-angle uniform's error over the own's
/// 1.06 against the same seed's estimate, 1.25 against the reference; 1.20 against one measurement of the own on
/// another seed, 1.25 against four).
struct PilotMeasurement
{
    const PilotHalves* halves = nullptr;
    const std::vector<float>* denominator = nullptr;
};

/// A candidate's error from its k >= 1 measurements: per measurement m and pixel p, t = the sum over the channels of
/// (a - b)^2 / 4 / (denominator^2 + epsilon), the variance of the halves' mean over the denominator; relMSE = sum t /
/// (k^2 values), that of the mean of the k measurements. Its standard error with the pixels independent: each pixel's
/// sum over m has the variance k / (k - 1) times the spread of its t's over m; with one measurement, the pixels'
/// spread (which also holds how much the pixels' own variances differ). Every halves' image and denominator the same
/// size, no pointer null, at least one measurement; throws UsageError otherwise.
PilotError measuredRelMse(std::span<const PilotMeasurement> measurements);

/// One seed's measurement of the final round's two candidates: each one's halves, and the denominator of their
/// relMSE (an estimate from other seeds: per value, Image's order, the halves' size).
struct PilotPair
{
    const PilotHalves* own = nullptr;
    const PilotHalves* challenger = nullptr;
    const std::vector<float>* denominator = nullptr;
};

/// The paired comparison of the final round. Per pair m and pixel p, x = sum over the channels of (a - b)^2 / 4 /
/// (denominator^2 + epsilon), the variance of the halves' mean over the denominator (y the challenger's): the relMSEs
/// are the x's and y's sums over (pairs^2 x values), as the relMSE of the mean of the pairs; the ratio R = sum y /
/// sum x. Its variance by the delta method, pixels and seeds independent (a pair's two renders are not: they share
/// the seed): the sum over pixels of k / (k - 1) times the spread over the k pairs of y - R x, over (sum x)^2; with
/// one pair, the spread of y - R x over the pixels (which also holds how much the pixels' own ratios differ: the
/// larger). Every halves' image and denominator the same size, no pointer null, at least one pair; throws UsageError
/// otherwise.
struct PairedRelMse
{
    double own = 0.0;
    double ownError = 0.0;
    double challenger = 0.0;
    double challengerError = 0.0;
    double ratio = 0.0; // challenger / own
    double ratioError = 0.0;
    std::vector<double> ownPerPair; // each pair's x summed over the pixels (the own's worst pair: the largest)
};
PairedRelMse pairedRelMse(std::span<const PilotPair> pairs);

/// Whether the pilot leaves the scene's own strategy for a challenger whose efficiency is `lead` times the own's:
/// where log(lead) is more than twice its standard error `logLeadError` and the lead more than 5 % (the times'
/// noise, which that error leaves out). Within that, a tie or noise, the scene's own stays: with one standard error,
/// and the challenger's lucky measurements counted, the best of 12 candidates beat the scene's own by noise alone
/// (uniform light selection on an H100's cornell-box-lights, 0.85x the BVH's efficiency); with its measurements
/// fresh, a heavy tail they did not meet (area sampling on veach-mis, 0.2x the own's efficiency).
bool pilotSwitches(double lead, double logLeadError);
} // namespace rt::compare
