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
} // namespace rt::gui
