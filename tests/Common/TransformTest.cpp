// Math/Transform.h: rotateY follows the books' rotate_y, composition reads right to left, normals use the
// inverse transpose, and uniformScale tells a rotation times a uniform scale (spheres stay spheres) from the
// rest.
#include <gtest/gtest.h>

#include <cmath>

#include "Math/Transform.h"

namespace rt
{
namespace
{
constexpr float kEps = 1e-6f; // a few float ulps of the unit-sized values below

void expectNear(const vec3& a, const vec3& b, float eps = kEps)
{
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Transform, RotateYNinetyMapsXToMinusZAndZToX)
{
    // RTTNW §8.2's rotate_y (object to world): x' = cos x + sin z, z' = -sin x + cos z.
    const Transform r = Transform::rotateY(90.0f);
    expectNear(r.vector({1, 0, 0}), {0, 0, -1});
    expectNear(r.vector({0, 0, 1}), {1, 0, 0});
    expectNear(r.vector({0, 1, 0}), {0, 1, 0});
}

TEST(Transform, RotateYMatchesTheBooksFormulaAtAnyAngle)
{
    for (float degrees : {-18.0f, 15.0f, 37.5f, 180.0f, 270.0f})
    {
        const double t = double(degrees) * 3.14159265358979323846 / 180.0;
        const vec3 p(0.3f, -1.2f, 2.5f);
        const vec3 expected(float(std::cos(t) * p.x + std::sin(t) * p.z), p.y,
                            float(-std::sin(t) * p.x + std::cos(t) * p.z));
        expectNear(Transform::rotateY(degrees).point(p), expected, 1e-5f);
    }
    EXPECT_TRUE(Transform::rotateY(0.0f).isIdentity()) << "a rotation by 0 must be exactly the identity";
}

TEST(Transform, ComposesRightToLeft)
{
    // worldFromObject = translate * rotate: rotate first, then translate.
    const Transform m = Transform::translate({10, 0, 0}) * Transform::rotateY(90.0f);
    expectNear(m.point({1, 0, 0}), {10, 0, -1});
    expectNear(m.vector({1, 0, 0}), {0, 0, -1}); // vectors ignore the translation
}

TEST(Transform, InverseUndoesTheTransform)
{
    const Transform m =
        Transform::translate({1, -2, 3}) * Transform::rotateY(33.0f) * Transform::scale({2.0f, 0.5f, 3.0f});
    const vec3 p(0.7f, -0.1f, 4.0f);
    expectNear(m.inverse().point(m.point(p)), p, 1e-5f);
    EXPECT_TRUE(Transform::identity().isIdentity());
}

TEST(Transform, NormalsStayPerpendicularToTransformedSurfaces)
{
    // Under a non-uniform scale the normal is not the transformed vector: it must stay perpendicular to the
    // transformed tangents of the surface.
    const Transform m = Transform::rotateY(20.0f) * Transform::scale({1.0f, 4.0f, 0.5f});
    const vec3 n = glm::normalize(vec3(1, 1, 1));
    const vec3 t1 = glm::cross(n, vec3(0, 0, 1)), t2 = glm::cross(n, t1);
    const vec3 nw = m.normal(n);
    EXPECT_NEAR(glm::dot(nw, m.vector(t1)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(nw, m.vector(t2)), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(nw, m.vector(n)), 0.0f) << "same side as the surface's outside";
}

TEST(Transform, BoundsHoldEveryTransformedCorner)
{
    const Aabb box(vec3(0.0f), vec3(1.0f, 2.0f, 1.0f));
    const Transform m = Transform::translate({5, 0, 0}) * Transform::rotateY(45.0f);
    const Aabb b = m.bounds(box);
    // The unit square footprint rotated by 45 degrees spans sqrt(2) in x and z.
    EXPECT_NEAR(b.max.x - b.min.x, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(b.max.z - b.min.z, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(b.max.y - b.min.y, 2.0f, 1e-6f);
    for (int corner = 0; corner < 8; ++corner)
    {
        const vec3 p = m.point({float(corner & 1), 2.0f * float((corner >> 1) & 1), float((corner >> 2) & 1)});
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_GE(p[k], b.min[k] - 1e-5f);
            EXPECT_LE(p[k], b.max[k] + 1e-5f);
        }
    }
}

TEST(UniformScale, FindsTheScaleOfARotationTimesAUniformScale)
{
    EXPECT_EQ(Transform::identity().uniformScale(), 1.0f);
    const auto s = (Transform::translate({3, 4, 5}) * Transform::rotateY(30.0f) * Transform::scale(vec3(2.5f))).uniformScale();
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(*s, 2.5f, 1e-5f);
    const auto small = (Transform::rotateY(-75.0f) * Transform::scale(vec3(1e-3f))).uniformScale();
    ASSERT_TRUE(small.has_value()) << "the tolerance is relative to the scale";
    EXPECT_NEAR(*small, 1e-3f, 1e-8f);
}

TEST(UniformScale, RejectsNonUniformScalesAndMirrors)
{
    EXPECT_FALSE(Transform::scale({1.0f, 2.0f, 1.0f}).uniformScale().has_value());
    EXPECT_FALSE((Transform::rotateY(30.0f) * Transform::scale({1.0f, 1.0f, 1.01f})).uniformScale().has_value());
    // A shear keeps every axis' length but not their angles.
    Transform shear;
    shear.m[1][0] = 0.5f;
    EXPECT_FALSE(shear.uniformScale().has_value());
    // Mirrors turn a sphere inside out: a negative axis, or a uniform negative scale (determinant < 0).
    EXPECT_FALSE(Transform::scale({-1.0f, 1.0f, 1.0f}).uniformScale().has_value());
    EXPECT_FALSE(Transform::scale(vec3(-2.0f)).uniformScale().has_value());
    EXPECT_FALSE(Transform::scale(vec3(0.0f)).uniformScale().has_value());
}

TEST(Transform, AxisRotationsAreRightHandedAndAgreeWithTheGeneralAxisForm)
{
    // Counter-clockwise seen from the positive axis: x -> y about z, y -> z about x, z -> x about y.
    expectNear(Transform::rotateZ(90.0f).point({1, 0, 0}), {0, 1, 0}, 1e-6f);
    expectNear(Transform::rotateX(90.0f).point({0, 1, 0}), {0, 0, 1}, 1e-6f);
    expectNear(Transform::rotateY(90.0f).point({0, 0, 1}), {1, 0, 0}, 1e-6f);
    // The exact sine/cosine forms against glm's Rodrigues form, at angles that are not multiples of 90.
    const vec3 p(0.3f, -1.7f, 2.2f);
    for (const float degrees : {-170.0f, -33.3f, 12.5f, 71.0f, 200.0f})
    {
        expectNear(Transform::rotateX(degrees).point(p), Transform::rotate({2, 0, 0}, degrees).point(p), 1e-5f);
        expectNear(Transform::rotateY(degrees).point(p), Transform::rotate({0, 0.5f, 0}, degrees).point(p), 1e-5f);
        expectNear(Transform::rotateZ(degrees).point(p), Transform::rotate({0, 0, 3}, degrees).point(p), 1e-5f);
    }
    EXPECT_TRUE(Transform::rotateX(0.0f).isIdentity());
    EXPECT_TRUE(Transform::rotateZ(0.0f).isIdentity());
}
} // namespace
} // namespace rt
