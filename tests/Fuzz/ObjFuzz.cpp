// Fuzz target: the OBJ reader (Assets/ObjLoader.h), fitted and as written.
#include "Assets/ObjLoader.h"
#include "Error.h"
#include "Fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path file = rt::fuzz::inputFile(data, size, ".obj");
    for (const rt::ObjPlacement placement : {rt::ObjPlacement::Fit, rt::ObjPlacement::AsWritten})
    {
        try
        {
            rt::loadObj(file.string(), placement);
        }
        catch (const rt::Error&)
        {
        }
    }
    return 0;
}
