// Fuzz target: the glTF import (SceneFile/GltfImport.h), .gltf and .glb alike (told apart by their first bytes),
// then the checks every scene file passes.
#include "Error.h"
#include "Fuzz/FuzzInput.h"
#include "Scene/SceneTransform.h"
#include "SceneFile/GltfImport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try
    {
        const rt::GltfImport imported = rt::readGltf(rt::fuzz::inputFile(data, size, ".gltf"));
        rt::checkFloatReach(imported.scene, "fuzz.gltf");
        imported.scene.validate();
    }
    catch (const rt::Error&)
    {
    }
    return 0;
}
