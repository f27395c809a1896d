#include "Render/RenderSettings.h"

#include <cmath>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
int RenderSettings::height() const
{
    return std::max(1, static_cast<int>(std::lround(static_cast<double>(width) / aspect)));
}

int RenderSettings::strata() const
{
    return sampling == PixelSampling::Stratified ? static_cast<int>(std::sqrt(static_cast<double>(spp))) : 1;
}

int RenderSettings::trueSpp() const
{
    return sampling == PixelSampling::Stratified ? strata() * strata() : spp;
}

void RenderSettings::validate() const
{
    constexpr int kMaxDimension = 1 << 16;
    if (spp < 1 || spp > kMaxSpp)
        throw UsageError(fmt::format("samples per pixel must be in [1, {}] (got {})", kMaxSpp, spp));
    if (depth < 1)
        throw UsageError(fmt::format("depth must be at least 1 (got {})", depth));
    if (width < 1 || width > kMaxDimension)
        throw UsageError(fmt::format("width must be in [1, {}] (got {})", kMaxDimension, width));
    if (!(aspect > 0.0f) || !std::isfinite(aspect))
        throw UsageError(fmt::format("aspect ratio must be positive (got {})", aspect));
    const double h = static_cast<double>(width) / aspect;
    if (h > kMaxDimension)
        throw UsageError(fmt::format("height {} (width / aspect) exceeds {}", h, kMaxDimension));
}

const char* toString(EngineKind engine)
{
    switch (engine)
    {
    case EngineKind::Single: return "single";
    case EngineKind::Multi: return "multi";
    case EngineKind::Gpu: return "gpu";
    }
    return "?";
}

const char* toString(PixelSampling sampling)
{
    switch (sampling)
    {
    case PixelSampling::Random: return "random";
    case PixelSampling::Stratified: return "stratified";
    case PixelSampling::Accumulate: return "accumulate";
    case PixelSampling::Sobol: return "sobol";
    }
    return "?";
}

const char* toString(Estimator estimator)
{
    switch (estimator)
    {
    case Estimator::BsdfOnly: return "bsdf";
    case Estimator::Mixture: return "mixture";
    case Estimator::Nee: return "nee";
    case Estimator::NeeMis: return "nee-mis";
    }
    return "?";
}

std::optional<EngineKind> parseEngine(const std::string& text)
{
    if (text == "single")
        return EngineKind::Single;
    if (text == "multi")
        return EngineKind::Multi;
    if (text == "gpu")
        return EngineKind::Gpu;
    return std::nullopt;
}

std::optional<PixelSampling> parsePixelSampling(const std::string& text)
{
    if (text == "random")
        return PixelSampling::Random;
    if (text == "stratified")
        return PixelSampling::Stratified;
    if (text == "accumulate")
        return PixelSampling::Accumulate;
    if (text == "sobol")
        return PixelSampling::Sobol;
    return std::nullopt;
}

std::optional<Estimator> parseEstimator(const std::string& text)
{
    for (Estimator e : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
        if (text == toString(e))
            return e;
    return std::nullopt;
}

const char* toString(LightSampler sampler)
{
    switch (sampler)
    {
    case LightSampler::Area: return "area";
    case LightSampler::SolidAngle: return "solid-angle";
    case LightSampler::Projected: return "projected";
    }
    return "?";
}

std::optional<LightSampler> parseLightSampler(const std::string& text)
{
    for (LightSampler s : {LightSampler::Area, LightSampler::SolidAngle, LightSampler::Projected})
        if (text == toString(s))
            return s;
    return std::nullopt;
}

const char* toString(LightSelection selection)
{
    switch (selection)
    {
    case LightSelection::Uniform: return "uniform";
    case LightSelection::Power: return "power";
    case LightSelection::Bvh: return "bvh";
    }
    return "?";
}

std::optional<LightSelection> parseLightSelection(const std::string& text)
{
    for (LightSelection s : {LightSelection::Uniform, LightSelection::Power, LightSelection::Bvh})
        if (text == toString(s))
            return s;
    return std::nullopt;
}

nlohmann::json toJson(const RenderSettings& s)
{
    return {{"spp", s.spp},
            {"depth", s.depth},
            {"width", s.width},
            {"aspect", s.aspect},
            {"sampling", toString(s.sampling)},
            {"estimator", toString(s.estimator)},
            {"light_sampler", toString(s.lightSampler)},
            {"light_selection", toString(s.lightSelection)},
            {"russian_roulette", s.russianRoulette},
            {"unidirectional_light", s.unidirectionalLight},
            {"seed", s.seed}};
}
} // namespace rt
