#include "App/Gui/PanelSettings.h"

namespace rt::gui
{
const char* engineLabel(EngineKind engine)
{
    switch (engine)
    {
    case EngineKind::Single: return "single core";
    case EngineKind::Multi: return "multi core";
    case EngineKind::Gpu: return "GPU";
    }
    return "?";
}

const char* samplingLabel(PixelSampling sampling)
{
    switch (sampling)
    {
    case PixelSampling::Random: return "random";
    case PixelSampling::Accumulate: return "accumulate";
    case PixelSampling::Stratified: return "stratified";
    case PixelSampling::Sobol: return "sobol";
    }
    return "?";
}
} // namespace rt::gui
