#include "core/scene/motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/accel/embree_accel.h"

namespace penumbra {
namespace {

Quat axis_angle(Vec3 axis, float angle) {
    const Vec3 a = normalize(axis) * std::sin(0.5f * angle);
    return {a.x, a.y, a.z, std::cos(0.5f * angle)};
}

double max_difference(const Mat4& a, const Mat4& b) {
    double d = 0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) d = std::max(d, double(std::abs(a(r, c) - b(r, c))));
    return d;
}

// Random affine maps of every kind the decomposition must handle: rotations with
// non-uniform, mirrored (one or three negative scales) and sheared linear parts.
Mat4 random_affine(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<float> u(-1, 1);
    const Quat q = axis_angle(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.01f), 3.1f * u(rng));
    Vec3 s(0.3f + std::abs(u(rng)) * 3, 0.3f + std::abs(u(rng)) * 3, 0.3f + std::abs(u(rng)) * 3);
    if (kind == 1) s.x = -s.x;
    if (kind == 2) s = s * -1.0f;
    Mat4 m = Transform::trs(Vec3(u(rng), u(rng), u(rng)) * 10.0f, q, s).matrix();
    if (kind == 3) {
        Mat4 shear = Mat4::identity();
        shear(0, 1) = u(rng);
        shear(1, 2) = u(rng);
        shear(2, 0) = u(rng);
        m = m * shear;
    }
    return m;
}

TEST(Motion, DecompositionRoundTripsMirroredScaledAndShearedMatrices) {
    std::mt19937 rng(7);
    for (int kind = 0; kind < 4; ++kind)
        for (int n = 0; n < 200; ++n) {
            const Mat4 m = random_affine(rng, kind);
            const QuatDecomposition d = decompose(m);
            // A proper rotation (unit quaternion) with scale, skew and translation.
            EXPECT_NEAR(d.r * d.r + d.i * d.i + d.j * d.j + d.k * d.k, 1.0f, 1e-6f);
            EXPECT_GT(d.scale.x, 0);
            EXPECT_GT(d.scale.y, 0);
            EXPECT_EQ(d.scale.z < 0, m.determinant3x3() < 0) << kind;
            EXPECT_LT(max_difference(compose(d), m), 2e-5) << "kind " << kind;
        }
}

TEST(Motion, StepsAreSignConsistent) {
    // q and -q are one rotation; the decomposition alone may return either. Small turns
    // across the +-pi boundary of the angle are where a naive sign flips.
    std::vector<Transform> steps;
    for (int k = 0; k < 6; ++k)
        steps.push_back(Transform::rotate(axis_angle(Vec3(0, 1, 0), 2.9f + 0.2f * k)));
    const auto ds = decompose_steps(steps);
    for (size_t k = 1; k < ds.size(); ++k)
        EXPECT_GT(ds[k].r * ds[k - 1].r + ds[k].i * ds[k - 1].i + ds[k].j * ds[k - 1].j +
                      ds[k].k * ds[k - 1].k,
                  0.9f);
}

TEST(Motion, InterpolationAtTheStepsGivesTheStepMatrices) {
    std::mt19937 rng(3);
    for (int K : {2, 3, 5})
        for (int n = 0; n < 50; ++n) {
            std::vector<Transform> steps;
            for (int k = 0; k < K; ++k) steps.push_back(Transform(random_affine(rng, n % 4)));
            const auto ds = decompose_steps(steps);
            for (int k = 0; k < K; ++k) {
                const float u = float(k) / float(K - 1);
                EXPECT_LT(max_difference(motion_matrix_at(ds, u), steps[k].matrix()), 1e-4)
                    << "K=" << K << " step " << k;
                EXPECT_LT(max_difference(transform_matrix_at(steps, u), steps[k].matrix()), 1e-4);
            }
        }
}

