// An OBJ file's text for the mesh tests of issue 13 (meshes modelled far from the origin, huge or tiny).
#pragma once

#include <string>

#include <spdlog/fmt/fmt.h>

namespace rt::test
{
/// An axis-aligned cube of edge `edge` centred at (c, c, c), as OBJ text with %.17g coordinates (every
/// double written exactly) and six outward quads.
inline std::string cubeObj(double c, double edge)
{
    std::string text;
    for (int i = 0; i < 8; ++i)
        text += fmt::format("v {:.17g} {:.17g} {:.17g}\n", c + ((i & 1) ? 0.5 : -0.5) * edge,
                            c + ((i & 2) ? 0.5 : -0.5) * edge, c + ((i & 4) ? 0.5 : -0.5) * edge);
    return text + "f 2 4 8 6\nf 1 5 7 3\nf 3 7 8 4\nf 1 2 6 5\nf 5 6 8 7\nf 1 3 4 2\n";
}
} // namespace rt::test
