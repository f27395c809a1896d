// Fuzz target: the PFM reader (Image/ImageIO.h), which reads every --reference and the comparisons' images.
#include "Error.h"
#include "Fuzz/FuzzInput.h"
#include "Image/ImageIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try
    {
        rt::readPfm(rt::fuzz::inputFile(data, size, ".pfm"));
    }
    catch (const rt::Error&)
    {
    }
    return 0;
}
