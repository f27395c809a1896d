#include "Sampling/LightBvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "Sampling/LightPower.h"
#include "Shared/LightBvh.h"

namespace rt
{
namespace
{
using glm::dvec3;

/// A cone of directions: every direction within theta of w (theta = pi: all of them).
struct DirectionCone
{
    dvec3 w{0.0, 0.0, 1.0};
    double theta = 0.0;
    bool empty = true;
};

DirectionCone wholeSphere() { return {dvec3(0.0, 0.0, 1.0), std::numbers::pi, false}; }

/// The smallest cone found by widening the wider of a and b towards the other (pbrt-v4 §12.6.1's union of
/// direction cones): both bound their directions, so the result bounds the union.
DirectionCone unite(const DirectionCone& a, const DirectionCone& b)
{
    if (a.empty)
        return b;
    if (b.empty)
        return a;
    const double between = std::acos(std::clamp(glm::dot(a.w, b.w), -1.0, 1.0));
    if (std::min(between + b.theta, std::numbers::pi) <= a.theta)
        return a;
    if (std::min(between + a.theta, std::numbers::pi) <= b.theta)
        return b;
    const double theta = 0.5 * (a.theta + between + b.theta);
    if (theta >= std::numbers::pi)
        return wholeSphere();
    const dvec3 k = glm::cross(a.w, b.w);
    if (glm::dot(k, k) < 1e-24)
        return wholeSphere();
    // Rotate a's axis towards b's by theta - theta_a (Rodrigues' formula; k is orthogonal to a.w).
    const double rotation = theta - a.theta;
    const dvec3 axis = glm::normalize(k);
    return {glm::normalize(a.w * std::cos(rotation) + glm::cross(axis, a.w) * std::sin(rotation)), theta, false};
}

/// What a node bounds while the tree is built (double; stored in float when the node is written).
struct Bounds
{
    dvec3 lo{std::numeric_limits<double>::infinity()};
    dvec3 hi{-std::numeric_limits<double>::infinity()};
    double power = 0.0;
    DirectionCone normals;
    double thetaE = 0.0;