TEST(Motion, RotationIsSlerpedNotBlended) {
    // 120 degrees about y with a non-uniform scale: at half time, a 60 degree turn of
    // the same scaled object (blending matrices would shrink it to cos 60 = 0.5 of its
    // size along the turning axes).
    const Vec3 s(2, 1, 0.5f);
    const std::vector<Transform> steps = {
        Transform::trs(Vec3(0, 0, 0), axis_angle(Vec3(0, 1, 0), 0), s),
        Transform::trs(Vec3(4, 0, 0), axis_angle(Vec3(0, 1, 0), 2.0944f), s)};
    const Mat4 mid = transform_matrix_at(steps, 0.5f);
    const Mat4 expected = Transform::trs(Vec3(2, 0, 0), axis_angle(Vec3(0, 1, 0), 1.0472f), s).matrix();
    EXPECT_LT(max_difference(mid, expected), 1e-5);
}

// How far Embree's interpolated matrix may lie from ours, entry by entry, when both
// evaluate the same formulas in float. Embree normalizes quaternions with the approximate
// reciprocal square root (RSQRTPS/RSQRT14, relative error at most 1.5 x 2^-12, whose bits
// differ between Intel and AMD) refined by one Newton step: relative error
// 1.5 e^2 + 4 roundings = 7.4 u (u = 2^-24). Each quaternion component then carries that
// plus about 16 roundings of the slerp's polynomials, which Embree may evaluate with FMA
// (23.4 u; ours, with a correctly rounded square root, 18 u). A rotation entry is
// quadratic in q with |q|_1 <= 2: 4 dq + 3 u each, 172 u for the two together. The linear
// part's column c is R times S's column c, so sum_k |S_kc| <= sqrt(3) |M_c| and an entry
// of column c differs by at most 172 u sqrt(3) |M_c|, plus the rounding of the product
// and the translation's lerp, gamma(3) of the terms' magnitudes on each side.
double embree_interpolation_bound(const Mat4& m, int r, int c) {
    constexpr double u = 0x1p-24;
    const double gamma3 = 3 * u / (1 - 3 * u);
    if (c == 3) return 2 * gamma3 * 2 * std::abs(double(m(r, 3)));
    double column = 0, row = 0;
    for (int k = 0; k < 3; ++k) {
        column += double(m(k, c)) * m(k, c);
        row += std::abs(double(m(r, k)));
    }
    column = std::sqrt(column);
    return 172 * u * std::sqrt(3.0) * column + 2 * gamma3 * (std::sqrt(3.0) * column + row);
}

TEST(Motion, MatchesEmbreesOwnInterpolation) {
    // rtcGetGeometryTransform evaluates the time steps inside Embree; ours must agree
    // within embree_interpolation_bound (the same formulas, including its approximate
    // acos and sincos; the matrices' entries reach ~30 here). Measured: at most 0.11 of
    // the bound on Intel (AVX-512), 4.8e-6 absolute; 1.6e-6 on AMD Zen 3. A blended
    // rather than slerped rotation, a wrong time segment or a flipped quaternion sign is
    // off by 1e-2 or more. (std::acos in place of Embree's approximation, 7e-6 on AMD, is
    // within the bound: no test of one CPU can tell it apart from another vendor's RSQRT.)
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u01(0, 1);
    double worst = 0, worst_ratio = 0;
    for (int n = 0; n < 200; ++n) {
        const int K = 2 + n % 3;
        std::vector<Transform> steps;
        for (int k = 0; k < K; ++k) steps.push_back(Transform(random_affine(rng, n % 4)));
        // Also nearly equal rotations, where Embree falls back to a normalized lerp.
        if (n % 5 == 0) steps[1] = Transform(steps[0].matrix() * Transform::rotate(
                                                 axis_angle(Vec3(1, 2, 3), 0.01f)).matrix());
        for (int t = 0; t < 8; ++t) {
            const float u = t == 0 ? 0.0f : (t == 1 ? 1.0f : u01(rng));
            const Mat4 ours = transform_matrix_at(steps, u);
            const Mat4 theirs = embree_transform_at(steps, u);
            worst = std::max(worst, max_difference(ours, theirs));
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c) {
                    const double diff = std::abs(double(ours(r, c)) - theirs(r, c));
                    const double bound = embree_interpolation_bound(ours, r, c);
                    worst_ratio = std::max(worst_ratio, diff / bound);
                    ASSERT_LE(diff, bound) << "n=" << n << " u=" << u << " entry " << r << c;
                }
        }
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g (%.3g of the bound)", worst, worst_ratio);
    RecordProperty("max_difference", buf);
}

