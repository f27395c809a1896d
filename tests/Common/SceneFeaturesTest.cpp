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
} // namespace
} // namespace rt
