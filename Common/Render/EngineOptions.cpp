#include "Render/EngineOptions.h"

namespace rt
{
const char* specializeName(Specialize specialize)
{
    switch (specialize)
    {
    case Specialize::Off: return "off";
    case Specialize::Strategy: return "strategy";
    case Specialize::Full: return "on";
    }
    return "?";
}

std::optional<Specialize> parseSpecialize(std::string_view name)
{
    for (const Specialize s : {Specialize::Off, Specialize::Strategy, Specialize::Full})
        if (name == specializeName(s))
            return s;
    return std::nullopt;
}

const char* integratorName(GpuIntegrator integrator)
{
    switch (integrator)
    {
    case GpuIntegrator::Auto: return "auto";
    case GpuIntegrator::Megakernel: return "megakernel";
    case GpuIntegrator::Wavefront: return "wavefront";
    }
    return "?";
}

std::optional<GpuIntegrator> parseIntegrator(std::string_view name)
{
    for (const GpuIntegrator i : {GpuIntegrator::Auto, GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
        if (name == integratorName(i))
            return i;
    return std::nullopt;
}
} // namespace rt
