// --strategy auto's measurement (Compare/AutoStrategy.h) on synthetic pilot images whose error is known in closed
// form, and the candidates it draws for a scene.
//
// measuredRelMse and pairedRelMse: each candidate's halves are a constant image R plus independent noise per pixel
// channel; the mean of two halves has variance sigma^2 / 2. relMSE normalises by R^2 + 0.01. 20000 pixel channels per image:
// the estimates' standard error is a few percent, the tolerances 5-6 of them (stated per test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "Compare/AutoStrategy.h"
#include "Error.h"
#include "Image/Metrics.h"
#include "Scenes/Catalogue.h"

namespace rt::compare
{
namespace
{
constexpr int kSide = 82; // 82 x 82 x 3 = 20172 values
constexpr float kRadiance = 0.5f;

using Noise = std::function<float(std::mt19937&)>;

Image noisyImage(std::mt19937& rng, const Noise& noise)
{
    Image image(kSide, kSide);
    for (vec3& p : image.pixels())
        for (int c = 0; c < 3; ++c)
            p[c] = noise(rng);
    return image;
}

PilotHalves halves(std::mt19937& rng, const Noise& noise) { return {noisyImage(rng, noise), noisyImage(rng, noise)}; }

Noise gaussian(float sigma)
{
    return [=](std::mt19937& rng) { return kRadiance + sigma * std::normal_distribution<float>()(rng); };
}

double relMseOf(double varianceOfMean)
{
    return varianceOfMean / (double(kRadiance) * kRadiance + kRelMseEpsilon);
}

/// A final round of `pairs` pairs: the own's noise sigma 0.1, the challenger's `ratio` times its variance, their
/// samples correlated by `correlation` (the same seed), every pair's denominator the true radiance.
PairedRelMse pairedTrial(std::mt19937& rng, std::size_t pairs, double ratio, double correlation,
                         const std::vector<float>& denominator)
{
    std::vector<PilotHalves> own, challenger;
    std::normal_distribution<double> normal;
    const double sigma = 0.1, scale = std::sqrt(ratio), rest = std::sqrt(1.0 - correlation * correlation);
    for (std::size_t m = 0; m < pairs; ++m)
    {
        PilotHalves o{Image(kSide, kSide), Image(kSide, kSide)}, c{Image(kSide, kSide), Image(kSide, kSide)};
        for (Image* half : {&o.a, &o.b})
        {
            Image& other = half == &o.a ? c.a : c.b;
            for (std::size_t p = 0; p < half->pixelCount(); ++p)
                for (int k = 0; k < 3; ++k)
                {
                    const double shared = normal(rng);
                    half->data()[p][k] = float(kRadiance + sigma * shared);
                    other.data()[p][k] = float(kRadiance + sigma * scale * (correlation * shared + rest * normal(rng)));
                }
        }
        own.push_back(std::move(o));
        challenger.push_back(std::move(c));
    }
    std::vector<PilotPair> list;
    for (std::size_t m = 0; m < pairs; ++m)
        list.push_back({&own[m], &challenger[m], &denominator});
    return pairedRelMse(list);
}

TEST(PairedRelMse, TheRatioAndItsStandardErrorHoldForCorrelatedPairs)
{
    // The own's variance sigma^2 = 0.01 a sample, the challenger's 0.8x, their samples correlated by 0.9: the
    // ratio's standard error must be what 200 trials' ratios spread by (within 25 %), each trial's ratio within two
    // of its standard errors of 0.8 in 90-99 % of trials (Gaussian: 95 %), and the own's relMSE of the mean of three
    // pairs sigma^2 / 2 / 3 / (R^2 + epsilon) within 5 % on average.
    std::mt19937 rng(43);
    const std::vector<float> denominator(std::size_t(kSide) * kSide * 3, kRadiance);
    constexpr int kTrials = 200;
    int within = 0;
    double sum = 0.0, sumSquares = 0.0, errors = 0.0, own = 0.0;
    for (int t = 0; t < kTrials; ++t)
    {
        const PairedRelMse r = pairedTrial(rng, 3, 0.8, 0.9, denominator);
        within += std::abs(r.ratio - 0.8) < 2.0 * r.ratioError;
        sum += r.ratio;
        sumSquares += r.ratio * r.ratio;
        errors += r.ratioError;
        own += r.own;
        ASSERT_EQ(r.ownPerPair.size(), 3u);
    }
    const double mean = sum / kTrials, spread = std::sqrt((sumSquares - sum * mean) / (kTrials - 1));
    EXPECT_NEAR(mean, 0.8, 0.01);
    EXPECT_NEAR(errors / kTrials / spread, 1.0, 0.25) << "standard error " << errors / kTrials << ", spread " << spread;
    EXPECT_GE(within, 180);
    EXPECT_LE(within, 198);
    EXPECT_NEAR(own / kTrials / relMseOf(0.01 / 2.0 / 3.0), 1.0, 0.05);
}

TEST(PairedRelMse, CorrelationNarrowsTheRatio)
{
    // The same challenger uncorrelated with the own: the ratio's standard error is larger by far (for variances 1
    // and 0.8 and rho 0.9, sqrt(1.28 / 0.243): about 2.3x).
    std::mt19937 rng(44);
    const std::vector<float> denominator(std::size_t(kSide) * kSide * 3, kRadiance);
    const double paired = pairedTrial(rng, 3, 0.8, 0.9, denominator).ratioError;
    const double independent = pairedTrial(rng, 3, 0.8, 0.0, denominator).ratioError;
    EXPECT_GT(independent, 2.0 * paired) << paired << " " << independent;
}

TEST(PairedRelMse, OnePairTakesItsStandardErrorFromThePixels)
{
    // A final round cut short after one pair: the ratio's error from its pixels' spread, which where every pixel is
    // alike is the trials' spread again (within 25 %, 200 trials).
    std::mt19937 rng(45);
    const std::vector<float> denominator(std::size_t(kSide) * kSide * 3, kRadiance);
    constexpr int kTrials = 200;
    double sum = 0.0, sumSquares = 0.0, errors = 0.0;
    for (int t = 0; t < kTrials; ++t)
    {
        const PairedRelMse r = pairedTrial(rng, 1, 0.8, 0.9, denominator);
        sum += r.ratio;
        sumSquares += r.ratio * r.ratio;
        errors += r.ratioError;
    }
    const double mean = sum / kTrials, spread = std::sqrt((sumSquares - sum * mean) / (kTrials - 1));
    EXPECT_NEAR(mean, 0.8, 0.02);
    EXPECT_NEAR(errors / kTrials / spread, 1.0, 0.25) << "standard error " << errors / kTrials << ", spread " << spread;
}

TEST(MeasuredRelMse, IsTheVarianceOfTheMeasurementsMeanOverTheDenominator)
{
    // k measurements of Gaussian noise sigma around R, each normalised by the exact R: the halves' mean has variance
    // sigma^2 / 2, the mean of k measurements sigma^2 / (2k). The standard error: (a - b)^2 / 4 has twice its mean's
    // square as variance, over 3 x 82 x 82 values and k measurements: sqrt(2 / (20172 k)) of the relMSE, right within
    // a factor 2; the estimate within 5 of them.
    std::mt19937 rng(21);
    constexpr float kSigma = 0.1f;
    const std::vector<float> exact(std::size_t(kSide) * kSide * 3, kRadiance);
    for (const int k : {1, 3})
    {
        std::vector<PilotHalves> halvesOf;
        for (int m = 0; m < k; ++m)
            halvesOf.push_back(halves(rng, gaussian(kSigma)));
        std::vector<PilotMeasurement> measurements;
        for (const PilotHalves& h : halvesOf)
            measurements.push_back({&h, &exact});
        const PilotError e = measuredRelMse(measurements);
        const double expected = relMseOf(0.5 * kSigma * kSigma / k);
        const double relative = std::sqrt(2.0 / (20172.0 * k));
        EXPECT_NEAR(e.relMse, expected, 5.0 * relative * expected) << k << " measurements";
        EXPECT_GT(e.standardError, 0.5 * relative * expected) << k << " measurements";
        EXPECT_LT(e.standardError, 2.0 * relative * expected) << k << " measurements";
    }
}

TEST(MeasuredRelMse, EachMeasurementHasItsOwnDenominator)
{
    // Two measurements of the same noise, one normalised by R, the other by 2R: each term by its own, so the relMSE
    // is the mean of the two (over k^2 = 4), not either's twice. The second's denominator taken for both would give
    // 1 / (4 R^2 + 0.01) twice.
    std::mt19937 rng(22);
    constexpr float kSigma = 0.1f;
    const std::vector<float> once(std::size_t(kSide) * kSide * 3, kRadiance), twice(once.size(), 2.0f * kRadiance);
    const PilotHalves first = halves(rng, gaussian(kSigma)), second = halves(rng, gaussian(kSigma));
    const std::vector<PilotMeasurement> measurements{{&first, &once}, {&second, &twice}};
    const PilotError e = measuredRelMse(measurements);
    const double variance = 0.5 * kSigma * kSigma;
    const double expected = 0.25 * (variance / (double(kRadiance) * kRadiance + kRelMseEpsilon) +
                                    variance / (4.0 * kRadiance * kRadiance + kRelMseEpsilon));
    EXPECT_NEAR(e.relMse, expected, 0.05 * expected);
}

TEST(MeasuredRelMse, AFireflyBeyondFloatsRangeStaysFiniteAndBadInputIsRefused)
{
    std::mt19937 rng(23);
    const std::vector<float> exact(std::size_t(kSide) * kSide * 3, kRadiance);
    PilotHalves spiky = halves(rng, gaussian(0.05f));
    spiky.a.data()[100].y = 1e20f;
    const PilotMeasurement one{&spiky, &exact};
    const PilotError e = measuredRelMse({&one, 1});
    ASSERT_TRUE(std::isfinite(e.relMse) && std::isfinite(e.standardError));
    // Its one term: (1e20 / 2)^2 over R^2 + 0.01, over the values.
    EXPECT_NEAR(e.relMse, relMseOf(0.25e40) / 20172.0, 0.01 * relMseOf(0.25e40) / 20172.0);

    EXPECT_THROW(measuredRelMse({}), UsageError);
    const std::vector<float> small(12, kRadiance);
    const PilotMeasurement wrongDenominator{&spiky, &small};
    EXPECT_THROW(measuredRelMse({&wrongDenominator, 1}), UsageError);
    const PilotMeasurement missing{nullptr, &exact};
    EXPECT_THROW(measuredRelMse({&missing, 1}), UsageError);
    const PilotHalves other{Image(4, 4), Image(4, 4)};
    const std::vector<PilotMeasurement> mismatched{{&spiky, &exact}, {&other, &exact}};
    EXPECT_THROW(measuredRelMse(mismatched), UsageError);
}

TEST(PairedRelMse, BadInputIsRefused)
{
    const std::vector<float> denominator(std::size_t(kSide) * kSide * 3, kRadiance);
    EXPECT_THROW(pairedRelMse({}), UsageError);
    const std::vector<float> small(12, kRadiance);
    const PilotHalves h{Image(kSide, kSide), Image(kSide, kSide)};
    const PilotPair wrong{&h, &h, &small};
    EXPECT_THROW(pairedRelMse({&wrong, 1}), UsageError);
    const PilotPair missing{&h, nullptr, &denominator};
    EXPECT_THROW(pairedRelMse({&missing, 1}), UsageError);
}

TEST(PilotSums, SumTheHalvesOfEveryMeasurement)
{
    // Two measurements, one half with a sample of 3e38 (float's largest is 3.4e38: two such would overflow a float
    // sum, not the double one). The sums are each value's four halves.
    std::mt19937 rng(16);
    PilotHalves first = halves(rng, gaussian(0.1f));
    PilotHalves second = halves(rng, gaussian(0.1f));
    first.a.data()[100].y = 3e38f;
    second.b.data()[100].y = 3e38f;
    PilotSums sums;
    sums.add(first.a, first.b);
    sums.add(second.a, second.b);
    ASSERT_EQ(sums.count, 2);
    ASSERT_EQ(sums.sums().size(), std::size_t(kSide) * kSide * 3);
    auto four = [&](std::size_t k) {
        const int p = int(k / 3), c = int(k % 3);
        return double(first.a.data()[p][c]) + double(first.b.data()[p][c]) + double(second.a.data()[p][c]) +
               double(second.b.data()[p][c]);
    };
    for (std::size_t k = 0; k < sums.sums().size(); k += 97)
        EXPECT_DOUBLE_EQ(sums.sums()[k], four(k));
    EXPECT_DOUBLE_EQ(sums.sums()[3 * 100 + 1], four(3 * 100 + 1));
    EXPECT_GT(sums.sums()[3 * 100 + 1], 6e38) << "beyond float's range";
    EXPECT_THROW(sums.add(Image(4, 4), Image(4, 4)), UsageError);
    EXPECT_THROW(PilotSums().add(Image(4, 4), Image(5, 4)), UsageError);
}

TEST(MeasuredRelMse, TheStandardErrorIsTheSpreadOfRepeatedPilotsWherePixelsDiffer)
{
    // A field whose pixels' noise differs 30-fold (a light's edge beside a dark wall), each pixel's noise the same in
    // its three channels (a path adds to all three): the spread of the pixels' terms holds the differences between
    // pixels too, which repeated pilots over the same pixels do not show (here 1.4x the spread), and channels taken
    // as independent would put the error at 1 / sqrt 3 of it. The standard error from each pixel's own spread over
    // the measurements against the relMSE's spread over 40 independent pilots of 3 measurements each (every one
    // normalised by the exact radiance): within 30 % (the spread of 40 draws is itself known to about 11 %).
    std::mt19937 rng(18);
    // One pixel in 16 with 30x the others' noise.
    auto image = [&] {
        Image i(kSide, kSide);
        std::size_t index = 0;
        for (vec3& p : i.pixels())
        {
            const float sigma = index++ % 16 == 0 ? 0.3f : 0.01f;
            p = vec3(kRadiance + sigma * std::normal_distribution<float>()(rng));
        }
        return i;
    };
    const std::vector<float> exact(std::size_t(kSide) * kSide * 3, kRadiance);
    constexpr int kPilots = 40;
    std::vector<double> relMses;
    double meanStandardError = 0.0;
    for (int pilot = 0; pilot < kPilots; ++pilot)
    {
        std::vector<PilotHalves> measured;
        for (int m = 0; m < 3; ++m)
            measured.push_back({image(), image()});
        std::vector<PilotMeasurement> list;
        for (const PilotHalves& h : measured)
            list.push_back({&h, &exact});
        const PilotError error = measuredRelMse(list);
        relMses.push_back(error.relMse);
        meanStandardError += error.standardError / kPilots;
    }
    double mean = 0.0, squares = 0.0;
    for (const double r : relMses)
        mean += r / kPilots;
    for (const double r : relMses)
        squares += (r - mean) * (r - mean);
    const double spread = std::sqrt(squares / (kPilots - 1));
    EXPECT_GT(meanStandardError, 0.7 * spread);
    EXPECT_LT(meanStandardError, 1.3 * spread);
}

TEST(AutoCandidates, FollowTheScenesLights)
{
    const Scene spheres = makeScene("sphere-light-closeup");
    const StrategyLists s = autoCandidates(spheres, {}, {});
    EXPECT_EQ(s.at("--estimators"), "nee-mis,mixture") << "single strategies can hide their fireflies from a pilot";
    EXPECT_EQ(s.at("--light-samplers"), "projected,solid-angle,area") << "projected-exact is projected on spheres";
    EXPECT_EQ(s.count("--light-selections"), spheres.emitterCount() > 1 ? 1u : 0u);
    ASSERT_NE(spheres.defaults.sampling, PixelSampling::Random);
    EXPECT_EQ(s.count("--samplings"), 0u) << "a scene's own sampling other than random stays";
    EXPECT_EQ(s.count("--roulettes"), 0u);

    const Scene quads = makeScene("cornell-box-lights");
    ASSERT_GT(quads.emitterCount(), 1u);
    const StrategyLists q = autoCandidates(quads, {}, {});
    EXPECT_NE(q.at("--light-samplers").find("projected-exact"), std::string::npos);
    EXPECT_EQ(q.at("--light-selections"), "bvh,power,uniform");

    const Scene glossy = makeScene("veach-mis");
    ASSERT_TRUE(glossy.hasMicrofacetMaterial());
    EXPECT_EQ(autoCandidates(glossy, {}, {}).at("--estimators"), "nee-mis")
        << "the mixture is BSDF sampling alone at a microfacet vertex";
}

TEST(AutoCandidates, ABookScenesRandomSamplesHaveSobolBesideThem)
{
    // rtrol-cornell-box (book 3's scene, random samples): with Sobol given, auto's choice was 1.4x as efficient on 2
    // cores at 64 spp (notebook §53).
    const Scene book = makeScene("rtrol-cornell-box");
    ASSERT_EQ(book.defaults.sampling, PixelSampling::Random);
    EXPECT_EQ(autoCandidates(book, {}, {}).at("--samplings"), "random,sobol");
    EXPECT_EQ(autoCandidates(book, {}, {"sampling"}).count("--samplings"), 0u) << "--sampling given";
    RenderSettings base;
    base.sampling = PixelSampling::Random;
    const std::vector<Strategy> grid = strategyGrid(autoCandidates(book, {}, {}), base);
    EXPECT_EQ(std::count_if(grid.begin(), grid.end(),
                            [](const Strategy& g) { return g.settings.sampling == PixelSampling::Sobol; }),
              std::ptrdiff_t(grid.size() / 2))
        << "every other candidate with Sobol samples";
    // A window's stratified samples are not in the list: they stay, not measured as random and replaced.
    RenderSettings window = base;
    window.sampling = PixelSampling::Stratified;
    const std::optional<StrategyLists> kept = pilotCandidates(autoCandidates(book, {}, {}), window);
    ASSERT_TRUE(kept.has_value());
    EXPECT_EQ(kept->count("--samplings"), 0u);
    EXPECT_EQ(kept->count("--light-samplers"), 1u);
    // The GPU window's accumulation, its passes' random samples, stands for random: Sobol beside it, the window's
    // own first.
    window.sampling = PixelSampling::Accumulate;
    const std::optional<StrategyLists> accumulated = pilotCandidates(autoCandidates(book, {}, {}), window);
    ASSERT_TRUE(accumulated.has_value());
    EXPECT_EQ(accumulated->at("--samplings"), "accumulate,sobol");
    EXPECT_EQ(strategyGrid(*accumulated, window).front().settings.sampling, PixelSampling::Accumulate);
    EXPECT_EQ(pilotCandidates(autoCandidates(book, {}, {}), base)->at("--samplings"), "random,sobol");
}

TEST(AutoCandidates, FlagsFixAndListsReplace)
{
    const Scene scene = makeScene("cornell-box-lights");
    const StrategyLists s = autoCandidates(scene, {{"--samplings", "random,stratified"}}, {"estimator", "light-sampler"});
    EXPECT_EQ(s.count("--estimators"), 0u);
    EXPECT_EQ(s.count("--light-samplers"), 0u);
    EXPECT_EQ(s.at("--samplings"), "random,stratified");
    EXPECT_EQ(s.at("--light-selections"), "bvh,power,uniform");
}

TEST(AutoCandidates, APilotKeepsAnEstimatorItDoesNotChooseAmongAndLeavesRestirDiAlone)
{
    const Scene scene = makeScene("cornell-box-lights");
    const StrategyLists lists = autoCandidates(scene, {}, {});
    RenderSettings settings;
    settings.estimator = Estimator::NeeMis;
    const std::optional<StrategyLists> combining = pilotCandidates(lists, settings);
    ASSERT_TRUE(combining);
    EXPECT_EQ(combining->at("--estimators"), "nee-mis,mixture");
    for (const Estimator single : {Estimator::Nee, Estimator::BsdfOnly})
    {
        settings.estimator = single;
        const std::optional<StrategyLists> kept = pilotCandidates(lists, settings);
        ASSERT_TRUE(kept);
        EXPECT_EQ(kept->count("--estimators"), 0u) << "the estimator asked stays";
        EXPECT_EQ(kept->at("--light-selections"), "bvh,power,uniform") << "the rest is still chosen";
    }
    settings.estimator = Estimator::RestirDi;
    EXPECT_FALSE(pilotCandidates(lists, settings)) << "correlated pixels: no pilot";
}
} // namespace
} // namespace rt::compare
