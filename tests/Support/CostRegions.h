// The two regions a heatmap test compares (--heatmap, Render/CostMap.h): the pixels that see a sphere, and the
// pixels around it that see the rest of the scene. A pixel belongs to the sphere when its centre's camera ray
// passes within 0.7 radii of the sphere's centre, to the surroundings when it passes farther than 1.5 radii, in
// front of the camera; the rim between is left out (a pixel there sees both).
#pragma once

#include "Render/CostMap.h"
#include "Scene/Scene.h"

namespace rt::test
{
struct CostRegions
{
    double sphere = 0.0; // the regions' means of the cost per sample, with their highest and lowest tenths left
    double surroundings = 0.0; // out: a thread preempted while it traced one pixel is not that pixel's cost
    std::size_t spherePixels = 0;
    std::size_t surroundingPixels = 0;
};

/// Book 3's final scene and its glass sphere, in the scene's own coordinates (placedScene): the heatmap tests'
/// case, where a path through the glass keeps its throughput, so Russian roulette keeps it longer than the walls'.
inline constexpr const char* kGlassScene = "rtrol-cornell-glass";
inline const vec3 kGlassCenter{190.0f, 90.0f, 190.0f};
inline constexpr float kGlassRadius = 90.0f;

/// `map` rendered of `scene` (its camera, the map's size) split by the sphere of `center` and `radius` (world).
CostRegions costAroundSphere(const CostMap& map, const Scene& scene, const vec3& center, float radius);
} // namespace rt::test
