#include "SceneFile/GltfCamera.h"

#include <cmath>
#include <numbers>

#include <glm/mat3x3.hpp>
#include <spdlog/fmt/fmt.h>

namespace rt
{
namespace
{
constexpr double kMaxVfovDegrees = 179.0; // the JSON reader's limit: tan(vfov / 2) stays finite
constexpr double kMinAspect = 1e-4; // the JSON reader's limits
constexpr double kMaxAspect = 1e4;

CameraDesc fromNode(const GltfDocument& doc, const GltfPlacedNode& placed, double yfov)
{
    const glm::dmat4& w = placed.worldFromNode;
    const glm::dvec3 eye(w * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 forward = glm::dmat3(w) * glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 up = glm::dmat3(w) * glm::dvec3(0.0, 1.0, 0.0);
    const double length = glm::length(forward);
    if (!(length > 0.0) || !std::isfinite(length) || !(glm::length(glm::cross(forward, up)) > 0.0))
        doc.fail(fmt::format("/nodes/{}", placed.node),
                 "the camera node's transform collapses its view direction or makes it parallel to its up");
    CameraDesc c;
    c.lookFrom = vec3(eye);
    c.lookAt = vec3(eye + forward / length);
    c.vup = vec3(glm::normalize(up));
    c.vfovDegrees = static_cast<float>(yfov * 180.0 / std::numbers::pi);
    c.defocusAngleDegrees = 0.0f;
    return c;
}
} // namespace

std::optional<GltfCamera> gltfCamera(const GltfDocument& doc, const std::vector<GltfPlacedNode>& nodes,
                                     GltfNotes& notes)
{
    const tinygltf::Model& m = doc.model;
    for (const GltfPlacedNode& placed : nodes)
    {
        const int index = m.nodes[static_cast<std::size_t>(placed.node)].camera;
        if (index < 0)
            continue;
        if (static_cast<std::size_t>(index) >= m.cameras.size())
            doc.fail(fmt::format("/nodes/{}/camera", placed.node),
                     fmt::format("camera {} does not exist (the file has {})", index, m.cameras.size()));
        const tinygltf::Camera& camera = m.cameras[static_cast<std::size_t>(index)];
        if (camera.type != "perspective")
        {
            notes.add(fmt::format("{} cameras", camera.type),
                      camera.name.empty() ? fmt::format("camera {}", index) : fmt::format("camera '{}'", camera.name));
            continue;
        }
        const std::string pointer = fmt::format("/cameras/{}/perspective", index);
        const double yfov = camera.perspective.yfov;
        if (!(yfov > 0.0 && yfov * 180.0 / std::numbers::pi <= kMaxVfovDegrees))
            doc.fail(pointer + "/yfov", fmt::format("expected radians in (0, {:.4f}] ({} degrees), got {}",
                                                    kMaxVfovDegrees * std::numbers::pi / 180.0, kMaxVfovDegrees, yfov));
        GltfCamera out{fromNode(doc, placed, yfov), std::nullopt};
        const double aspect = camera.perspective.aspectRatio;
        if (aspect != 0.0) // tinygltf's value when the file gives none
        {
            if (!(aspect >= kMinAspect && aspect <= kMaxAspect))
                doc.fail(pointer + "/aspectRatio",
                         fmt::format("expected a number in [{}, {}], got {}", kMinAspect, kMaxAspect, aspect));
            out.aspect = static_cast<float>(aspect);
        }
        return out;
    }
    return std::nullopt;
}

CameraDesc gltfFramingCamera(const glm::dvec3& lo, const glm::dvec3& hi)
{
    const glm::dvec3 centre = 0.5 * (lo + hi);
    double radius = 0.5 * glm::length(hi - lo);
    if (!(radius > 0.0))
        radius = 1.0; // a single point: any distance shows it
    const double halfAngle = 0.5 * kGltfFramingVfov * std::numbers::pi / 180.0;
    const double distance = 1.1 * radius / std::sin(halfAngle);
    CameraDesc c;
    c.lookFrom = vec3(centre + glm::dvec3(0.0, 0.0, distance));
    c.lookAt = vec3(centre);
    c.vup = vec3(0.0f, 1.0f, 0.0f);
    c.vfovDegrees = kGltfFramingVfov;
    c.focusDistance = static_cast<float>(distance);
    return c;
}
} // namespace rt
