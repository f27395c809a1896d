// The default suite's run of a fuzz target (no libFuzzer, any compiler): every file of the folders given (the
// checked-in seed corpus and the regressions, inputs that once crashed) goes through LLVMFuzzerTestOneInput once.
// A reader that crashes, or throws what is not its documented rt::Error, fails the test; the file is named first.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
    int files = 0;
    for (int i = 1; i < argc; ++i)
    {
        if (!std::filesystem::is_directory(argv[i]))
        {
            std::fprintf(stderr, "replay: '%s' is not a folder\n", argv[i]);
            return 2;
        }
        for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i]))
        {
            if (!entry.is_regular_file())
                continue;
            std::fprintf(stderr, "replay: %s\n", entry.path().string().c_str());
            std::ifstream in(entry.path(), std::ios::binary);
            const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            try
            {
                LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
            }
            catch (const std::exception& e)
            {
                std::fprintf(stderr, "replay: FAIL %s: uncaught %s\n", entry.path().string().c_str(), e.what());
                return 1;
            }
            ++files;
        }
    }
    if (files == 0)
    {
        std::fprintf(stderr, "replay: no input files\n");
        return 2;
    }
    std::printf("replay: %d inputs, no crash\n", files);
    return 0;
}
