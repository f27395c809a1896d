// Fuzz target: the OpenEXR reader (Image/ExrIO.h), which reads --reference files.
#include "Error.h"
#include "Fuzz/FuzzInput.h"
#include "Image/ExrIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try
    {
        rt::readExr(rt::fuzz::inputFile(data, size, ".exr"));
    }
    catch (const rt::Error&)
    {
    }
    return 0;
}
