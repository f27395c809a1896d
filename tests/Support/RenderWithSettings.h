// The render driver for tests that hold settings rather than a whole request: the request names the scene the
// engine holds, with its default options.
#pragma once

#include "Render/RenderDriver.h"

namespace rt::test
{
inline RenderResult renderWithSettings(RenderEngine& engine, const RenderSettings& settings, RenderControl& control,
                                       const PreviewCallback& preview = {})
{
    const RenderRequest request{.scene = {.id = engine.scene() ? engine.scene()->id : std::string()},
                                .settings = settings};
    return render(engine, request, control, preview);
}
} // namespace rt::test
