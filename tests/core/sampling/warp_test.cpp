#include "core/sampling/warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "support/statistics/chi2.h"

namespace penumbra {
namespace {

using test::Chi2Result;

// Chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 11;
const double kLevel = test::sidak_significance(0.01, kChi2Tests);

Vec2 next_2d(Rng& rng) { return {rng.next_float(), rng.next_float()}; }

Chi2Result sphere_test(Vec3 (*warp)(Vec2), test::DirectionPdf pdf, bool hemisphere, uint64_t seed) {
    test::SphereChi2Options o;
    o.hemisphere = hemisphere;
    o.seed = seed;
    o.significance = kLevel;
    return test::chi2_sphere([&](Rng& rng) { return std::optional<Vec3>(warp(next_2d(rng))); }, pdf,
                             o);
}

// The regular polygon whose first vertex is at angle `rotation`.
struct Polygon {
    std::vector<Vec2> v;
    Polygon(int blades, float rotation) {
        for (int k = 0; k < blades; ++k) {
            const double a = rotation + 2 * M_PI * k / blades;
            v.emplace_back(float(std::cos(a)), float(std::sin(a)));
        }
    }
    bool contains(Vec2 p) const {
        for (size_t k = 0; k < v.size(); ++k) {
            const Vec2 a = v[k], e = v[(k + 1) % v.size()] - a;
            if (e.x * (p.y - a.y) - e.y * (p.x - a.x) < 0) return false;
        }
        return true;
    }
};

TEST(WarpChi2, UniformSphere) {
    const Chi2Result r = sphere_test(
        square_to_uniform_sphere, [](Vec3) { return double(uniform_sphere_pdf()); }, false, 1);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
}

TEST(WarpChi2, UniformHemisphere) {
    const Chi2Result r = sphere_test(
        square_to_uniform_hemisphere, [](Vec3 w) { return double(uniform_hemisphere_pdf(w)); },
        true, 2);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
}

TEST(WarpChi2, CosineHemisphere) {
    const Chi2Result r = sphere_test(
        square_to_cosine_hemisphere, [](Vec3 w) { return double(cosine_hemisphere_pdf(w)); }, true,
        3);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
}

TEST(WarpChi2, UniformCone) {
    // Narrow, wide and wider than a hemisphere (4 tests with the one below).
    for (float cos_max : {0.97f, 0.6f, 0.0f, -0.45f}) {
        test::SphereChi2Options o;
        o.seed = 4;
        o.significance = kLevel;
        const Chi2Result r = test::chi2_sphere(
            [&](Rng& rng) {
                return std::optional<Vec3>(square_to_uniform_cone(next_2d(rng), cos_max));
            },
            [&](Vec3 w) { return w.z >= cos_max ? double(uniform_cone_pdf(cos_max)) : 0.0; }, o);
        EXPECT_TRUE(r.passed) << "cos_max " << cos_max << "\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5) << "cos_max " << cos_max;
    }
}

TEST(WarpChi2, ConcentricDisk) {
    test::PlanarChi2Options o;
    o.lo = {-1, -1};
    o.significance = kLevel;
    o.seed = 5;
    const Chi2Result r = test::chi2_planar(
        [](Rng& rng) { return std::optional<Vec2>(square_to_concentric_disk(next_2d(rng))); },
        [](Vec2 p) { return p.x * p.x + p.y * p.y <= 1 ? 1 / M_PI : 0.0; }, o);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3);
}

TEST(WarpChi2, Polygon) {
    for (int blades : {5, 6}) {
        const float rotation = 0.3f;
        const Polygon polygon(blades, rotation);
        test::PlanarChi2Options o;
        o.lo = {-1, -1};
        o.significance = kLevel;
        o.seed = 6 + blades;
        const Chi2Result r = test::chi2_planar(
            [&](Rng& rng) {
                return std::optional<Vec2>(square_to_polygon(next_2d(rng), blades, rotation));
            },
            [&](Vec2 p) { return polygon.contains(p) ? 1.0 / polygon_area(blades) : 0.0; }, o);
        EXPECT_TRUE(r.passed) << blades << " blades\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3) << blades << " blades";
    }
}

TEST(WarpChi2, Triangle) {
    // Barycentrics (b1, b2) uniform on the lower-left half of the unit square.
    test::PlanarChi2Options o;
    o.significance = kLevel;
    o.seed = 13;
    const Chi2Result r = test::chi2_planar(
        [](Rng& rng) { return std::optional<Vec2>(square_to_triangle(next_2d(rng))); },
        [](Vec2 b) { return b.x + b.y <= 1 ? 2.0 : 0.0; }, o);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 2e-3);
}

