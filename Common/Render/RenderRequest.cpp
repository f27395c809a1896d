#include "Render/RenderRequest.h"

namespace rt
{
Scene buildScene(const SceneRef& ref) { return makeScene(ref.id, ref.options); }

void applySceneDefaults(RenderSettings& settings, const SceneDefaults& defaults)
{
    settings.spp = defaults.spp;
    settings.depth = defaults.depth;
    settings.width = defaults.width;
    settings.aspect = defaults.aspect;
    settings.unidirectionalLight = defaults.unidirectionalLight;
    settings.estimator = defaults.estimator;
    settings.sampling = defaults.sampling;
}

RenderRequest defaultRequest(const SceneRef& ref, const Scene& scene)
{
    RenderRequest r{.scene = ref};
    applySceneDefaults(r.settings, scene.defaults);
    return r;
}
} // namespace rt
