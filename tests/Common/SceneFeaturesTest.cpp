// SceneFeatures: what each scene uses, which decides the code the engines leave out (issue 11). A feature
// wrongly absent would render a scene without a part of it; wrongly present only costs time, so the
// catalogue cases check both directions.
#include <gtest/gtest.h>

#include "Scene/SceneBuilder.h"
#include "Scene/SceneFeatures.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
TEST(SceneFeatures, CatalogueScenesHaveWhatTheBooksPutInThem)
{
    const SceneFeatures glass = featuresOf(makeScene("rtrol-cornell-glass"));
    EXPECT_TRUE(glass.quads && glass.spheres && glass.dielectric && glass.lambertian && glass.diffuseLight);
    EXPECT_TRUE(glass.transformedInstances) << "the rotated box";
    EXPECT_TRUE(glass.quadEmitters);
    EXPECT_FALSE(glass.media || glass.motionBlur || glass.meshes || glass.metal || glass.textures() || glass.thinLens);
    EXPECT_TRUE(glass.blackBackground);

    const SceneFeatures motion = featuresOf(makeScene("rtnw-motion-blur"));
    EXPECT_TRUE(motion.motionBlur && motion.spheres && motion.checkerTextures);
    EXPECT_FALSE(motion.emitters());
    EXPECT_EQ(motion.background, BackgroundType::Constant) << "book 2's constant sky colour";
    EXPECT_FALSE(motion.blackBackground);

    const SceneFeatures smoke = featuresOf(makeScene("rtnw-cornell-smoke"));
    EXPECT_TRUE(smoke.media);
    EXPECT_FALSE(smoke.motionBlur);

    EXPECT_TRUE(featuresOf(makeScene("rtnw-earth")).imageTextures);
    EXPECT_TRUE(featuresOf(makeScene("rtnw-perlin-spheres")).noiseTextures);
    const SceneFeatures book1 = featuresOf(makeScene("rtow-final"));
    EXPECT_TRUE(book1.thinLens && book1.metal && book1.dielectric);
    EXPECT_EQ(book1.background, BackgroundType::Gradient);
    const SceneFeatures mesh = featuresOf(makeScene("cornell-box-and-mesh"));
    EXPECT_TRUE(mesh.meshes);
    EXPECT_TRUE(featuresOf(makeScene("triangle-lights")).triangleEmitters);
    EXPECT_TRUE(featuresOf(makeScene("sphere-light-closeup")).sphereEmitters);
}

TEST(SceneFeatures, UnusedMaterialsAndTexturesDoNotCount)
{
    SceneBuilder b("features");
    const std::uint32_t used = b.lambertian(vec3(0.5f));
    b.lambertianTextured(b.checker(1.0f, vec3(0.0f), vec3(1.0f))); // defined, never placed
    b.metal(vec3(0.8f), 0.1f); // defined, never placed
    b.sphere(b.world(), vec3(0.0f), 1.0f, used);
    const SceneFeatures f = featuresOf(b.finish());
    EXPECT_TRUE(f.spheres && f.lambertian);
    EXPECT_FALSE(f.metal || f.checkerTextures || f.quads || f.transformedInstances || f.emitters());
    EXPECT_EQ(f.describe(), "spheres lambertian black-background");
    EXPECT_EQ(f.toJson()["spheres"], true);
    EXPECT_EQ(f.toJson()["metal"], false);
}
/// A ground sphere of `radius` whose top touches y = 0 (a medium's boundary if `medium`), through an instance
/// scaled by `scale`, under a 6x6 light 20 units up, seen from 1.5 units above it: the region rays start from
/// is 21.7 units across, so the ground is huge above a radius of 21.7 kHugeSphereTolerance / kSphereRootError
/// = 4,550.
Scene groundUnderLight(float radius, float scale = 1.0f, bool medium = false)
{
    SceneBuilder b("ground");
    const std::uint32_t ground = b.group("ground");
    if (medium)
        b.sphereMedium(ground, {0.0f, -radius / scale, 0.0f}, radius / scale, 0.01f, vec3(0.5f));
    else
        b.sphere(ground, {0.0f, -radius / scale, 0.0f}, radius / scale, b.lambertian(vec3(0.5f)));
    b.instance(ground, Transform::scale(vec3(scale)));
    b.quad(b.world(), {-3.0f, 20.0f, -3.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 6.0f}, b.diffuseLight(vec3(5.0f)));
    b.scene().camera.lookFrom = {0.0f, 1.5f, 3.0f};
    b.scene().camera.lookAt = vec3(0.0f);
    return b.finish();
}

// Only where float's c of the ray-sphere quadratic would misplace hits by more than 1e-4 of the scene do the GPU's
// sphere tests pay for the exact c: the threshold from both sides, an instance's scale, a medium's boundary, a
// lone planet under the camera, and none of the catalogue's scenes (rtow's radius-1000 ground included).
TEST(SceneFeatures, HugeSpheresAreThoseFloatsCPlacesTooCoarsely)
{
    EXPECT_FALSE(featuresOf(groundUnderLight(4000.0f)).hugeSpheres);
    EXPECT_TRUE(featuresOf(groundUnderLight(5500.0f)).hugeSpheres);
    EXPECT_TRUE(featuresOf(groundUnderLight(1e6f)).hugeSpheres);
    EXPECT_TRUE(featuresOf(groundUnderLight(6000.0f, 6.0f)).hugeSpheres) << "1000 object units, scaled 6x";
    EXPECT_FALSE(featuresOf(groundUnderLight(4000.0f, 0.5f)).hugeSpheres);
    EXPECT_TRUE(featuresOf(groundUnderLight(1e6f, 1.0f, true)).hugeSpheres) << "a medium's boundary";
    EXPECT_FALSE(featuresOf(groundUnderLight(4000.0f, 1.0f, true)).hugeSpheres);
    EXPECT_NE(featuresOf(groundUnderLight(1e6f)).describe().find("huge-spheres"), std::string::npos);

    const auto lone = [](float radius, const vec3& camera) {
        SceneBuilder b("lone");
        b.sphere(b.world(), {0.0f, -radius, 0.0f}, radius, b.lambertian(vec3(0.5f)));
        b.scene().camera.lookFrom = camera;
        return featuresOf(b.finish()).hugeSpheres;
    };
    EXPECT_TRUE(lone(6.4e6f, {0.0f, 1.5f, 3.0f})) << "a planet seen from 3.4 units";
    EXPECT_FALSE(lone(1.0f, {0.0f, 1.5f, 3.0f}));
    EXPECT_FALSE(lone(1.0f, {0.0f, -1.0f, 0.0f})) << "the camera at the centre";

    for (const SceneInfo& info : sceneCatalogue())
        EXPECT_FALSE(featuresOf(makeScene(info.id)).hugeSpheres) << info.id;
}
} // namespace
} // namespace rt