// The branchless form gives Heitz's two branches' values bit for bit (renders unchanged).
TEST(Warp, TriangleEqualsHeitzBranchesExactly) {
    Rng rng(14);
    for (int i = 0; i < 100000; ++i) {
        Vec2 u = next_2d(rng);
        if (i % 8 == 0) u.y = u.x;  // the tie goes to the second branch
        if (i % 8 == 1) u.x = i % 16 == 1 ? 0.0f : 0x1.fffffep-1f;
        const Vec2 b = square_to_triangle(u);
        const Vec2 ref = u.x < u.y ? Vec2(u.x / 2, u.y - u.x / 2) : Vec2(u.x - u.y / 2, u.y / 2);
        ASSERT_EQ(b.x, ref.x) << u.x << " " << u.y;
        ASSERT_EQ(b.y, ref.y) << u.x << " " << u.y;
    }
}

TEST(Warp, DensitiesIntegrateToOne) {
    for (float cos_max : {0.999f, 0.5f, -0.9f})
        EXPECT_NEAR(uniform_cone_pdf(cos_max) * 2 * kPi * (1 - cos_max), 1.0f, 1e-5f);
    EXPECT_NEAR(uniform_sphere_pdf() * 4 * kPi, 1.0f, 1e-6f);
    // The polygon area against the shoelace formula over its vertices.
    for (int blades : {3, 5, 6, 9}) {
        double area = 0;
        for (int k = 0; k < blades; ++k) {
            const double a0 = 2 * M_PI * k / blades, a1 = 2 * M_PI * (k + 1) / blades;
            area += 0.5 * (std::cos(a0) * std::sin(a1) - std::cos(a1) * std::sin(a0));
        }
        EXPECT_NEAR(polygon_area(blades), area, 1e-6) << blades;
    }
}

TEST(Warp, DensitiesVanishOutsideTheirDomain) {
    for (Vec3 w : {Vec3(0, 0, -1), normalize(Vec3(1, 2, -0.01f)), normalize(Vec3(-1, 0, -3))}) {
        EXPECT_EQ(uniform_hemisphere_pdf(w), 0.0f);
        EXPECT_EQ(cosine_hemisphere_pdf(w), 0.0f);
    }
    EXPECT_EQ(cosine_hemisphere_pdf(Vec3(1, 0, 0)), 0.0f);
    EXPECT_GT(uniform_hemisphere_pdf(normalize(Vec3(1, 2, 0.01f))), 0.0f);
    EXPECT_GT(cosine_hemisphere_pdf(normalize(Vec3(1, 2, 0.01f))), 0.0f);
}

// z comes from the disk radius, apart from x and y (square_to_cosine_hemisphere): the
// three must still make a unit vector, to rounding, over the whole square.
TEST(Warp, CosineHemisphereDirectionsAreUnit) {
    const int n = 1024;
    double worst = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const Vec2 u(std::min(i / float(n), 0x1.fffffep-1f),
                         std::min(j / float(n), 0x1.fffffep-1f));
            const Vec3 w = square_to_cosine_hemisphere(u);
            const double len = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
            worst = std::max(worst, std::abs(len - 1));
        }
    EXPECT_LT(worst, 3e-7) << worst;
}

