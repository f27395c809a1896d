// Light sampling for C++ callers in namespace rt: the sampler and the pdf are Shared/LightSampling.h, which
// the shaders compile too; the light records' constructors (host only) are here.
#pragma once

#include "Math/Math.h"
#include "Math/PlaneDuals.h"
#include "Sampling/Warps.h"
#include "Shared/HostDevice.h"
#include "Shared/LightSampling.h"

namespace rt
{
using shader::LightData;
using shader::LightShape;
using shader::LightSampler;

using shader::LightSample;
using shader::lightPdf;
using shader::sampleLight;

/// Sets the lengths of a quad or triangle light that planarHit's slack reads (LightData::p0Length and the
/// duals'), from its p0, dualU and dualV; call it after setting or changing those.
inline void setPlanarSlackLengths(LightData& l)
{
    l.p0Length = glm::length(l.p0);
    l.dualULength = glm::length(l.dualU);
    l.dualVLength = glm::length(l.dualV);
    l.dualSumLength = glm::length(l.dualU + l.dualV);
}

/// A quad light: the parallelogram q + a u + b v (a, b in [0, 1]), front along u x v.
inline LightData makeQuadLight(const vec3& q, const vec3& u, const vec3& v, std::uint32_t material)
{
    LightData l{};
    l.shape = LightShape::Quad;
    l.material = material;
    l.p0 = q;
    l.p1 = u;
    l.p2 = v;
    const vec3 n = glm::cross(u, v);
    l.area = glm::length(n);
    l.normal = n / l.area;
    const PlaneDuals duals = planeDuals(u, v);
    l.dualU = duals.ua;
    l.dualV = duals.vb;
    setPlanarSlackLengths(l);
    return l;
}

/// A triangle light with vertices a, b, c (front along (b - a) x (c - a)).
inline LightData makeTriangleLight(const vec3& a, const vec3& b, const vec3& c, std::uint32_t material)
{
    LightData l = makeQuadLight(a, b - a, c - a, material);
    l.shape = LightShape::Triangle;
    l.area *= 0.5f;
    return l;
}

/// A sphere light (or sampling target with material kNoIndex).
inline LightData makeSphereLight(const vec3& center, float radius, std::uint32_t material)
{
    LightData l{};
    l.shape = LightShape::Sphere;
    l.material = material;
    l.p0 = center;
    l.radius = radius;
    l.area = 4.0f * kPi * radius * radius;
    return l;
}

} // namespace rt
