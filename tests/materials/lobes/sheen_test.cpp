// KHR_materials_sheen's Charlie lobe and its albedo table: the table against adaptive
// quadrature of the lobe (independent of the table's own rule), the lobe's symmetry,
// and albedos at most 1 (the albedo scaling assumes it).
#include "materials/lobes/sheen.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <cstdio>

#include "materials/albedo/sheen_albedo.h"
#include "materials/albedo/sheen_albedo_table.h"
#include "support/bsdf/bsdf_properties.h"
#include "support/statistics/quadrature.h"

namespace penumbra {
namespace {

// E(mu, r) = int D V cos dwi by nested adaptive Gauss-Kronrod over (cos_i, phi).
double reference_albedo(float mu, float r) {
    const CharlieSheen sheen(r);
    const Vec3 wo(std::sqrt(1 - mu * mu), 0, mu);
    return test::integrate_2d(
        [&](double c, double phi) {
            const double s = std::sqrt(std::max(0.0, 1 - c * c));
            const Vec3 wi(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c));
            return double(sheen.value(wo, wi)) * c;
        },
        0, 1, 0, 2 * kPi, 1e-6);
}

// Measured: the largest difference over these points is 7.7e-4 (printed); the test
// allows 1.5e-3, the interpolation error of the 32 x 32 grid (E reaches about 0.99).
TEST(SheenAlbedo, TableMatchesQuadrature) {
    Rng rng(5);
    double worst = 0;
    for (int i = 0; i < 60; ++i) {
        // Grid corners and random points, grazing views included.
        const float mu = i < 6 ? std::array<float, 6>{1, 0.5f, 0.1f, 0.02f, 0.8f, 0.3f}[i]
                               : 0.01f + 0.99f * rng.next_float();
        const float r =
            i < 6 ? std::array<float, 6>{1, 0.5f, 0.05f, 0.3f, 0.01f, 0.9f}[i] : rng.next_float();
        const double ref = reference_albedo(mu, r);
        const double table = sheen_albedo(mu, r);
        worst = std::max(worst, std::abs(table - ref));
        EXPECT_NEAR(table, ref, 1.5e-3) << "mu " << mu << ", r " << r;
        EXPECT_LE(ref, 1.0) << "mu " << mu << ", r " << r;
    }
    std::printf("sheen albedo table: largest error %.2e\n", worst);
}

TEST(SheenAlbedo, StaysBelowOneDownToTheSmallestRoughness) {
    // The lobe reflects less than it receives at every view, grazing ones included, down
    // to the clamp (sheen.h), and roughness 0 is the clamped lobe.
    for (float mu = 1e-3f; mu <= 1; mu *= 1.2f)
        for (float r : {0.0f, CharlieSheen::kMinRoughness, 0.1f, 0.3f, 0.6f, 1.0f}) {
            const float e = integrate_sheen_albedo(mu, r, 256, 256);
            EXPECT_GE(e, 0.0f);
            EXPECT_LE(e, 1.0f) << "mu " << mu << ", r " << r;
            EXPECT_LE(sheen_albedo(mu, r), 1.0f) << "mu " << mu << ", r " << r;
        }
    EXPECT_EQ(sheen_albedo(0.3f, 0), sheen_albedo(0.3f, CharlieSheen::kMinRoughness));
}

TEST(SheenAlbedo, CompiledTableIsTheIntegratedOne) {
    // The build integrates the table (albedo_generator.cpp); the rows it compiled in
    // are exactly what integrating them here gives, to the bit, and so what the
    // renderer integrated on first use before the table moved to build time.
    auto fresh = std::make_unique<SheenAlbedoTable>();
    for (int j : {0, 1, 13, SheenAlbedoTable::R - 1}) {
        integrate_sheen_albedo_row(j, *fresh);
        for (int i = 0; i < SheenAlbedoTable::M; ++i)
            ASSERT_EQ(kSheenAlbedo.e[j][i], fresh->e[j][i]) << j << " " << i;
    }
}

TEST(CharlieSheen, IsSymmetricAndFinite) {
    Rng rng(6);
    for (int i = 0; i < 2000; ++i) {
        const CharlieSheen sheen(i % 10 == 0 ? 0.0f : rng.next_float());
        const Vec3 wo = test::random_direction(rng, 0.001f),
                   wi = test::random_direction(rng, 0.001f);
        const float a = sheen.value(wo, wi), b = sheen.value(wi, wo);
        ASSERT_TRUE(std::isfinite(a));
        EXPECT_GE(a, 0.0f);
        EXPECT_NEAR(a, b, 1e-5f * a);
        EXPECT_EQ(sheen.value(wo, Vec3(wi.x, wi.y, -wi.z)), 0.0f);
    }
}

}  // namespace
}  // namespace penumbra