TEST(Motion, TimeSegmentsFollowEmbree) {
    float f;
    EXPECT_EQ(time_segment(0.0f, 3, &f), 0);
    EXPECT_EQ(f, 0.0f);
    EXPECT_EQ(time_segment(0.5f, 3, &f), 1);
    EXPECT_EQ(f, 0.0f);
    EXPECT_EQ(time_segment(1.0f, 3, &f), 1);  // the last segment's end, not a third one
    EXPECT_EQ(f, 1.0f);
    EXPECT_EQ(time_segment(0.25f, 2, &f), 0);
    EXPECT_EQ(f, 0.25f);
}

TEST(Motion, VerticesAndNormalsInterpolateLinearly) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}};
    mesh.normals = {{0, 0, 1}};
    mesh.motion_positions = {{{0, 0, 0}}, {{2, 0, 0}}, {{2, 4, 0}}};
    mesh.motion_normals = {{{0, 0, 1}}, {{0, 1, 0}}, {{1, 0, 0}}};
    EXPECT_EQ(position_at(mesh, 0, 0.25f), Vec3(1, 0, 0));
    EXPECT_EQ(position_at(mesh, 0, 0.75f), Vec3(2, 2, 0));
    EXPECT_EQ(normal_at(mesh, 0, 0.25f), Vec3(0, 0.5f, 0.5f));
    TriangleMesh still;
    still.positions = {{1, 2, 3}};
    EXPECT_EQ(position_at(still, 0, 0.6f), Vec3(1, 2, 3));
}

// Points of the box at many times, through the same interpolation the accelerators use,
// must lie in the motion bounds; and for a large rotation the union of the boxes at the
// steps alone must miss some (the arc bulges), or this test would not test the bound.
TEST(Motion, BoundsEncloseTheWholeMotion) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u01(0, 1);
    const Bounds3 box{Vec3(-1, -0.5f, -2), Vec3(1.5f, 0.5f, 0.25f)};
    int outside_step_union = 0;
    for (int n = 0; n < 60; ++n) {
        const int K = 2 + n % 3;
        std::vector<Transform> steps;
        for (int k = 0; k < K; ++k) steps.push_back(Transform(random_affine(rng, n % 4)));
        const auto ds = decompose_steps(steps);
        const Bounds3 mb = motion_bounds(ds, box);
        Bounds3 step_union;
        for (const Transform& t : steps) step_union.expand(t.bounds(box));
        for (int s = 0; s < 400; ++s) {
            const Mat4 m = motion_matrix_at(ds, u01(rng));
            const Vec3 p = box.lo + box.diagonal() * Vec3(s % 2 ? 1.0f : u01(rng), s % 3 ? 1.0f : u01(rng),
                                                          s % 5 ? u01(rng) : 0.0f);
            Vec3 x;
            for (int r = 0; r < 3; ++r) x[r] = m(r, 0) * p.x + m(r, 1) * p.y + m(r, 2) * p.z + m(r, 3);
            for (int a = 0; a < 3; ++a) {
                ASSERT_GE(x[a], mb.lo[a]) << "n=" << n;
                ASSERT_LE(x[a], mb.hi[a]) << "n=" << n;
            }
            bool in_union = true;
            for (int a = 0; a < 3; ++a)
                in_union = in_union && x[a] >= step_union.lo[a] && x[a] <= step_union.hi[a];
            outside_step_union += !in_union;
        }
        // Not much looser than needed: within 5% of the step boxes' size on each side
        // beyond the true sweep is what the pieces allow; check the overall growth.
        EXPECT_LT(length(mb.diagonal()), 3.0f * length(step_union.diagonal()));
    }
    EXPECT_GT(outside_step_union, 100);
}

}  // namespace
}  // namespace penumbra
