// What a glTF import could not map (an unsupported feature, a texture it left out, a tinygltf warning), each
// feature named once with where it was met, for the one `warning:` line of docs/SCENES.md's glTF section.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rt
{
class GltfNotes
{
public:
    /// Notes `feature` ("normal textures") met at `where` ("material 'Floor'"; may be empty). A feature is
    /// listed once, in the order first met, with the first few places it was met at.
    void add(const std::string& feature, const std::string& where = "");

    bool empty() const { return m_entries.empty(); }
    /// Whether a feature noted so far starts with `word` (an extension noted where it was met, with words after
    /// its name, is not noted again from the file's extensionsUsed).
    bool mentions(const std::string& word) const;
    /// The features alone, in the order first met.
    std::vector<std::string> features() const;
    /// "normal textures (material 'Floor', material 'Wall'), KHR_texture_transform (material 'Arrow')".
    std::string list() const;

    static constexpr std::size_t kPlacesShown = 3; // then "and N more"

private:
    struct Entry
    {
        std::string feature;
        std::vector<std::string> places; // distinct, in the order met
    };
    std::vector<Entry> m_entries;
};
} // namespace rt
