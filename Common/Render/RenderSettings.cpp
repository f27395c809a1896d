#include "Render/RenderSettings.h"

#include <cmath>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Render/SettingsTable.h"

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
    for (const Setting& s : settingsTable())
    {
        if (s.number == nullptr)
            continue;
        const double v = s.number(*this);
        const bool inRange = s.type == SettingType::Integer ? v >= s.minimum && v <= s.maximum
                                                            : std::isfinite(v) && v > s.minimum && v <= s.maximum;
        if (!inRange)
            throw UsageError(s.refusal(s.text(*this)));
    }
    const double h = static_cast<double>(width) / aspect;
    if (h > kMaxImageSide)
        throw UsageError(fmt::format("height {} (width / aspect) exceeds {}", h, kMaxImageSide));
}

std::string estimatorLabel(const RenderSettings& settings)
{
    std::string label = toString(settings.estimator);
    if (settings.estimator == Estimator::RestirDi && settings.restirBiased)
        label += "-biased";
    return label;
}

nlohmann::json toJson(const RenderSettings& settings)
{
    nlohmann::json out = nlohmann::json::object();
    for (const Setting& s : settingsTable())
        out[std::string(s.jsonKey)] = s.json(settings);
    return out;
}
} // namespace rt
