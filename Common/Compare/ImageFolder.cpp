#include "Compare/ImageFolder.h"

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "IO/AtomicFile.h"
#include "IO/OutputSet.h"
#include "Image/ImageIO.h"
#include "Image/Metrics.h"

namespace rt::compare
{
namespace
{
/// A file name's part from a strategy name: letters, digits and '-' kept, runs of anything else as one '_'.
std::string fileSafe(const std::string& text)
{
    std::string out;
    for (const char c : text)
    {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-';
        if (keep)
            out += c;
        else if (!out.empty() && out.back() != '_')
            out += '_';
    }
    while (!out.empty() && out.back() == '_')
        out.pop_back();
    return out.empty() ? "default" : out;
}
} // namespace

ImageFolder::ImageFolder(std::filesystem::path dir, const std::string& scene, int width, int height)
    : m_dir(std::move(dir))
{
    if (m_dir.empty())
        return;
    std::error_code ec;
    if (std::filesystem::is_symlink(m_dir, ec))
        throw OutputError(fmt::format("--images '{}' is a symbolic link: give the folder itself", m_dir.string()));
    if (std::filesystem::exists(m_dir, ec) && !std::filesystem::is_directory(m_dir, ec))
        throw OutputError(fmt::format("--images '{}' is not a folder", m_dir.string()));
    std::filesystem::create_directories(m_dir, ec);
    if (ec)
        throw OutputError(fmt::format("--images '{}': cannot create the folder: {}", m_dir.string(), ec.message()));
    checkWritable(m_dir / "images.json", "--images");
    m_index = {{"scene", scene},
               {"width", width},
               {"height", height},
               {"epsilon", kRelMseEpsilon},
               {"images", nlohmann::json::array()}};
    flush();
}

void ImageFolder::setDevice(EngineKind engine, const std::string& device)
{
    if (!enabled())
        return;
    m_index["devices"][toString(engine)] = device;
    flush();
}

void ImageFolder::addReference(const Image& image, const std::string& description, int spp,
                               std::optional<double> ownRelMse)
{
    if (!enabled())
        return;
    writePfm(m_dir / "reference.pfm", image);
    m_index["reference"] = {{"path", "reference.pfm"}, {"description", description}, {"spp", spp}};
    if (ownRelMse)
        m_index["reference"]["own_relmse"] = *ownRelMse;
    flush();
}

void ImageFolder::add(EngineKind engine, const std::string& name, const std::string& label, const Measurement& m,
                      std::uint32_t seed)
{
    if (!enabled())
        return;
    const std::string file = fmt::format("{}-{}-{}spp-seed{}.pfm", toString(engine), fileSafe(label), m.spp, seed);
    writePfm(m_dir / file, m.image);
    m_index["images"].push_back({{"path", file},
                                 {"engine", toString(engine)},
                                 {"strategy", name},
                                 {"label", label},
                                 {"spp", m.spp},
                                 {"seed", seed},
                                 {"ms", m.ms()},
                                 {"wall_ms", m.wallMs},
                                 {"gpu_ms", m.gpuMs},
                                 {"relmse", m.error.relMse}});
    flush();
}

void ImageFolder::discard()
{
    if (!enabled())
        return;
    std::error_code ignored;
    for (const nlohmann::json& image : m_index["images"])
        std::filesystem::remove(m_dir / image.at("path").get<std::string>(), ignored);
    if (m_index.contains("reference"))
        std::filesystem::remove(m_dir / "reference.pfm", ignored);
    std::filesystem::remove(indexPath(), ignored);
}

void ImageFolder::flush()
{
    writeFileAtomically(indexPath(), m_index.dump(2) + "\n");
}
} // namespace rt::compare
