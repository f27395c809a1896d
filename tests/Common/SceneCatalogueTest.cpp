// The scene catalogue (Scenes/Catalogue.h): every id builds a valid scene from the assets beside the test
// binary, unknown ids are reported with the list of known ones, and the light lists the samplers draw from
// hold what shared/spec/scenes.md describes.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "Assets/AssetPaths.h"
#include "Error.h"
#include "Scenes/Catalogue.h"
#include "Support/CubeObj.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
using shader::LightShape;

/// Emitting primitives of a scene, counted from its instances (what SceneBuilder::finish must have listed).
std::size_t countEmitters(const Scene& s)
{
    std::size_t count = 0;
    for (const InstanceDesc& inst : s.instances)
    {
        const GroupDesc& g = s.groups.at(inst.group);
        for (const QuadDesc& q : g.quads)
            count += s.isEmissive(q.material) ? 1 : 0;
        for (const SphereDesc& sp : g.spheres)
            count += s.isEmissive(sp.material) ? 1 : 0;
        for (const MeshRef& ref : g.meshes)
        {
            const MeshData& mesh = s.meshes.at(ref.mesh);
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
                count += s.isEmissive(mesh.triangleMaterials.empty() ? ref.material : mesh.triangleMaterials[t]) ? 1 : 0;
        }
    }
    return count;
}

vec3 emission(const Scene& s, const LightData& l)
{
    return s.textures.at(s.materials.at(l.material).emissionTexture).color0;
}

TEST(SceneCatalogue, EveryIdBuildsAndValidates)
{
    // Textures and meshes come from the binary's own asset folder (build/bin/Assets); a missing one is an
    // AssetError naming it, which fails here with its message.
    ASSERT_FALSE(sceneCatalogue().empty());
    for (const SceneInfo& info : sceneCatalogue())
    {
        SCOPED_TRACE(info.id + " (assets in " + assetRoot().string() + ")");
        try
        {
            const Scene s = makeScene(info.id);
            EXPECT_EQ(s.id, info.id);
            EXPECT_NO_THROW(s.validate());
            EXPECT_GT(s.primitiveCount(), 0u);
            EXPECT_FALSE(s.bounds().empty());
            EXPECT_FALSE(info.title.empty());
            EXPECT_FALSE(info.source.empty());
        }
        catch (const Error& e)
        {
            ADD_FAILURE() << e.what();
        }
    }
}

TEST(SceneCatalogue, IdsAreUniqueAndFound)
{
    std::set<std::string> ids;
    for (const SceneInfo& info : sceneCatalogue())
    {
        EXPECT_TRUE(ids.insert(info.id).second) << "duplicate id " << info.id;
        EXPECT_EQ(findScene(info.id), &info);
    }
    EXPECT_EQ(findScene("no-such-scene"), nullptr);
}

