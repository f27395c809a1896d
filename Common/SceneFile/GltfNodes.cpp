#include "SceneFile/GltfNodes.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <spdlog/fmt/fmt.h>

namespace rt
{
namespace
{
/// `values` (the node's `key`), checked: empty, or `length` finite numbers.
const std::vector<double>& numbers(const GltfDocument& doc, int node, const char* key,
                                   const std::vector<double>& values, std::size_t length)
{
    const std::string pointer = fmt::format("/nodes/{}/{}", node, key);
    if (!values.empty() && values.size() != length)
        doc.fail(pointer, fmt::format("expected {} numbers, got {}", length, values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            doc.fail(fmt::format("{}/{}", pointer, i), "expected a finite number");
    return values;
}
} // namespace

glm::dmat4 gltfLocalTransform(const GltfDocument& doc, int index)
{
    const tinygltf::Node& n = doc.model.nodes[static_cast<std::size_t>(index)];
    if (const auto& m = numbers(doc, index, "matrix", n.matrix, 16); !m.empty())
    {
        glm::dmat4 out;
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row)
                out[column][row] = m[static_cast<std::size_t>(4 * column + row)];
        return out;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (const auto& v = numbers(doc, index, "translation", n.translation, 3); !v.empty())
        t = glm::translate(glm::dmat4(1.0), glm::dvec3(v[0], v[1], v[2]));
    if (const auto& q = numbers(doc, index, "rotation", n.rotation, 4); !q.empty())
    {
        const glm::dquat rotation(q[3], q[0], q[1], q[2]); // glTF: x, y, z, w; glm: w, x, y, z
        const double length = glm::length(rotation);
        if (!(length > 0.0))
            doc.fail(fmt::format("/nodes/{}/rotation", index), "a zero quaternion is no rotation");
        r = glm::mat4_cast(rotation / length);
    }
    if (const auto& v = numbers(doc, index, "scale", n.scale, 3); !v.empty())
        s = glm::scale(glm::dmat4(1.0), glm::dvec3(v[0], v[1], v[2]));
    return t * r * s;
}

std::vector<GltfPlacedNode> gltfSceneNodes(const GltfDocument& doc)
{
    const tinygltf::Model& m = doc.model;
    const std::size_t nodeCount = m.nodes.size();
    std::vector<int> roots;
    std::vector<std::string> rootPointers; // where each root is named
    if (!m.scenes.empty())
    {
        const int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
        if (static_cast<std::size_t>(scene) >= m.scenes.size())
            doc.fail("/scene", fmt::format("scene {} does not exist (the file has {})", scene, m.scenes.size()));
        roots = m.scenes[static_cast<std::size_t>(scene)].nodes;
        for (std::size_t i = 0; i < roots.size(); ++i)
        {
            rootPointers.push_back(fmt::format("/scenes/{}/nodes/{}", scene, i));
            if (roots[i] < 0 || static_cast<std::size_t>(roots[i]) >= nodeCount)
                doc.fail(rootPointers.back(),
                         fmt::format("node {} does not exist (the file has {})", roots[i], nodeCount));
        }
    }
    else
    {
        std::vector<bool> child(nodeCount, false);
        for (const tinygltf::Node& n : m.nodes)
            for (int c : n.children)
                if (c >= 0 && static_cast<std::size_t>(c) < nodeCount)
                    child[static_cast<std::size_t>(c)] = true;
        for (std::size_t i = 0; i < nodeCount; ++i)
            if (!child[i])
            {
                roots.push_back(static_cast<int>(i));
                rootPointers.push_back(fmt::format("/nodes/{}", i));
            }
    }

    std::vector<GltfPlacedNode> out;
    std::vector<bool> reached(nodeCount, false);
    struct Pending
    {
        int node;
        glm::dmat4 worldFromParent;
        std::string pointer; // where it was named, for errors
    };
    std::vector<Pending> stack; // depth first without recursion: a deep hierarchy cannot overflow the stack
    for (std::size_t i = roots.size(); i-- > 0;)
        stack.push_back({roots[i], glm::dmat4(1.0), rootPointers[i]});
    while (!stack.empty())
    {
        const Pending p = std::move(stack.back());
        stack.pop_back();
        if (reached[static_cast<std::size_t>(p.node)])
            doc.fail(p.pointer, fmt::format("node {} is reached twice: the node hierarchy must be disjoint trees "
                                            "(glTF 2.0 §3.5.2)",
                                            p.node));
        reached[static_cast<std::size_t>(p.node)] = true;
        const glm::dmat4 world = p.worldFromParent * gltfLocalTransform(doc, p.node);
        out.push_back({p.node, world});
        const std::vector<int>& children = m.nodes[static_cast<std::size_t>(p.node)].children;
        for (std::size_t i = children.size(); i-- > 0;)
        {
            const std::string pointer = fmt::format("/nodes/{}/children/{}", p.node, i);
            if (children[i] < 0 || static_cast<std::size_t>(children[i]) >= nodeCount)
                doc.fail(pointer, fmt::format("node {} does not exist (the file has {})", children[i], nodeCount));
            stack.push_back({children[i], world, pointer});
        }
    }
    return out;
}
} // namespace rt