    void add(const Bounds& b)
    {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
        power += b.power;
        normals = unite(normals, b.normals);
        thetaE = std::max(thetaE, b.thetaE);
    }
    dvec3 centre() const { return 0.5 * (lo + hi); }
    double surfaceArea() const
    {
        const dvec3 d = hi - lo;
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

Bounds lightBounds(const LightData& l, double power)
{
    Bounds b;
    b.power = power;
    b.thetaE = 0.5 * std::numbers::pi;
    const dvec3 p0(l.p0);
    auto include = [&](const dvec3& p) {
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
    };
    switch (l.shape)
    {
    case shader::LightShape::Sphere:
        include(p0 - dvec3(l.radius));
        include(p0 + dvec3(l.radius));
        b.normals = wholeSphere();
        break;
    case shader::LightShape::Quad:
        include(p0);
        include(p0 + dvec3(l.p1));
        include(p0 + dvec3(l.p2));
        include(p0 + dvec3(l.p1) + dvec3(l.p2));
        b.normals = {glm::normalize(dvec3(l.normal)), 0.0, false};
        break;
    case shader::LightShape::Triangle:
        include(p0);
        include(p0 + dvec3(l.p1));
        include(p0 + dvec3(l.p2));
        b.normals = {glm::normalize(dvec3(l.normal)), 0.0, false};
        break;
    }
    return b;
}

/// The surface area orientation heuristic of a candidate child (Estevez Conty & Kulla 2018, eq. 4; pbrt-v4
/// BVHLightSampler::EvaluateCost): power x M_Omega (the solid-angle measure of the directions the cones
/// can emit in) x box area, times the parent box's aspect in the split axis (thin slabs split across).
double splitCost(const Bounds& b, const Bounds& parent, int axis)
{
    const double thetaO = b.normals.theta;
    const double thetaW = std::min(thetaO + b.thetaE, std::numbers::pi);
    const double sinO = std::sin(thetaO);
    const double cosO = std::cos(thetaO);
    const double mOmega = 2.0 * std::numbers::pi * (1.0 - cosO) +
                          0.5 * std::numbers::pi *
                              (2.0 * thetaW * sinO - std::cos(thetaO - 2.0 * thetaW) - 2.0 * thetaO * sinO + cosO);
    const dvec3 d = parent.hi - parent.lo;
    const double aspect = std::max({d.x, d.y, d.z}) / d[axis];
    return b.power * mOmega * aspect * b.surfaceArea();
}

struct Item
{
    std::uint32_t light;
    Bounds bounds;
};

class Builder
{
public:
    explicit Builder(LightBvh& out) : m_out(out) {}

    std::uint32_t build(std::vector<Item>& items, std::size_t begin, std::size_t end, std::uint32_t parent,
                        std::uint32_t depth)
    {
        const auto index = static_cast<std::uint32_t>(m_out.nodes.size());
        m_out.nodes.emplace_back();
        Bounds all;
        for (std::size_t i = begin; i < end; ++i)
            all.add(items[i].bounds);
        if (end - begin == 1)
        {
            write(index, all, items[begin].light, parent, true);
            m_out.leaves[items[begin].light] = index;
            return index;
        }
        const std::size_t middle = partition(items, begin, end, all, depth);
        build(items, begin, middle, index, depth + 1);
        const std::uint32_t second = build(items, middle, end, index, depth + 1);
        write(index, all, second, parent, false);
        return index;
    }

private:
    static constexpr int kBuckets = 12;

    void write(std::uint32_t index, const Bounds& b, std::uint32_t child, std::uint32_t parent, bool leaf)
    {
        LightBvhNode& n = m_out.nodes[index];
        // The sphere through the box's corners, in float about the rounded centre: its radius grows by the
        // rounding of the centre and by 1e-6 of the coordinates' magnitude (16 float ulps: the rounding of a
        // point the engines compute on the light), so that it holds every such point.
        n.centre = vec3(b.centre());
        const double radius = 0.5 * glm::length(b.hi - b.lo);
        const double slack = glm::length(dvec3(n.centre) - b.centre()) + 1e-6 * (glm::length(b.centre()) + radius);
        n.radius2 = static_cast<float>((radius + slack) * (radius + slack));
        n.power = static_cast<float>(b.power);
        n.axis = vec3(b.normals.w);
        const bool whole = b.normals.theta >= std::numbers::pi;
        n.cosThetaO = whole ? -1.0f : static_cast<float>(std::cos(b.normals.theta + (leaf ? 0.0 : 1e-6)));
        n.cosThetaE = static_cast<float>(std::cos(b.thetaE));
        n.child = leaf ? shader::kLightBvhLeaf | child : child;
        n.parent = parent;
    }

    /// Reorders items[begin, end) into two non-empty halves and returns where the second starts.
    std::size_t partition(std::vector<Item>& items, std::size_t begin, std::size_t end, const Bounds& all,
                          std::uint32_t depth) const
    {
        dvec3 lo(std::numeric_limits<double>::infinity());
        dvec3 hi(-std::numeric_limits<double>::infinity());
        for (std::size_t i = begin; i < end; ++i)
        {
            lo = glm::min(lo, items[i].bounds.centre());
            hi = glm::max(hi, items[i].bounds.centre());
        }
        auto bucketOf = [&](const Item& item, int axis) {
            const double t = (item.bounds.centre()[axis] - lo[axis]) / (hi[axis] - lo[axis]);
            return std::clamp(static_cast<int>(t * kBuckets), 0, kBuckets - 1);
        };
        double bestCost = std::numeric_limits<double>::infinity();
        int bestAxis = -1;
        int bestSplit = 0;
        if (depth < 32) // deeper, median splits bound the depth
        {
            for (int axis = 0; axis < 3; ++axis)
            {
                if (!(hi[axis] > lo[axis]))
                    continue;
                std::array<Bounds, kBuckets> buckets{};
                for (std::size_t i = begin; i < end; ++i)
                    buckets[bucketOf(items[i], axis)].add(items[i].bounds);
                for (int split = 1; split < kBuckets; ++split)
                {
                    Bounds below, above;
                    for (int b = 0; b < split; ++b)
                        if (buckets[b].lo.x <= buckets[b].hi.x)
                            below.add(buckets[b]);
                    for (int b = split; b < kBuckets; ++b)
                        if (buckets[b].lo.x <= buckets[b].hi.x)
                            above.add(buckets[b]);
                    if (below.normals.empty || above.normals.empty)
                        continue;
                    const double cost = splitCost(below, all, axis) + splitCost(above, all, axis);
                    if (cost < bestCost)
                    {
                        bestCost = cost;
                        bestAxis = axis;
                        bestSplit = split;
                    }
                }
            }
        }
        if (bestAxis >= 0)
        {
            const auto middle = std::partition(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                                               [&](const Item& item) { return bucketOf(item, bestAxis) < bestSplit; });
            return std::size_t(middle - items.begin());
        }
        const dvec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(middle),
                         items.begin() + std::ptrdiff_t(end), [axis](const Item& a, const Item& b) {
                             return a.bounds.centre()[axis] < b.bounds.centre()[axis];
                         });
        return middle;
    }

    LightBvh& m_out;
};
} // namespace

LightBvh buildLightBvh(const Scene& scene)
{
    LightBvh bvh;
    const std::vector<double> powers = emitterPowers(scene);
    bvh.leaves.assign(powers.size(), kNoIndex);
    std::vector<Item> items;
    for (std::uint32_t i = 0; i < powers.size(); ++i)
        if (powers[i] > 0.0 && std::isfinite(powers[i]))
            items.push_back({i, lightBounds(scene.lights[i], powers[i])});
    if (items.empty())
    {
        LightBvhNode empty{};
        empty.child = shader::kLightBvhLeaf;
        empty.parent = kNoIndex;
        bvh.nodes.push_back(empty);
        return bvh;
    }
    bvh.nodes.reserve(2 * items.size() - 1);
    Builder(bvh).build(items, 0, items.size(), kNoIndex, 0);
    return bvh;
}
} // namespace rt
