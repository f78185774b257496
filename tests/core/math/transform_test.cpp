#include "core/math/transform.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "core/math/frame.h"

namespace penumbra {
namespace {

void expect_near(Vec3 a, Vec3 b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Transform, TrsAppliesScaleThenRotationThenTranslation) {
    // 90 degrees about +Z: x -> y.
    const float s = std::sqrt(0.5f);
    const Transform xf = Transform::trs({1, 2, 3}, Quat{0, 0, s, s}, {2, 2, 2});
    expect_near(xf.point({1, 0, 0}), {1, 4, 3});
    expect_near(xf.vector({1, 0, 0}), {0, 2, 0});
}

TEST(Transform, InverseRoundTrips) {
    const Transform xf =
        Transform::trs({5, -2, 7}, Quat{0.1f, 0.7f, -0.2f, 0.6f}, {0.5f, 3.0f, -2.0f});
    const Vec3 p(0.3f, -1.2f, 4.5f);
    expect_near(xf.inverse().point(xf.point(p)), p, 1e-4f);
    const Mat4 id = xf.matrix() * xf.inverse_matrix();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(id(r, c), r == c ? 1.0f : 0.0f, 1e-5f);
}

TEST(Transform, SingularMatrixIsRejected) {
    Mat4 m = Mat4::identity();
    m(1, 1) = 0;
    EXPECT_THROW(Transform{m}, std::invalid_argument);
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
    const Transform xf = Transform::scale({4, 1, 0.25f});
    // A plane through the origin containing (1, 1, 0) and (0, 0, 1).
    const Vec3 t1(1, 1, 0), t2(0, 0, 1);
    const Vec3 n = cross(t1, t2);
    const Vec3 nw = xf.normal(n);
    EXPECT_NEAR(dot(nw, xf.vector(t1)), 0, 1e-6f);
    EXPECT_NEAR(dot(nw, xf.vector(t2)), 0, 1e-6f);
    // Transforming the normal like a vector would be wrong here.
    EXPECT_GT(std::abs(dot(xf.vector(n), xf.vector(t1))), 0.1f);
}

TEST(Transform, MirroringFlipsHandednessAndKeepsNormalsConsistent) {
    const Transform xf = Transform::scale({-1, 1, 1});
    EXPECT_TRUE(xf.swaps_handedness());
    EXPECT_FALSE(Transform::scale({1, 2, 3}).swaps_handedness());
    // Triangle in the z = 0 plane, counter-clockwise seen from +z: normal +z.
    const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
    const Vec3 n = cross(p1 - p0, p2 - p0);
    // The mirrored triangle's winding normal flips, the transformed normal does not:
    // both describe the same side only once the winding flip is accounted for.
    const Vec3 wn = cross(xf.point(p1) - xf.point(p0), xf.point(p2) - xf.point(p0));
    expect_near(normalize(xf.normal(n)), {0, 0, 1});
    expect_near(normalize(wn), {0, 0, -1});
}

TEST(Transform, ColumnMajorMatchesGltf) {
    // glTF: translation in elements 12, 13, 14.
    const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1};
    const Transform xf(Mat4::from_column_major(m));
    expect_near(xf.point({0, 0, 0}), {7, 8, 9});
}

TEST(Transform, LookAtMapsMinusZToTarget) {
    const Transform xf = Transform::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    expect_near(xf.point({0, 0, 0}), {0, 0, 5});
    expect_near(xf.vector({0, 0, -1}), {0, 0, -1});
    expect_near(xf.vector({0, 1, 0}), {0, 1, 0});
}

TEST(Transform, BoundsEncloseTransformedCorners) {
    Bounds3 b;
    b.expand({-1, -1, -1});
    b.expand({1, 1, 1});
    const float s = std::sqrt(0.5f);
    const Bounds3 r = Transform::rotate(Quat{0, 0, s, s}).bounds(b);
    EXPECT_NEAR(r.hi.x, 1.0f, 1e-5f);
    const Bounds3 r45 = Transform::rotate(Quat{0, 0, std::sin(kPi / 8), std::cos(kPi / 8)}).bounds(b);
    EXPECT_NEAR(r45.hi.x, std::sqrt(2.0f), 1e-5f);
}

// The general 4x4 formulas, written out from the matrices, for checking the shortcuts.
Vec3 point_by_matrix(const Transform& xf, Vec3 p) {
    const Mat4& m = xf.matrix();
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = m(i, 0) * p.x + m(i, 1) * p.y + m(i, 2) * p.z + m(i, 3);
    return r;
}
Vec3 normal_by_matrix(const Transform& xf, Vec3 n) {
    const Mat4& mi = xf.inverse_matrix();
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = mi(0, i) * n.x + mi(1, i) * n.y + mi(2, i) * n.z;
    return r;
}

// xf's point and normal equal the written-out formulas bit for bit.
void expect_formulas(const Transform& xf, Vec3 p) {
    const Vec3 a = xf.point(p), b = point_by_matrix(xf, p);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, b.z);
    const Vec3 n = xf.normal(p), nb = normal_by_matrix(xf, p);
    EXPECT_EQ(n.x, nb.x);
    EXPECT_EQ(n.y, nb.y);
    EXPECT_EQ(n.z, nb.z);
}

