// What the fuzz targets share: the readers under test take files, so each input is written to a file of this
// process's own folder (removed at exit) under the reader's extension; and which errors are the reader's
// documented refusals (rt::Error: a one-line message for the user) rather than findings. Anything else a reader
// throws (std::bad_alloc for a header that claims gigapixels, std::out_of_range, ...) escapes the target and is
// reported by libFuzzer as a crash, as are the sanitizers' reports.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace rt::fuzz
{
/// A folder of this process's own, made on first use and removed when the process ends.
inline const std::filesystem::path& scratchFolder()
{
    struct Folder
    {
        std::filesystem::path path;
        Folder()
        {
            path = std::filesystem::temp_directory_path() / ("rt-fuzz-" + std::to_string(::getpid()));
            std::filesystem::create_directories(path);
        }
        ~Folder()
        {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Folder folder;
    return folder.path;
}

/// Writes `data` to <scratch>/input<extension> and returns that path.
inline std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size, const std::string& extension)
{
    const std::filesystem::path file = scratchFolder() / ("input" + extension);
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file;
}

inline std::string_view text(const std::uint8_t* data, std::size_t size)
{
    return {reinterpret_cast<const char*>(data), size};
}
} // namespace rt::fuzz
