// Parameterised tests over the scene catalogue: the ids, and gtest names made from them.
#pragma once

#include <string>
#include <vector>

namespace rt::test
{
/// Every catalogue scene id, in catalogue order.
std::vector<std::string> catalogueIds();

/// `id` as a gtest parameter name (gtest allows letters, digits and '_': rtnw-final -> rtnw_final).
std::string testNameOf(std::string id);
} // namespace rt::test