TEST(SceneCatalogue, UnknownIdIsASceneErrorListingTheKnownIds)
{
    try
    {
        makeScene("cornell-box-light"); // a plausible typo
        FAIL() << "no SceneError";
    }
    catch (const SceneError& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find("'cornell-box-light'"), std::string::npos) << message;
        for (const SceneInfo& info : sceneCatalogue())
            EXPECT_NE(message.find(info.id), std::string::npos) << info.id << " missing from: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

TEST(SceneCatalogue, LightListHoldsEveryEmitter)
{
    // Emitters first, with their material; then sampling targets (no material). Planar lights carry the unit
    // normal of u x v and their area; spheres their radius.
    for (const SceneInfo& info : sceneCatalogue())
    {
        SCOPED_TRACE(info.id);
        const Scene s = makeScene(info.id);
        std::size_t emitters = 0;
        bool targetsStarted = false;
        for (const LightData& l : s.lights)
        {
            if (l.material == kNoIndex)
                targetsStarted = true;
            else
            {
                EXPECT_FALSE(targetsStarted) << "an emitter after a sampling target";
                EXPECT_TRUE(s.isEmissive(l.material));
                ++emitters;
            }
            if (l.shape == LightShape::Sphere)
                EXPECT_GT(l.radius, 0.0f);
            else
            {
                const dvec3 n = glm::cross(dvec3(l.p1), dvec3(l.p2));
                const double area = glm::length(n) * (l.shape == LightShape::Triangle ? 0.5 : 1.0);
                EXPECT_NEAR(l.area, area, 1e-5 * area);
                EXPECT_NEAR(glm::distance(dvec3(l.normal), n / glm::length(n)), 0.0, 1e-5);
            }
        }
        EXPECT_EQ(emitters, countEmitters(s));
    }
}

TEST(SceneCatalogue, CornellBoxLightsHasNineStripsAndThreeSpheres)
{
    // scenes.md: 9 strips (15,15,15) on the back wall facing the camera (-z), then spheres r50 red, blue, green.
    const Scene s = placedScene("cornell-box-lights");
    ASSERT_EQ(s.lights.size(), 12u);
    for (int i = 0; i < 9; ++i)
    {
        const LightData& l = s.lights[i];
        ASSERT_EQ(l.shape, LightShape::Quad) << i;
        EXPECT_EQ(l.normal, vec3(0, 0, -1)) << i;
        EXPECT_FLOAT_EQ(l.area, 355.0f * 10.0f) << i;
        EXPECT_EQ(emission(s, l), vec3(15.0f)) << i;
    }
    const vec3 centers[3] = {{530, 530, 277}, {277, 530, 277}, {30, 530, 277}};
    const vec3 colours[3] = {{20.0f, 0.7f, 0.7f}, {0.7f, 0.7f, 20.0f}, {0.7f, 20.0f, 0.7f}};
    for (int i = 0; i < 3; ++i)
    {
        const LightData& l = s.lights[9 + i];
        ASSERT_EQ(l.shape, LightShape::Sphere) << i;
        EXPECT_EQ(l.p0, centers[i]);
        EXPECT_EQ(l.radius, 50.0f);
        EXPECT_EQ(emission(s, l), colours[i]);
    }
}

TEST(SceneCatalogue, TriangleLightsHasTheCeilingHalvesTheSliverAndTheEmittingMesh)
{
    // scenes.md: the book-3 ceiling light as two triangles (15), facing down; a 300 x 3 sliver (8) on the
    // back wall at y = 400 facing the camera; every triangle of the mesh (2), 150 tall on the floor about
    // (278, 278).
    const Scene s = placedScene("triangle-lights");
    for (const LightData& l : s.lights)
        ASSERT_EQ(l.shape, LightShape::Triangle);
    ASSERT_GT(s.lights.size(), 3u + 1000u); // the bunny has 3,674 triangles
    for (int i = 0; i < 2; ++i)
    {
        EXPECT_EQ(s.lights[i].normal, vec3(0, -1, 0)) << i;
        EXPECT_FLOAT_EQ(s.lights[i].area, 0.5f * 130.0f * 105.0f) << i;
        EXPECT_EQ(s.lights[i].p0.y, 554.0f) << i;
        EXPECT_EQ(emission(s, s.lights[i]), vec3(15.0f)) << i;
    }
    const LightData& sliver = s.lights[2];
    EXPECT_EQ(sliver.normal, vec3(0, 0, -1));
    EXPECT_FLOAT_EQ(sliver.area, 0.5f * 300.0f * 3.0f);
    EXPECT_EQ(sliver.p0, vec3(428, 400, 554));
    EXPECT_EQ(emission(s, sliver), vec3(8.0f));
    Aabb mesh;
    for (std::size_t i = 3; i < s.lights.size(); ++i)
    {
        const LightData& l = s.lights[i];
        EXPECT_EQ(emission(s, l), vec3(2.0f)) << i;
        for (const vec3& corner : {l.p0, l.p0 + l.p1, l.p0 + l.p2})
            mesh.expand(corner);
    }
    EXPECT_NEAR(mesh.min.y, 0.0f, 1e-3f);
    EXPECT_NEAR(mesh.max.y, 150.0f, 1e-3f);
    EXPECT_NEAR(0.5f * (mesh.min.x + mesh.max.x), 278.0f, 1e-3f);
    EXPECT_NEAR(0.5f * (mesh.min.z + mesh.max.z), 278.0f, 1e-3f);
    EXPECT_EQ(s.defaults.estimator, shader::Estimator::NeeMis);
    EXPECT_TRUE(s.defaults.unidirectionalLight);
}

TEST(SceneCatalogue, CornellGlassSamplesTheLightThenTheGlass)
{
    // RTTROYL §12.5: the ceiling light (facing down) and the glass sphere, a sampling target that emits nothing.
    const Scene s = placedScene("rtrol-cornell-glass");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].shape, LightShape::Quad);
    EXPECT_NE(s.lights[0].material, kNoIndex);
    EXPECT_EQ(s.lights[0].normal, vec3(0, -1, 0));
    EXPECT_FLOAT_EQ(s.lights[0].area, 130.0f * 105.0f);
    EXPECT_EQ(s.lights[1].shape, LightShape::Sphere);
    EXPECT_EQ(s.lights[1].material, kNoIndex);
    EXPECT_EQ(s.lights[1].p0, vec3(190, 90, 190));
    EXPECT_EQ(s.lights[1].radius, 90.0f);
}

