// What a render is asked to do, identical for every engine; scene defaults fill what the user leaves out.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "Shared/HostDevice.h"

namespace rt
{
using shader::Estimator;
using shader::LightSampler;
using shader::LightSelection;
using shader::PixelSampling;

enum class EngineKind
{
    Single, // CPU, std::execution::seq
    Multi, // CPU, std::execution::par (TBB)
    Gpu // Vulkan ray tracing
};

/// The most samples per pixel a render takes: the GPU counts a pixel's samples in a float channel, exact up
/// to 2^24 (scene files have the same bound).
inline constexpr int kMaxSpp = 1 << 24;

struct RenderSettings
{
    int spp = 100; // samples per pixel asked for (stratified rounds down to a square: see trueSpp())
    int depth = 50; // ray segments per path at most, the camera ray included (RTIOW's max_depth): 1 sees emitters only
    int width = 600; // pixels
    float aspect = 1.0f; // width / height
    PixelSampling sampling = PixelSampling::Random;
    Estimator estimator = Estimator::NeeMis;
    LightSampler lightSampler = LightSampler::Projected; // how NEE samples a light
    LightSelection lightSelection = LightSelection::Bvh; // how NEE picks the light it samples
    bool russianRoulette = true; // paths end by Russian roulette from their third segment (Shared/RussianRoulette.h)
    bool unidirectionalLight = true; // emitters emit from their front side only
    std::uint32_t seed = 0;

    bool operator==(const RenderSettings&) const = default;

    int height() const;
    /// Strata per image axis of a pixel: floor(sqrt(spp)) for stratified sampling, else 1. Sample s of a
    /// pixel falls in stratum (s % strata, s / strata).
    int strata() const;
    /// Samples each pixel really gets: spp, or strata()^2 for stratified sampling.
    int trueSpp() const;
    /// Throws UsageError naming the first bad value (spp < 1, width < 1, depth < 1, aspect <= 0, ...).
    void validate() const;
};

const char* toString(EngineKind engine);
const char* toString(PixelSampling sampling);
const char* toString(Estimator estimator);
const char* toString(LightSampler sampler);
const char* toString(LightSelection selection);
std::optional<EngineKind> parseEngine(const std::string& text);
std::optional<PixelSampling> parsePixelSampling(const std::string& text);
std::optional<Estimator> parseEstimator(const std::string& text);
std::optional<LightSampler> parseLightSampler(const std::string& text);
std::optional<LightSelection> parseLightSelection(const std::string& text);

/// Every field, by the command line's names (spp, depth, width, aspect, sampling, estimator, light_sampler,
/// light_selection, russian_roulette, unidirectional_light, seed): the stats JSON's "settings" and the
/// reference cache's key.
nlohmann::json toJson(const RenderSettings& settings);
} // namespace rt
