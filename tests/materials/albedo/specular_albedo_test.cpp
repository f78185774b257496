#include "materials/albedo/specular_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/sampling/rng.h"
#include "materials/albedo/specular_albedo_table.h"

namespace penumbra {
namespace {

// The largest error of the interpolated table against a fine brute-force integration,
// away from the grid's nodes. Energy conservation of the layered glTF BRDF rests on it:
// a white dielectric reflects exactly 1 + (E_true - E_table)(wo).
constexpr float kTableTolerance = 2e-3f;

TEST(SpecularAlbedo, TableMatchesBruteForceBetweenNodes) {
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        Rng rng(type == MicrofacetType::Ggx ? 3 : 4);
        float worst = 0;
        for (int k = 0; k < 60; ++k) {
            // Half uniform, half log-uniform: the corner of smooth lobes seen at grazing
            // angles (roughness 0.01, mu 0.002) is where the table is hardest.
            const bool corner = k % 2;
            const float r = corner ? 0.01f * std::pow(100.0f, rng.next_float())
                                   : 0.01f + 0.99f * rng.next_float();
            const float mu = corner ? 0.002f * std::pow(500.0f, rng.next_float())
                                    : 0.002f + 0.998f * rng.next_float();
            const Vec2 table = SpecularAlbedo(type, r * r).at(mu);
            const Vec2 exact = integrate_specular_albedo(type, r * r, mu, 96, 160);
            worst = std::max({worst, std::abs(table.x - exact.x), std::abs(table.y - exact.y)});
            EXPECT_NEAR(table.x, exact.x, kTableTolerance) << "r " << r << " mu " << mu;
            EXPECT_NEAR(table.y, exact.y, kTableTolerance) << "r " << r << " mu " << mu;
        }
        std::printf("%s: worst table error %.5f\n",
                    type == MicrofacetType::Ggx ? "ggx" : "beckmann", worst);
    }
}

TEST(SpecularAlbedo, CompiledTableIsTheIntegratedOne) {
    // The build integrates the table (albedo_generator.cpp); the rows it
    // compiled in are exactly what integrating them here gives, to the bit.
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        const SpecularAlbedoTable& compiled =
            type == MicrofacetType::Ggx ? kSpecularAlbedoGgx : kSpecularAlbedoBeckmann;
        auto fresh = std::make_unique<SpecularAlbedoTable>();
        for (int j : {0, 1, 17, 40, SpecularAlbedoTable::R - 1}) {
            integrate_specular_albedo_row(type, j, *fresh);
            for (int i = 0; i < SpecularAlbedoTable::M; ++i)
                for (int c = 0; c < 2; ++c)
                    ASSERT_EQ(compiled.ab[j][i][c], fresh->ab[j][i][c]) << j << " " << i;
            for (int c = 0; c < 2; ++c) ASSERT_EQ(compiled.average[j][c], fresh->average[j][c]);
        }
    }
}

// The column lookup behind at() against a plain search: the largest column at or below
// mu, on both sides of every column's node, at the guide table's bin edges, and at
// random and tiny mu.
TEST(SpecularAlbedo, ColumnBelowIsTheLastNodeAtOrBelowMu) {
    constexpr int M = SpecularAlbedoTable::M;
    auto expected = [](float mu) {
        int i = 0;
        while (i < M - 2 && specular_albedo_column_mu(i + 1) <= mu) ++i;
        return i;
    };
    std::vector<float> mus = {0.0f, -1.0f, 1.0f, 1e-30f, 1e-7f, 0x1.fffffep-1f};
    for (int i = 0; i < M; ++i) {
        const float node = specular_albedo_column_mu(i);
        mus.insert(mus.end(), {node, std::nextafter(node, 0.0f), std::nextafter(node, 2.0f)});
    }
    for (int k = 0; k <= 4096; ++k) {
        const float edge = k / 4096.0f;
        mus.insert(mus.end(), {edge, std::nextafter(edge, 0.0f), std::nextafter(edge, 2.0f)});
    }
    Rng rng(9);
    for (int k = 0; k < 200000; ++k) {
        const float u = rng.next_float();
        mus.push_back(k % 2 ? u : u * u * u * u);  // half of them crowded towards 0
    }
    for (float mu : mus) {
        const float clamped = std::clamp(mu, 0.0f, 1.0f);
        ASSERT_EQ(specular_albedo_column_below(clamped), expected(clamped)) << mu;
    }
}

TEST(SpecularAlbedo, KnownLimits) {
    // A single-scattering lobe never reflects more than it receives, and the Fresnel
    // moment B never exceeds A.
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float r : {0.0f, 0.1f, 0.5f, 1.0f})
            for (float mu : {0.0f, 0.01f, 0.3f, 1.0f}) {
                const Vec2 ab = SpecularAlbedo(type, r * r).at(mu);
                EXPECT_GE(ab.x, 0.0f);
                EXPECT_LE(ab.x, 1.0f + 1e-6f);
                EXPECT_GE(ab.y, 0.0f);
                EXPECT_LE(ab.y, ab.x + 1e-6f);  // (1 - v.h)^5 <= 1
            }
    // Roughness 0 is the mirror: A = 1, B = (1 - mu)^5 exactly.
    const SpecularAlbedo mirror(MicrofacetType::Ggx, 0);
    for (float mu : {0.0f, 0.25f, 1.0f}) EXPECT_NEAR(mirror.at(mu).x, 1.0f, 1e-6f);
    // At the nodes mu = (i / (columns - 1))^3 B is exact; between them, linear.
    const int last = SpecularAlbedoGrid::kColumns - 1;
    for (int i : {0, 5, 17, last}) {
        const float s = i / float(last), mu = s * s * s;
        EXPECT_NEAR(mirror.at(mu).y, std::pow(1 - mu, 5.0f), 1e-6f) << "mu " << mu;
    }
}

TEST(SpecularAlbedo, AverageIsTheCosineWeightedIntegralOfTheInterpolant) {
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float r : {0.0f, 0.13f, 0.5f, 0.77f, 1.0f}) {
            const SpecularAlbedo albedo(type, r * r);
            // Midpoint rule on a fine grid: 2 int (A, B)(mu) mu dmu.
            const int n = 200000;
            double a = 0, b = 0;
            for (int i = 0; i < n; ++i) {
                const float mu = (i + 0.5f) / n;
                const Vec2 ab = albedo.at(mu);
                a += 2.0 * ab.x * mu / n;
                b += 2.0 * ab.y * mu / n;
            }
            EXPECT_NEAR(albedo.average().x, a, 2e-5) << "r " << r;
            EXPECT_NEAR(albedo.average().y, b, 2e-5) << "r " << r;
        }
    // The mirror's B average is 2 int (1 - mu)^5 mu dmu = 1/21, up to the linear
    // interpolation between columns.
    EXPECT_NEAR(SpecularAlbedo(MicrofacetType::Ggx, 0).average().y, 1.0 / 21, 1e-3);
}

}  // namespace
}  // namespace penumbra