TEST(Warp, ImagesStayInTheirDomains) {
    // The corners and edges of the unit square, where rounding is most likely to escape.
    const float one = 0x1.fffffep-1f;
    for (float x : {0.0f, 0.5f, one})
        for (float y : {0.0f, 1e-7f, 0.5f, one}) {
            const Vec2 u(x, y);
            const Vec2 d = square_to_concentric_disk(u);
            EXPECT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f);
            const Vec2 b = square_to_triangle(u);
            EXPECT_GE(b.x, 0.0f);
            EXPECT_GE(b.y, 0.0f);
            EXPECT_LE(b.x + b.y, 1.0f + 1e-6f);
            EXPECT_GE(square_to_cosine_hemisphere(u).z, 0.0f);
            EXPECT_GE(square_to_uniform_hemisphere(u).z, 0.0f);
            EXPECT_NEAR(length(square_to_uniform_sphere(u)), 1.0f, 1e-6f);
            EXPECT_GE(square_to_uniform_cone(u, 0.8f).z, 0.8f - 1e-6f);
            for (int blades : {5, 6})
                EXPECT_TRUE(Polygon(blades, 0).contains(square_to_polygon(u, blades) * 0.9999f))
                    << x << " " << y;
        }
}

// The concentric map's cos and sin: Cephes' polynomials on [-pi/4, pi/4] are within
// 0.80 ulp (sin) and 0.98 ulp (cos) of double over every float of the range (an exhaustive
// run, too slow for a test); here every 257th float (about 8 million), the ends and zero,
// with the bound 1.
TEST(Warp, QuarterPiCosSinWithinAnUlp) {
    auto ulps = [](float got, double exact) {
        const float e = float(std::abs(exact));
        return std::abs(double(got) - exact) / double(std::nextafter(e, 2.0f) - e);
    };
    const float end = float(M_PI / 4);
    uint32_t end_bits;
    std::memcpy(&end_bits, &end, 4);
    double worst_cos = 0, worst_sin = 0;
    int checked = 0;
    auto check = [&](uint32_t bits) {
        float a;
        std::memcpy(&a, &bits, 4);
        for (float x : {a, -a}) {
            const Vec2 cs = cos_sin_quarter_pi_for_test(x);
            worst_cos = std::max(worst_cos, ulps(cs.x, std::cos(double(x))));
            if (x != 0) worst_sin = std::max(worst_sin, ulps(cs.y, std::sin(double(x))));
            EXPECT_EQ(cs.y, -cos_sin_quarter_pi_for_test(-x).y);  // odd, exactly
            ++checked;
        }
    };
    for (uint32_t b = 0; b < end_bits; b += 257) check(b);
    check(end_bits);
    EXPECT_GT(checked, 8'000'000);
    EXPECT_EQ(cos_sin_quarter_pi_for_test(0).x, 1.0f);
    EXPECT_EQ(cos_sin_quarter_pi_for_test(0).y, 0.0f);
    EXPECT_LE(worst_cos, 1.0);
    EXPECT_LE(worst_sin, 1.0);
}

// The selects give Shirley-Chiu's map: every point of a 1024 x 1024 grid (and the square's
// edges and diagonals) within 4e-7 of the double-precision map, and inside the unit disk
// to rounding.
TEST(Warp, ConcentricDiskMatchesTheExactMap) {
    double worst = 0, worst_r2 = 0;
    const int n = 1024;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const Vec2 u{float(i) / n, float(j) / n};
            const double ox = 2.0 * u.x - 1, oy = 2.0 * u.y - 1;
            double ex = 0, ey = 0;
            if (ox != 0 || oy != 0) {
                const bool xm = std::abs(ox) > std::abs(oy);
                const double r = xm ? ox : oy;
                const double t = xm ? M_PI / 4 * (oy / ox) : M_PI / 2 - M_PI / 4 * (ox / oy);
                ex = r * std::cos(t);
                ey = r * std::sin(t);
            }
            const Vec2 d = square_to_concentric_disk(u);
            worst = std::max({worst, std::abs(d.x - ex), std::abs(d.y - ey)});
            worst_r2 = std::max(worst_r2, double(d.x) * d.x + double(d.y) * d.y);
        }
    EXPECT_LT(worst, 4e-7);
    EXPECT_LT(worst_r2, 1 + 4e-7);
}

}  // namespace
}  // namespace penumbra
