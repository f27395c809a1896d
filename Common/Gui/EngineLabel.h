// The engines' names as both windows' panels, timings tables and plots show them.
#pragma once

#include "Render/RenderSettings.h"

namespace rt::gui
{
/// "single core", "multi core", "GPU".
inline const char* engineLabel(EngineKind engine)
{
    switch (engine)
    {
    case EngineKind::Single: return "single core";
    case EngineKind::Multi: return "multi core";
    case EngineKind::Gpu: return "GPU";
    }
    return "?";
}
} // namespace rt::gui
