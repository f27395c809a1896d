#include "SceneFile/GltfFile.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Assets/AssetPaths.h"
#include "Error.h"
#include "SceneFile/GltfTypes.h"
#include "SceneFile/JsonNode.h"

namespace rt
{
namespace
{
/// The files tinygltf looked for and could not read, and why (its error text does not say which kind of failure
/// it was): missing, not a regular file, or outside the scene's folders.
struct MissingFiles
{
    std::filesystem::path folder; // the glTF file's
    std::vector<std::string> paths;
    std::vector<std::string> reasons; // "" for a missing file
};

/// A buffer or image file tinygltf may read: a regular file inside the scene's folder or the asset folder.
bool fileExists(const std::string& path, void* user)
{
    auto& missing = *static_cast<MissingFiles*>(user);
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    std::string reason;
    if (!std::filesystem::exists(status))
        reason = "";
    else if (!std::filesystem::is_regular_file(status))
        reason = fmt::format("'{}' is not a regular file", path);
    else if (reason = outsideSceneFolders(path, missing.folder); reason.empty())
        return true;
    missing.paths.push_back(path);
    missing.reasons.push_back(reason);
    return false;
}

std::string expandFilePath(const std::string& path, void*) { return path; } // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
{
    if (fileExists(path, user) && tinygltf::ReadWholeFile(out, err, path, nullptr))
        return true;
    auto& missing = *static_cast<MissingFiles*>(user);
    if (missing.paths.empty() || missing.paths.back() != path)
    {
        missing.paths.push_back(path);
        missing.reasons.push_back("");
    }
    return false;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err = "the importer writes no files";
    return false;
}

/// Keeps an image's encoded bytes (a data URI's) for GltfImages; an image in a bufferView is read there, with
/// its bounds checked (tinygltf hands this callback a pointer at the view's offset without checking it).
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*)
{
    image->as_is = true;
    if (image->bufferView < 0 && bytes && size > 0)
        image->image.assign(bytes, bytes + size);
    return true;
}

bool isGlb(const std::vector<unsigned char>& bytes)
{
    return bytes.size() >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F';
}

std::vector<unsigned char> readBytes(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw SceneError(fmt::format("{}: cannot be opened", file.string()));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    std::vector<unsigned char> bytes(size > 0 ? static_cast<std::size_t>(size) : 0);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (size < 0 || in.bad() || in.gcount() != static_cast<std::streamsize>(bytes.size()))
        throw SceneError(fmt::format("{}: cannot be read", file.string()));
    return bytes;
}
} // namespace

std::string gltfOneLine(const std::string& text)
{
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
    {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos)
            continue;
        line = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
        out += (out.empty() ? "" : "; ") + line;
    }
    return out;
}

void GltfDocument::fail(const std::string& pointer, const std::string& what) const
{
    throw SceneError(fmt::format("{}: {}: {}", file.string(), pointer, what));
}

GltfDocument loadGltfFile(const std::filesystem::path& file, GltfNotes& notes)
{
    std::error_code ec;
    if (const auto size = std::filesystem::file_size(file, ec); !ec && size > (std::uintmax_t{16} << 20))
        spdlog::info("reading {} ({} MB)", file.string(), size >> 20);
    const std::vector<unsigned char> bytes = readBytes(file);
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw SceneError(fmt::format("{}: {} bytes: tinygltf reads files of less than 4 GiB", file.string(),
                                     bytes.size()));

    // The JSON (a .glb's first chunk) nested no deeper than the parser's recursion can take.
    std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (isGlb(bytes))
    {
        std::uint32_t length = 0;
        if (bytes.size() >= 20)
            std::memcpy(&length, bytes.data() + 12, 4);
        json = json.substr(std::min<std::size_t>(20, bytes.size()), length);
    }
    checkJsonNesting(json, file.string());
    checkGltfTypes(json, file);

    MissingFiles missing{.folder = file.parent_path()};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &missing});
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    GltfDocument doc{{}, file};
    std::string err, warn;
    const std::string folder = file.parent_path().string();
    const bool binary = isGlb(bytes);
    bool ok = false;
    try
    {
        const auto size = static_cast<unsigned int>(bytes.size());
        ok = binary ? loader.LoadBinaryFromMemory(&doc.model, &err, &warn, bytes.data(), size, folder)
                    : loader.LoadASCIIFromString(&doc.model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                 size, folder);
    }
    catch (const std::exception& e) // tinygltf reports through `err`; the JSON library it calls may still throw
    {
        err += e.what();
    }
    if (!ok)
    {
        if (!missing.paths.empty() && !missing.reasons.front().empty())
            throw SceneError(fmt::format("{}: a buffer or image refers to '{}': {}", file.string(),
                                         missing.paths.front(), missing.reasons.front()));
        if (!missing.paths.empty())
            throw AssetError(fmt::format("{}: buffer file '{}' not found ({})", file.string(), missing.paths.front(),
                                         gltfOneLine(err)));
        throw SceneError(fmt::format("{}: not a valid glTF 2.0 {} file: {}", file.string(), binary ? "binary" : "JSON",
                                     err.empty() ? "tinygltf refused it" : gltfOneLine(err)));
    }
    // tinygltf also reports problems it read past (a value of the wrong type, left at its default) in `err`.
    for (const std::string& message : {warn, err})
        if (!gltfOneLine(message).empty())
            notes.add(fmt::format("tinygltf: {}", gltfOneLine(message)));
    return doc;
}
} // namespace rt