TEST(Transform, TranslationsTakeTheShortcutWithTheGeneralFormulasValues) {
    const float s = std::sqrt(0.5f);
    EXPECT_TRUE(Transform().is_translation_only());
    EXPECT_TRUE(Transform::translate({1, -2, 3}).is_translation_only());
    EXPECT_TRUE((Transform::translate({1, 2, 3}) * Transform::translate({-4, 0.5f, 9}))
                    .is_translation_only());
    EXPECT_TRUE(Transform(Mat4::identity()).is_translation_only());
    EXPECT_FALSE(Transform::scale({1, 1, 2}).is_translation_only());
    EXPECT_FALSE(Transform::rotate(Quat{0, 0, s, s}).is_translation_only());
    EXPECT_FALSE(Transform::trs({1, 2, 3}, Quat{}, {-1, 1, 1}).is_translation_only());
    Mat4 projective = Mat4::identity();
    projective(3, 2) = 0.5f;
    EXPECT_FALSE(Transform(projective).is_translation_only());

    const Vec3 points[] = {{0.3f, -7.25f, 1e-3f}, {1e6f, -3e-5f, 2.5f}, {-1, -1, -1},
                           {123.456f, 0.1f, -9e4f}};
    for (const Transform& xf : {Transform(), Transform::translate({0.1f, -2e5f, 3.7f}),
                                Transform::translate({-1e-4f, 0, 1e7f})})
        for (Vec3 p : points) {
            expect_formulas(xf, p);
            EXPECT_EQ(xf.vector(p).x, p.x);
            EXPECT_FALSE(xf.swaps_handedness());
        }
    // The general path still matches its formula.
    const Transform g = Transform::trs({1, 2, 3}, Quat{0, 0, s, s}, {2, -1, 0.5f});
    EXPECT_TRUE(g.swaps_handedness());
    for (Vec3 p : points) expect_formulas(g, p);
}

// The hot path's columns (surface_point.cpp's bare facets) are the matrix's, with a zero
// fourth float, 16-byte aligned; only a (0, 0, 0, 1) last row is affine.
TEST(Transform, ColumnsAndAffinityMatchTheMatrix) {
    const float s = std::sqrt(0.5f);
    Mat4 projective = Mat4::identity();
    projective(3, 2) = 0.5f;
    const Transform xfs[] = {Transform(), Transform::translate({1, -2, 3}),
                             Transform::trs({1, 2, 3}, Quat{0, 0, s, s}, {2, -1, 0.5f}),
                             Transform(projective)};
    for (const Transform& xf : xfs) {
        for (int c = 0; c < 4; ++c) {
            EXPECT_EQ(reinterpret_cast<uintptr_t>(xf.column(c)) % 16, 0u);
            for (int r = 0; r < 3; ++r) EXPECT_EQ(xf.column(c)[r], xf.matrix()(r, c));
            EXPECT_EQ(xf.column(c)[3], 0.0f);
        }
        if (xf.is_translation_only()) EXPECT_TRUE(xf.is_affine());
    }
    EXPECT_TRUE(xfs[2].is_affine());
    EXPECT_FALSE(xfs[3].is_affine());
}

TEST(Frame, IsOrthonormalForAnyNormal) {
    for (Vec3 n : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), normalize(Vec3(1, 2, -3)),
                   normalize(Vec3(1e-8f, 0, -1))}) {
        const Frame f = Frame::from_normal(n);
        EXPECT_NEAR(dot(f.s, f.t), 0, 1e-6f);
        EXPECT_NEAR(dot(f.s, f.n), 0, 1e-6f);
        EXPECT_NEAR(length(f.s), 1, 1e-6f);
        EXPECT_NEAR(length(f.t), 1, 1e-6f);
        expect_near(f.to_world(f.to_local({0.3f, -0.4f, 0.5f})), {0.3f, -0.4f, 0.5f});
        expect_near(cross(f.s, f.t), f.n);  // right-handed
    }
}

}  // namespace
}  // namespace penumbra