TEST(SceneCatalogue, BookOneScenesHaveNoLights)
{
    int checked = 0;
    for (const SceneInfo& info : sceneCatalogue())
        if (info.id.rfind("rtow-", 0) == 0)
        {
            EXPECT_TRUE(makeScene(info.id).lights.empty()) << info.id;
            ++checked;
        }
    EXPECT_EQ(checked, 3);
}

TEST(SceneCatalogue, OptionsReachTheScene)
{
    // white-spheres scales with --count; the mesh scenes load --mesh, and report a missing one by its path.
    const Scene few = makeScene("white-spheres", {.count = 10});
    std::size_t spheres = 0;
    for (const InstanceDesc& inst : few.instances)
        spheres += few.groups[inst.group].spheres.size();
    EXPECT_EQ(spheres, 10u);
    try
    {
        makeScene("mesh-in-one-weekend", {.meshPath = "meshes/no-such-mesh.obj"});
        FAIL() << "no AssetError";
    }
    catch (const AssetError& e)
    {
        EXPECT_NE(std::string(e.what()).find("meshes/no-such-mesh.obj"), std::string::npos) << e.what();
    }
}

TEST(SceneCatalogue, SceneInfoSaysWhichOptionsEachSceneReads)
{
    // The command line warns that --count or --mesh is ignored from SceneInfo::takes: it must be the truth.
    // A count of 7 and a one-triangle mesh change exactly the scenes that say they read them.
    const test::ScratchDir dir;
    const std::string triangle = dir.write("one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string();
    for (const SceneInfo& info : sceneCatalogue())
    {
        const Scene plain = makeScene(info.id, {});
        const Scene counted = makeScene(info.id, {.count = 7});
        EXPECT_EQ(counted.primitiveCount() != plain.primitiveCount(), (info.takes & kTakesCount) != 0u) << info.id;
        const Scene meshed = makeScene(info.id, {.meshPath = triangle});
        EXPECT_EQ(meshed.primitiveCount() != plain.primitiveCount(), (info.takes & kTakesMesh) != 0u) << info.id;
    }
}

/// World-space bounds of every instance of a group that holds a mesh loaded from `meshName`.
Aabb placedMeshBounds(const Scene& scene, const std::string& meshName)
{
    Aabb box;
    for (const InstanceDesc& inst : scene.instances)
        for (const MeshRef& ref : scene.groups[inst.group].meshes)
            if (scene.meshes[ref.mesh].name == meshName)
                box.expand(inst.worldFromObject.bounds(scene.meshes[ref.mesh].bounds()));
    return box;
}

TEST(SceneCatalogue, TheMeshScenesPlaceACubeAlikeWhereverAndHoweverLargeItWasModelled)
{
    // Issue 13: a cube of +-1e7, a unit cube at 1e7, a 0.5-wide cube at 1e7 and a 1e-7 cube must land where
    // the unit cube at the origin lands, in every scene that takes --mesh (both engines build from this).
    const test::ScratchDir dir;
    const auto cube = [&](double centre, double edge) {
        return dir.write("cube.obj", test::cubeObj(centre, edge)).string();
    };
    for (const char* id : {"mesh-in-one-weekend", "cornell-box-and-mesh", "triangle-lights"})
    {
        const Aabb reference = placedMeshBounds(makeScene(id, {.meshPath = cube(0.0, 1.0)}), "cube.obj");
        ASSERT_GT(reference.extent().y, 0.0f) << id;
        const float tolerance = 1e-5f * maxComponent(reference.extent());
        for (const auto& [centre, edge] : {std::pair{0.0, 2e7}, {1e7, 1.0}, {1e7, 0.5}, {0.0, 1e-7}})
        {
            const Aabb placed = placedMeshBounds(makeScene(id, {.meshPath = cube(centre, edge)}), "cube.obj");
            for (int k = 0; k < 3; ++k)
            {
                EXPECT_NEAR(placed.min[k], reference.min[k], tolerance) << id << ": edge " << edge << " at " << centre;
                EXPECT_NEAR(placed.max[k], reference.max[k], tolerance) << id << ": edge " << edge << " at " << centre;
            }
        }
    }
}

TEST(SceneCatalogue, FurnaceIsAClosedEmissiveSphere)
{
    // Every surface must emit and reflect alike for Le / (1 - a) to hold (research notes §4.5).
    const Scene s = makeFurnace(0.25f, 2.0f);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].shape, LightShape::Sphere);
    const vec3 eye = s.camera.lookFrom;
    EXPECT_LT(glm::distance(eye, s.lights[0].p0), s.lights[0].radius) << "the camera must be inside";
    for (const MaterialData& m : s.materials)
    {
        EXPECT_EQ(m.type, MaterialType::Lambertian);
        EXPECT_EQ(s.textures.at(m.albedoTexture).color0, vec3(0.25f));
        EXPECT_EQ(s.textures.at(m.emissionTexture).color0, vec3(2.0f));
    }
}
} // namespace
} // namespace rt

