// What the window's panel holds, split the way re-rendering needs it (style pattern 20): the RenderRequest
// (Render/RenderRequest.h: scene, options, settings) changes the image, so an image rendered with another
// request is stale and a new render starts; DisplaySettings only change how the window looks.
#pragma once

#include <string>

#include "Gui/EngineLabel.h"
#include "Render/RenderRequest.h"

namespace rt::gui
{
/// How the window looks: the thesis' "UI parameters" (colour mode and font).
struct DisplaySettings
{
    bool dark = true;
    std::string font; // a name from availableFonts(); empty: the first available
    float fontSize = 16.0f; // pixels

    bool operator==(const DisplaySettings&) const = default;
};
} // namespace rt::gui
