// Lights and shading points for the light-sampling tests: the LightData the scene builder would derive,
// written out here from the geometry so that a test does not depend on SceneBuilder's own helpers.
#pragma once

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "Math/Math.h"
#include "Sampling/LightSampling.h"

namespace rt::test
{
inline LightData makeQuadLight(const vec3& q, const vec3& u, const vec3& v)
{
    LightData l{};
    l.shape = LightShape::Quad;
    l.material = 0;
    l.p0 = q;
    l.p1 = u;
    l.p2 = v;
    const dvec3 n = glm::cross(dvec3(u), dvec3(v));
    l.area = float(glm::length(n));
    l.normal = vec3(glm::normalize(n));
    const dvec3 w = n / glm::dot(n, n);
    l.dualU = vec3(glm::cross(dvec3(v), w));
    l.dualV = vec3(glm::cross(w, dvec3(u)));
    setPlanarSlackLengths(l);
    return l;
}

inline LightData makeTriangleLight(const vec3& a, const vec3& b, const vec3& c)
{
    LightData l = makeQuadLight(a, b - a, c - a);
    l.shape = LightShape::Triangle;
    l.area = float(0.5 * glm::length(glm::cross(dvec3(b - a), dvec3(c - a))));
    return l;
}

inline LightData makeSphereLight(const vec3& center, float radius)
{
    LightData l{};
    l.shape = LightShape::Sphere;
    l.material = 0;
    l.p0 = center;
    l.radius = radius;
    l.area = float(4.0 * 3.14159265358979323846 * double(radius) * double(radius));
    return l;
}

/// A sphere of radius 1 whose centre is seen from the origin at sin^2(theta_max) = sin2, along `direction`.
inline LightData sphereSeenAt(float sin2, const vec3& direction)
{
    const double d = 1.0 / std::sqrt(double(sin2));
    return makeSphereLight(vec3(d * glm::normalize(dvec3(direction))), 1.0f);
}

/// cornell-box-lights' back-wall strip (355 x 10) cut along its diagonal: a sliver with a 1.6 degree corner.
inline LightData sliverTriangle()
{
    return makeTriangleLight({455, 100, 554}, {100, 100, 554}, {100, 110, 554});
}

struct LightCase
{
    std::string name;
    LightData light;
    vec3 p; // shading point
    /// Most of the light's solid angle seen from p lies within a few degrees of the light's plane, where its
    /// pdf peaks (r^2 / cos) and ends at the outline: no grid of directions resolves that well.
    bool grazing = false;
};

inline std::ostream& operator<<(std::ostream& out, const LightCase& c) { return out << c.name; }

/// Quads and triangles: overhead, near field (the point almost touching the light), grazing (the point
/// almost in the light's plane), seen from the back, and a general orientation (pbrt-v4's sampling test).
inline std::vector<LightCase> planarCases()
{
    return {
        {"quad overhead", makeQuadLight({-0.5f, -0.5f, 1.0f}, {0, 1, 0}, {1, 0, 0}), {0.1f, 0.2f, 0.0f}},
        {"quad near field", makeQuadLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {0.3f, 0.6f, 0.02f}, true},
        {"quad grazing", makeQuadLight({1, -1, 0.05f}, {2, 0, 0}, {0, 2, 0}), {0, 0, 0}, true},
        {"quad from behind", makeQuadLight({-1, -1, 2}, {2, 0, 0}, {0, 2, 0}), {0.4f, -0.3f, 0.0f}},
        {"quad tilted", makeQuadLight({4, 1, 1}, {2, 0, -3}, {0, 3, 0}), {0.5f, -0.4f, 0.7f}},
        {"triangle large", makeTriangleLight({4, 1, 1}, {-10, 3, 3}, {-2, -8, 10}), {0.5f, -0.4f, 0.7f}, true},
        {"triangle near field", makeTriangleLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {0.25f, 0.25f, 0.01f}, true},
        {"triangle grazing", makeTriangleLight({2, -1, 0.03f}, {3, 1, 0.03f}, {2, 1, 0.03f}), {0, 0, 0}, true},
    };
}

/// Spheres seen from outside, from the near field (a cone of 65 degrees) down to a small one (0.6 degrees).
inline std::vector<LightCase> sphereOutsideCases()
{
    const vec3 dir(0.3f, 1.0f, -0.2f);
    return {
        {"sphere near (sin^2 = 0.826)", sphereSeenAt(0.826f, dir), vec3(0.0f)},
        {"sphere mid (sin^2 = 0.25)", sphereSeenAt(0.25f, dir), vec3(0.0f)},
        {"sphere far (sin^2 = 1e-2)", sphereSeenAt(1e-2f, dir), vec3(0.0f)},
        {"sphere small (sin^2 = 1e-4)", sphereSeenAt(1e-4f, dir), vec3(0.0f)},
    };
}

/// Spheres around the point: area sampling (RTTROYL's glass sphere seen from inside it).
inline std::vector<LightCase> sphereInsideCases()
{
    return {
        {"inside sphere, half radius", makeSphereLight({0.2f, 0.5f, 0.3f}, 1.0f), {0.2f, 0.0f, 0.3f}},
        {"inside sphere, near the surface", makeSphereLight({1, 2, 3}, 2.0f), {1.0f, 2.0f, 4.9f}},
    };
}
} // namespace rt::test