namespace rt
{
TEST(SceneCatalogue, FresnelOptionSetsEveryDielectric)
{
    const auto models = [](const Scene& s) {
        std::vector<shader::FresnelModel> out;
        for (const MaterialData& m : s.materials)
            if (m.type == MaterialType::Dielectric)
                out.push_back(m.fresnel);
        return out;
    };
    SceneOptions exact;
    exact.fresnel = shader::FresnelModel::Exact;
    const auto books = models(makeScene("rtow-final"));
    const auto chosen = models(makeScene("rtow-final", exact));
    ASSERT_FALSE(books.empty());
    EXPECT_EQ(books, std::vector<shader::FresnelModel>(books.size(), shader::FresnelModel::Schlick));
    EXPECT_EQ(chosen, std::vector<shader::FresnelModel>(books.size(), shader::FresnelModel::Exact));
}
} // namespace rt

namespace rt
{
TEST(SceneCatalogue, RoughnessScaleMultipliesEveryMicrofacetAlphaUpToOne)
{
    // glossy-cornell holds all three microfacet materials (conductor alpha 0.1, glTF roughness 0.3 -> alpha 0.09,
    // rough dielectric alpha 0.05) beside diffuse ones.
    const Scene own = makeScene("glossy-cornell");
    SceneOptions doubled;
    doubled.roughnessScale = 2.0f;
    SceneOptions far;
    far.roughnessScale = 50.0f;
    const Scene twice = makeScene("glossy-cornell", doubled);
    const Scene matte = makeScene("glossy-cornell", far);
    ASSERT_EQ(own.materials.size(), twice.materials.size());
    int microfacet = 0;
    for (std::size_t i = 0; i < own.materials.size(); ++i)
    {
        const MaterialData& m = own.materials[i];
        if (!isMicrofacetMaterial(m.type))
        {
            EXPECT_EQ(twice.materials[i].alphaX, m.alphaX) << i;
            continue;
        }
        ++microfacet;
        EXPECT_FLOAT_EQ(twice.materials[i].alphaX, 2.0f * m.alphaX) << i;
        EXPECT_FLOAT_EQ(twice.materials[i].alphaY, 2.0f * m.alphaY) << i;
        EXPECT_EQ(matte.materials[i].alphaX, 1.0f) << i; // 50 x 0.05 and more: kept at 1
        EXPECT_EQ(matte.materials[i].alphaY, 1.0f) << i;
    }
    EXPECT_EQ(microfacet, 3);
    EXPECT_TRUE(own.hasMicrofacetMaterial());
    EXPECT_FALSE(makeScene("cornell-box-lights").hasMicrofacetMaterial());
    matte.validate();
}
} // namespace rt

namespace rt
{
TEST(SceneCatalogue, AnUnknownIdNamesTheNearestOneWhenItIsATypo)
{
    const auto message = [](const std::string& id) {
        try
        {
            makeScene(id);
        }
        catch (const SceneError& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("cornel-box-lights").find("did you mean 'cornell-box-lights'?"), std::string::npos);
    EXPECT_NE(message("veach_mis").find("did you mean 'veach-mis'?"), std::string::npos);
    const std::string far = message("nonsense");
    EXPECT_NE(far.find("unknown scene 'nonsense' (known: "), std::string::npos) << far;
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}
} // namespace rt
