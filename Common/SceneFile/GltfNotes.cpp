#include "SceneFile/GltfNotes.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

namespace rt
{
void GltfNotes::add(const std::string& feature, const std::string& where)
{
    auto it = std::find_if(m_entries.begin(), m_entries.end(), [&](const Entry& e) { return e.feature == feature; });
    if (it == m_entries.end())
        it = m_entries.insert(m_entries.end(), Entry{feature, {}});
    if (!where.empty() && std::find(it->places.begin(), it->places.end(), where) == it->places.end())
        it->places.push_back(where);
}

bool GltfNotes::mentions(const std::string& word) const
{
    return std::any_of(m_entries.begin(), m_entries.end(), [&](const Entry& e) { return e.feature.starts_with(word); });
}

std::vector<std::string> GltfNotes::features() const
{
    std::vector<std::string> out;
    for (const Entry& e : m_entries)
        out.push_back(e.feature);
    return out;
}

std::string GltfNotes::list() const
{
    std::string out;
    for (const Entry& e : m_entries)
    {
        out += out.empty() ? "" : ", ";
        out += e.feature;
        if (e.places.empty())
            continue;
        std::string places;
        for (std::size_t i = 0; i < std::min(e.places.size(), kPlacesShown); ++i)
            places += fmt::format("{}{}", i == 0 ? "" : ", ", e.places[i]);
        if (e.places.size() > kPlacesShown)
            places += fmt::format(" and {} more", e.places.size() - kPlacesShown);
        out += fmt::format(" ({})", places);
    }
    return out;
}
} // namespace rt
