// What a render is asked to do, identical for every engine; scene defaults fill what the user leaves out.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "Render/NamedEnum.h"
#include "Shared/HostDevice.h"

namespace rt
{
using shader::Estimator;
using shader::LightSampler;
using shader::LightSelection;
using shader::PixelSampling;
using shader::RussianRoulette;

enum class EngineKind
{
    Single, // CPU, std::execution::seq
    Multi, // CPU, std::execution::par (TBB)
    Gpu // Vulkan ray tracing
};

/// The most samples per pixel a render takes: the GPU counts a pixel's samples in a float channel, exact up
/// to 2^24 (scene files have the same bound).
inline constexpr int kMaxSpp = 1 << 24;
/// The widest and tallest image a render makes, in pixels.
inline constexpr int kMaxImageSide = 1 << 16;

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
    int restirCandidates = 32; // restir-di: candidates per pixel and iteration (Bitterli et al. 2020's M)
    int restirSpatial = 5; // restir-di: neighbours of spatial reuse per pixel and iteration
    int restirRadius = 30; // restir-di: the disk spatial reuse draws them in, in pixels (Bitterli et al. 2020, §6)
    bool restirBiased = false; // restir-di: the biased combination (Alg. 4) instead of the unbiased one
    int restirTemporalCap = 20; // restir-di: temporal reuse's M cap, in multiples of restirCandidates (0: no reuse)
    // How paths end by Russian roulette from their third segment (Shared/RussianRoulette.h): Cycles' rule, 1.13x
    // pbrt-v4's efficiency over the catalogue on both engines (docs/notebook/PERFORMANCE.md §28)
    RussianRoulette russianRoulette = RussianRoulette::Sqrt;
    bool unidirectionalLight = true; // emitters emit from their front side only
    std::uint32_t seed = 0;

    bool operator==(const RenderSettings&) const = default;

    int height() const;
    /// Strata per image axis of a pixel: floor(sqrt(spp)) for stratified sampling, else 1. Sample s of a
    /// pixel falls in stratum (s % strata, s / strata).
    int strata() const;
    /// Samples each pixel really gets: spp, or strata()^2 for stratified sampling.
    int trueSpp() const;
    /// Throws UsageError naming the first value outside its range in the settings table (Render/SettingsTable.h),
    /// or a height (width / aspect) beyond 65536.
    void validate() const;
};

template <>
struct EnumNames<EngineKind>
{
    static constexpr std::array<EnumName<EngineKind>, 3> values{
        {{EngineKind::Single, "single"}, {EngineKind::Multi, "multi"}, {EngineKind::Gpu, "gpu"}}};
};

template <>
struct EnumNames<PixelSampling>
{
    // The thesis' names ("normal", "accumulation") are accepted as aliases.
    static constexpr std::array<EnumName<PixelSampling>, 4> values{{{PixelSampling::Random, "random", "normal"},
                                                                    {PixelSampling::Accumulate, "accumulate", "accumulation"},
                                                                    {PixelSampling::Stratified, "stratified"},
                                                                    {PixelSampling::Sobol, "sobol"}}};
};

template <>
struct EnumNames<Estimator>
{
    static constexpr std::array<EnumName<Estimator>, 5> values{{{Estimator::BsdfOnly, "bsdf"},
                                                                {Estimator::Mixture, "mixture"},
                                                                {Estimator::Nee, "nee"},
                                                                {Estimator::NeeMis, "nee-mis"},
                                                                {Estimator::RestirDi, "restir-di"}}};
};

template <>
struct EnumNames<LightSampler>
{
    static constexpr std::array<EnumName<LightSampler>, 4> values{
        {{LightSampler::Area, "area"}, {LightSampler::SolidAngle, "solid-angle"}, {LightSampler::Projected, "projected"},
         {LightSampler::ProjectedExact, "projected-exact"}}};
};

template <>
struct EnumNames<RussianRoulette>
{
    // "on" was the only rule before Cycles' joined it; "throughput" names it beside "sqrt".
    static constexpr std::array<EnumName<RussianRoulette>, 3> values{{{RussianRoulette::Off, "off"},
                                                                      {RussianRoulette::Throughput, "on", "throughput"},
                                                                      {RussianRoulette::Sqrt, "sqrt"}}};
};

template <>
struct EnumNames<LightSelection>
{
    static constexpr std::array<EnumName<LightSelection>, 3> values{
        {{LightSelection::Uniform, "uniform"}, {LightSelection::Power, "power"}, {LightSelection::Bvh, "bvh"}}};
};

/// The pixel sampling of a progressive render (the GPU window's passes of one or a few samples): Sobol's points,
/// indexed by the sample whatever the passes, stay; so do stratified samples when the passes stop at the settings'
/// spp (`countKnown`: the strata are counted from it, and sample s lies in stratum s); anything else becomes random
/// jitter per pass (accumulate, the same numbers as random).
constexpr PixelSampling progressiveSampling(PixelSampling sampling, bool countKnown = false)
{
    if (sampling == PixelSampling::Sobol || (sampling == PixelSampling::Stratified && countKnown))
        return sampling;
    return PixelSampling::Accumulate;
}

/// The estimator's word, "restir-di-biased" for restir-di's biased combination: what every output that names a
/// render's estimator shows (the headless summary, --compare's labels).
std::string estimatorLabel(const RenderSettings& settings);

/// Every field by its JSON key (Render/SettingsTable.h: spp, depth, width, aspect, sampling, estimator,
/// light_sampler, light_selection, russian_roulette, unidirectional_light, seed): the stats JSON's "settings"
/// and the reference cache's key.
nlohmann::json toJson(const RenderSettings& settings);
} // namespace rt
