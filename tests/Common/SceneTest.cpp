// SceneBuilder and Scene::validate: the vocabulary scenes are written in (boxes face outward, emitters reach
// the light list in world space) and the checks that keep a renderer from reading a broken description.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "Error.h"
#include "Scene/SceneBuilder.h"

namespace rt
{
namespace
{
/// Runs `f` and returns the SceneError's message, or fails.
template <typename F>
std::string sceneErrorOf(F&& f)
{
    try
    {
        f();
    }
    catch (const SceneError& e)
    {
        return e.what();
    }
    ADD_FAILURE() << "no SceneError";
    return {};
}

TEST(SceneBuilder, BoxQuadsFaceOutward)
{
    // The box between two corners (given in either order): six quads, one per face, each with its u x v
    // normal pointing away from the box's centre and lying on that face.
    for (const auto& [a, b] : {std::pair{vec3(1, 2, 3), vec3(4, 6, 5)}, std::pair{vec3(4, 6, 5), vec3(1, 2, 3)}})
    {
        SceneBuilder builder("box");
        const std::uint32_t g = builder.group("box");
        builder.box(g, a, b, builder.lambertian(vec3(0.5f)));
        const auto& quads = builder.scene().groups[g].quads;
        ASSERT_EQ(quads.size(), 6u);
        const vec3 lo = glm::min(a, b), hi = glm::max(a, b), centre = 0.5f * (lo + hi);
        std::set<std::pair<int, int>> faces; // (axis, sign)
        for (const QuadDesc& q : quads)
        {
            const vec3 n = glm::normalize(glm::cross(q.u, q.v));
            const vec3 mid = q.q + 0.5f * (q.u + q.v);
            EXPECT_GT(glm::dot(n, mid - centre), 0.0f) << "a quad faces inward";
            int axis = 0;
            for (int k = 1; k < 3; ++k)
                if (std::fabs(n[k]) > std::fabs(n[axis]))
                    axis = k;
            EXPECT_FLOAT_EQ(std::fabs(n[axis]), 1.0f) << "not axis-aligned";
            EXPECT_FLOAT_EQ(mid[axis], n[axis] > 0 ? hi[axis] : lo[axis]) << "not on the box's face";
            // The face is covered whole: its two edges span the box's extent on the other two axes.
            EXPECT_FLOAT_EQ(glm::length(glm::cross(q.u, q.v)),
                            (hi - lo)[(axis + 1) % 3] * (hi - lo)[(axis + 2) % 3]);
            faces.insert({axis, n[axis] > 0 ? 1 : -1});
        }
        EXPECT_EQ(faces.size(), 6u) << "a face is missing or doubled";
    }
}

TEST(SceneBuilder, FinishListsEmittersInWorldSpace)
{
    // An emitting quad and sphere in a group placed by translate * rotateY(90) * scale(2): the light list
    // holds them as the world sees them, found by transforming the object-space values here.
    SceneBuilder b("lights");
    const std::uint32_t g = b.group("lamps");
    const std::uint32_t light = b.diffuseLight(vec3(3.0f));
    b.quad(g, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, light); // faces -y
    b.sphere(g, {1, 0, 0}, 0.5f, light);
    b.sphere(g, {0, 0, 5}, 0.5f, b.lambertian(vec3(0.5f))); // not a light
    const Transform m = Transform::translate({10, 0, 0}) * Transform::rotateY(90.0f) * Transform::scale(vec3(2.0f));
    b.instance(g, m);
    b.samplingTargetSphere({0, 3, 0}, 1.0f);
    const Scene s = b.finish();
    ASSERT_EQ(s.lights.size(), 3u);
    const LightData& quad = s.lights[0];
    EXPECT_EQ(quad.shape, shader::LightShape::Quad);
    EXPECT_NEAR(glm::distance(quad.p0, vec3(10, 2, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(quad.p1, vec3(0, 0, -2)), 0.0f, 1e-5f); // +x, rotated by 90 about y, scaled by 2
    EXPECT_NEAR(glm::distance(quad.p2, vec3(2, 0, 0)), 0.0f, 1e-5f); // +z
    EXPECT_NEAR(glm::distance(quad.normal, vec3(0, -1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(quad.area, 4.0f, 1e-5f);
    const LightData& sphere = s.lights[1];
    EXPECT_EQ(sphere.shape, shader::LightShape::Sphere);
    EXPECT_NEAR(glm::distance(sphere.p0, vec3(10, 0, -2)), 0.0f, 1e-5f);
    EXPECT_NEAR(sphere.radius, 1.0f, 1e-6f);
    EXPECT_EQ(s.lights[2].material, kNoIndex); // the sampling target comes last
}

TEST(SceneBuilder, FinishRejectsAnEmittingSphereItCannotSample)
{
    SceneBuilder b("ellipsoid lamp");
    const std::uint32_t g = b.group("lamp");
    b.sphere(g, vec3(0.0f), 1.0f, b.diffuseLight(vec3(1.0f)));
    b.instance(g, Transform::scale({1, 2, 1}));
    EXPECT_NE(sceneErrorOf([&] { b.finish(); }).find("lamp"), std::string::npos);
}

/// A valid scene: one sphere group and one triangle-mesh group, both under the identity.
Scene minimalScene()
{
    SceneBuilder b("minimal");
    const std::uint32_t white = b.lambertian(vec3(0.5f));
    const std::uint32_t balls = b.group("balls");
    b.sphere(balls, vec3(0.0f), 1.0f, white);
    b.instance(balls, Transform::identity());
    MeshData tri;
    tri.name = "tri";
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};
    const std::uint32_t mesh = b.addMesh(tri);
    const std::uint32_t shapes = b.group("shapes");
    b.mesh(shapes, mesh, white);
    b.instance(shapes, Transform::identity());
    return b.finish();
}

TEST(SceneValidation, AcceptsAValidScene) { EXPECT_NO_THROW(minimalScene().validate()); }

TEST(SceneValidation, RejectsASphereGroupUnderNonUniformScale)
{
    // A sphere under a non-uniform scale is an ellipsoid, which neither engine intersects; a mirror too.
    for (const Transform& t : {Transform::scale({1, 2, 1}), Transform::rotateY(30.0f) * Transform::scale({1, 1, 3}),
                               Transform::scale({-1, 1, 1})})
    {
        Scene s = minimalScene();
        s.instances[0].worldFromObject = t;
        const std::string message = sceneErrorOf([&] { s.validate(); });
        EXPECT_NE(message.find("'balls'"), std::string::npos) << message;
    }
    // A uniform scale with a rotation and a translation is fine.
    Scene s = minimalScene();
    s.instances[0].worldFromObject =
        Transform::translate({1, 2, 3}) * Transform::rotateY(30.0f) * Transform::scale(vec3(2.0f));
    EXPECT_NO_THROW(s.validate());
}

TEST(SceneValidation, RejectsAMeshIndexOutOfRange)
{
    Scene s = minimalScene();
    s.meshes[0].indices = {0, 1, 3}; // 3 positions
    const std::string message = sceneErrorOf([&] { s.validate(); });
    EXPECT_NE(message.find("'tri'"), std::string::npos) << message;
    EXPECT_NE(message.find("index 3"), std::string::npos) << message;
    EXPECT_NE(message.find("'minimal'"), std::string::npos) << "the scene is named: " << message;
}

TEST(SceneValidation, RejectsAMeshGroupUnderAMirror)
{
    // A mirror would turn the triangle's normal (the edges' cross product) to its back: refused by name.
    for (const Transform& t : {Transform::scale({-1, 1, 1}), Transform::rotateY(30.0f) * Transform::scale({1, 1, -2})})
    {
        Scene s = minimalScene();
        s.instances[1].worldFromObject = t;
        const std::string message = sceneErrorOf([&] { s.validate(); });
        EXPECT_NE(message.find("'shapes'"), std::string::npos) << message;
        EXPECT_NE(message.find("mirroring"), std::string::npos) << message;
    }
    // Two mirrors make a rotation: fine.
    Scene s = minimalScene();
    s.instances[1].worldFromObject = Transform::scale({-1, -1, 1});
    EXPECT_NO_THROW(s.validate());
}

TEST(SceneValidation, RejectsOtherBrokenReferences)
{
    const auto expectRejected = [](const char* what, auto&& breakIt) {
        Scene s = minimalScene();
        breakIt(s);
        EXPECT_THROW(s.validate(), SceneError) << what;
    };
    expectRejected("missing material", [](Scene& s) { s.groups[0].spheres[0].material = 99; });
    expectRejected("zero radius", [](Scene& s) { s.groups[0].spheres[0].radius = 0.0f; });
    expectRejected("missing group", [](Scene& s) { s.instances[0].group = 7; });
    expectRejected("singular transform", [](Scene& s) { s.instances[1].worldFromObject = Transform::scale({1, 0, 1}); });
    expectRejected("partial triangle", [](Scene& s) { s.meshes[0].indices.push_back(0); });
    expectRejected("missing texture", [](Scene& s) { s.materials[0].albedoTexture = 42; });
    expectRejected("no instances", [](Scene& s) { s.instances.clear(); });
    expectRejected("light with a missing material", [](Scene& s) {
        s.lights.push_back({});
        s.lights.back().material = 9;
    });
}
} // namespace
} // namespace rt
