// Fuzz target: the JSON scene reader (SceneFile/JsonSceneReader.h), then the checks every scene file passes
// (float32's reach, Scene::validate).
#include "Error.h"
#include "Fuzz/FuzzInput.h"
#include "Scene/Scene.h"
#include "Scene/SceneTransform.h"
#include "SceneFile/JsonSceneReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try
    {
        const rt::Scene scene = rt::readJsonSceneText(std::string(rt::fuzz::text(data, size)),
                                                      rt::fuzz::scratchFolder() / "fuzz.json");
        rt::checkFloatReach(scene, "fuzz.json");
        scene.validate();
    }
    catch (const rt::Error&)
    {
    }
    return 0;
}
