// The one settings record of a render: which scene (catalogue id and the options it is built with) and how
// to render it. The command line resolves one (Cli/CommonOptions.h), both windows edit one, the render driver
// takes one and the stats report it, --compare varies it. The defaulted operator== compares every field, so a
// field added later takes part in every "is this the same render?" check (the windows' staleness, the
// timings table) without anyone remembering to add it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "Render/RenderSettings.h"
#include "Scene/Camera.h"
#include "Scenes/Catalogue.h"

namespace rt
{
/// A scene as the catalogue builds it: equal references build equal scenes.
struct SceneRef
{
    std::string id = "cornell-box-lights"; // a catalogue id or a scene file's path (SceneFile.h)
    SceneOptions options;
    /// For a scene file: the version (sceneFileVersion, SceneFileWatch.h) the request saw; a window that
    /// notices a newer one changes it, so that every "same scene?" check rebuilds the scene. 0 otherwise.
    std::int64_t fileVersion = 0;

    bool operator==(const SceneRef&) const = default;
};

struct RenderRequest
{
    SceneRef scene;
    RenderSettings settings;
    /// The windows' moved camera (orbit, WASD, wheel); none: the scene's own. An image of another view is other
    /// work: the timings, the references and their cache key tell them apart.
    std::optional<CameraDesc> camera;

    bool operator==(const RenderRequest&) const = default;
};

/// Builds the scene `ref` names. Throws SceneError (unknown id), AssetError (missing mesh or texture).
Scene buildScene(const SceneRef& ref);

/// `settings` with a scene's own defaults: spp, depth, width, aspect, emitter sidedness, estimator, pixel sampling.
void applySceneDefaults(RenderSettings& settings, const SceneDefaults& defaults);

/// The request for `ref` with the built scene's own defaults (applySceneDefaults); the rest are
/// RenderSettings' defaults.
RenderRequest defaultRequest(const SceneRef& ref, const Scene& scene);
} // namespace rt
