#include "Support/CatalogueCases.h"

#include <algorithm>

#include "Scenes/Catalogue.h"

namespace rt::test
{
std::vector<std::string> catalogueIds()
{
    std::vector<std::string> ids;
    for (const SceneInfo& info : sceneCatalogue())
        ids.push_back(info.id);
    return ids;
}

std::string testNameOf(std::string id)
{
    std::replace(id.begin(), id.end(), '-', '_');
    return id;
}
} // namespace rt::test
