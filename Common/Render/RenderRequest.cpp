#include "Render/RenderRequest.h"

namespace rt
{
Scene buildScene(const SceneRef& ref) { return makeScene(ref.id, ref.options); }

RenderRequest defaultRequest(const SceneRef& ref, const Scene& scene)
{
    RenderRequest r{.scene = ref};
    r.settings.spp = scene.defaults.spp;
    r.settings.depth = scene.defaults.depth;
    r.settings.width = scene.defaults.width;
    r.settings.aspect = scene.defaults.aspect;
    r.settings.unidirectionalLight = scene.defaults.unidirectionalLight;
    return r;
}
} // namespace rt
