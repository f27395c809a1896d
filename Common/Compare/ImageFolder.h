// --images DIR of --compare: every render's linear image kept as a PFM beside an index (images.json), so that
// an analysis the comparison does not make itself (the error over regions of the image, another metric, a
// second reference) reads the very images whose time and error the comparison printed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "Compare/Measurement.h"
#include "Render/RenderEngine.h"

namespace rt::compare
{
class ImageFolder
{
public:
    /// Creates `dir` (and its parents) when missing and indexes the renders of `scene` at width x height pixels
    /// there. Throws OutputError when it is a symbolic link, not a folder or cannot be written; an empty `dir`
    /// makes every call a no-op.
    ImageFolder(std::filesystem::path dir, const std::string& scene, int width, int height);

    bool enabled() const { return !m_dir.empty(); }
    /// images.json: scene, size, the relMSE's epsilon, each engine's device, the reference and every image.
    std::filesystem::path indexPath() const { return m_dir / "images.json"; }

    /// Records the device `engine` renders on (the figures' captions).
    void setDevice(EngineKind engine, const std::string& device);

    /// Writes the reference as reference.pfm (linear radiance, W/(sr m^2) per channel) with its spp (0 for a
    /// file) and its own relMSE where known.
    void addReference(const Image& image, const std::string& description, int spp, std::optional<double> ownRelMse);

    /// Writes `m.image` as <engine>-<label>-<spp>spp-seed<seed>.pfm and indexes it with its seed, time and error. The strategy
    /// is `name` (every setting) and `label` (what tells it apart in this comparison). The index, images.json
    /// (scene, size, the reference and every image in the order added), is written again (atomically) after
    /// each image, so Ctrl-C keeps an index of what was written.
    void add(EngineKind engine, const std::string& name, const std::string& label, const Measurement& m,
             std::uint32_t seed);

    /// Removes what this folder wrote (the images, the reference, images.json): a failed distributed comparison
    /// leaves no partial output. The folder itself stays.
    void discard();

private:
    void flush();

    std::filesystem::path m_dir;
    nlohmann::json m_index;
};
} // namespace rt::compare
