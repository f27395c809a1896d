// The thesis' settings panel (appendix B.1) and what it lacked: UI parameters (colours, font); rendering
// parameters (scene, samples per pixel, depth, aspect ratio, image width, engine, pixel sampling, PDF,
// unidirectional light, loop rendering); then Render/Cancel with progress and ETA, the last render's time,
// and Save image. Every widget calls a Session command: it holds no setting of its own.
#pragma once

#include <string>

#include "App/Gui/Session.h"

namespace rt::gui
{
class SettingsPanel
{
public:
    /// Draws into the current ImGui window.
    void draw(Session& session);

private:
    void drawUiParameters(Session& session);
    void drawRenderingParameters(Session& session);
    void drawEngineChoice(Session& session);
    void drawRenderControls(Session& session);
    void drawSaveImage(Session& session);

    std::string m_sceneFile; // the path typed beside Load
    std::string m_savePath; // follows the suggested name until the user edits it
    bool m_savePathEdited = false;
};
} // namespace rt::gui
