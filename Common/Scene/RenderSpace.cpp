#include "Scene/RenderSpace.h"

#include "Scene/Scene.h"
#include "Scene/SceneTransform.h"

namespace rt
{
void toRenderSpace(Scene& scene)
{
    const vec3 camera = scene.camera.lookFrom;
    if (camera == vec3(0.0f))
        return;
    moveScene(scene, {-camera, 1.0f});
    scene.origin += dvec3(camera);
    for (TextureData& t : scene.textures)
        if (t.type == TextureType::Checker || t.type == TextureType::Noise || t.type == TextureType::Turbulence ||
            t.type == TextureType::Marble)
            t.origin += camera; // the pattern stays on the scene's coordinates
}
} // namespace rt
