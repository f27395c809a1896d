// Builders of the catalogue's scenes, one file per source (book or thesis). Internal to Scenes/.
#pragma once

#include <cstdint>

#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"

namespace rt::scenes
{
// Ray Tracing in One Weekend
Scene rtowDefault(const SceneOptions&);
Scene rtowCameraTest(const SceneOptions&);
Scene rtowFinal(const SceneOptions&);
// Ray Tracing: The Next Week
Scene rtnwMotionBlur(const SceneOptions&);
Scene rtnwCheckerSpheres(const SceneOptions&);
Scene rtnwEarth(const SceneOptions&);
Scene rtnwPerlinSpheres(const SceneOptions&);
Scene rtnwQuads(const SceneOptions&);
Scene rtnwSimpleLight(const SceneOptions&);
Scene rtnwCornellBox(const SceneOptions&);
Scene rtnwCornellSmoke(const SceneOptions&);
Scene rtnwFinal(const SceneOptions&);
// Ray Tracing: The Rest of Your Life
Scene rtrolCornellBox(const SceneOptions&);
Scene rtrolCornellMirror(const SceneOptions&);
Scene rtrolCornellGlass(const SceneOptions&);
// Thesis
Scene whiteSpheres(const SceneOptions&);
Scene cornellBoxLights(const SceneOptions&);
// Thesis GPU framework
Scene cubeAndSpheres(const SceneOptions&);
Scene planetsInOneWeekend(const SceneOptions&);
Scene meshInOneWeekend(const SceneOptions&);
Scene cornellBoxAndMesh(const SceneOptions&);
// Light-sampling tests
Scene furnace(const SceneOptions&);
Scene rectLightCloseup(const SceneOptions&);
Scene manyLights(const SceneOptions&);
Scene lampRoom(const SceneOptions&);
Scene sphereLightCloseup(const SceneOptions&);
Scene triangleLights(const SceneOptions&);

Scene veachMis(const SceneOptions&);
Scene glossyCornell(const SceneOptions&);

// Pieces several sources share.
inline const vec3 kSky{0.70f, 0.80f, 1.00f};
void setGradientSky(Scene& scene); // white -> (0.5, 0.7, 1.0), RTIOW §4
void setConstantBackground(Scene& scene, const vec3& color);
/// RTIOW §14's field of small random spheres (a, b in -11..10). With `moving`, the Lambertian ones rise by
/// rnd[0, 0.5] over the shutter (RTTNW §2).
void randomSphereField(SceneBuilder& b, std::uint32_t group, std::uint32_t seed, bool moving);
/// RTIOW §14's ground and camera (from (13,2,3) at 0, vfov 20, focus 10, 16:9).
void finalSceneCamera(Scene& scene, float defocusAngle);
/// The five book-2 Cornell box walls (without light) in RTTNW §7's orientation.
void rtnwCornellWalls(SceneBuilder& b, std::uint32_t group);
/// The five book-3 walls (normals facing into the box, RTTROYL §12); the floor of material `floor` when given.
void rtrolCornellWalls(SceneBuilder& b, std::uint32_t group, std::uint32_t floor = kNoIndex);
void cornellCamera(Scene& scene);
/// A mesh loaded by loadObj (so already in MeshFit.h's fit frame: floor centre at the origin, fit height 1)
/// placed by an instance: scaled by `height`, rotated about y, its floor centre moved to `base`. The fit was
/// done in double by the loader; this transform is well-conditioned for any mesh the loader accepted.
/// Returns the new group.
std::uint32_t placeMesh(SceneBuilder& b, std::uint32_t mesh, std::uint32_t material, const vec3& base, float height,
                        float rotateYDegrees = 0.0f);
} // namespace rt::scenes
