// A small curved grid with every vertex attribute the renderer keeps, for round trips
// through compressed glTF (Draco, meshopt): the reference arrays, and a comparison of a
// loaded TriangleMesh with them that ignores vertex and triangle order (Draco reorders).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/scene/scene.h"

namespace penumbra::test {

struct ReferenceGrid {
    std::vector<float> positions, normals, uv0, uv1, tangents, colors;  // 3, 3, 2, 2, 4, 4
    std::vector<uint32_t> indices;
    size_t vertex_count() const { return positions.size() / 3; }
};

// n x n vertices over [-1, 1]^2, z = 0.3 sin(2x) cos(3y); the normals and tangents of that
// surface, uv0 in [0.05, 0.95]^2 (not dyadic), uv1 in [0, 2] x [-1, 0], colours (u, v, 1 - u, 1),
// and the bitangent sign alternating by row so that a lost w shows.
inline ReferenceGrid make_reference_grid(int n = 9) {
    ReferenceGrid g;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float u = float(i) / float(n - 1), v = float(j) / float(n - 1);
            const float x = 2 * u - 1, y = 2 * v - 1;
            const float dzdx = 0.6f * std::cos(2 * x) * std::cos(3 * y);
            const float dzdy = -0.9f * std::sin(2 * x) * std::sin(3 * y);
            const float nl = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1);
            const float tl = std::sqrt(1 + dzdx * dzdx);
            g.positions.insert(g.positions.end(), {x, y, 0.3f * std::sin(2 * x) * std::cos(3 * y)});
            g.normals.insert(g.normals.end(), {-dzdx / nl, -dzdy / nl, 1 / nl});
            g.uv0.insert(g.uv0.end(), {0.05f + 0.9f * u, 0.05f + 0.9f * v});
            g.uv1.insert(g.uv1.end(), {2 * u, -v});
            g.tangents.insert(g.tangents.end(), {1 / tl, 0, dzdx / tl, j % 2 ? -1.0f : 1.0f});
            g.colors.insert(g.colors.end(), {u, v, 1 - u, 1});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            g.indices.insert(g.indices.end(), {a, b, d, a, d, c});
        }
    return g;
}

// Largest error allowed per attribute, in the attribute's units: |difference| per
// component; for normals, the length of the difference vector.
struct GridTolerance {
    float position = 0, normal = 0, uv0 = 0, uv1 = 0, tangent = 0, color = 0;
};

// Every loaded triangle must match one reference triangle (the one with the nearest
// centroid, each used once) corner by corner, within `tol`; also counts attributes that
// are present. Returns the largest errors seen, for the test to report.
inline GridTolerance expect_matches_grid(const TriangleMesh& m, const ReferenceGrid& g,
                                         const GridTolerance& tol) {
    GridTolerance worst;
    const size_t tris = g.indices.size() / 3;
    EXPECT_EQ(m.triangle_count(), tris);
    EXPECT_EQ(m.normals.size(), m.positions.size());
    EXPECT_EQ(m.uv0.size(), m.positions.size());
    EXPECT_EQ(m.uv1.size(), m.positions.size());
    EXPECT_EQ(m.tangents.size(), m.positions.size());
    EXPECT_EQ(m.colors.size(), m.positions.size());
    if (m.triangle_count() != tris || m.tangents.size() != m.positions.size() ||
        m.colors.size() != m.positions.size() || m.uv1.size() != m.positions.size())
        return worst;
    auto ref_pos = [&](uint32_t v) {
        return Vec3{g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]};
    };
    std::vector<bool> used(tris, false);
    for (size_t t = 0; t < tris; ++t) {
        const Vec3 c = (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                        m.positions[m.indices[3 * t + 2]]) /
                       3.0f;
        size_t best = 0;
        float best_d = 1e30f;
        for (size_t r = 0; r < tris; ++r) {
            const Vec3 rc = (ref_pos(g.indices[3 * r]) + ref_pos(g.indices[3 * r + 1]) +
                             ref_pos(g.indices[3 * r + 2])) /
                            3.0f;
            const float d = length(rc - c);
            if (d < best_d) best_d = d, best = r;
        }
        if (used[best]) {
            ADD_FAILURE() << "two loaded triangles match reference triangle " << best;
            return worst;
        }
        used[best] = true;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = m.indices[3 * t + size_t(k)];
            // The reference corner nearest to this one.
            uint32_t rv = g.indices[3 * best];
            for (int q = 1; q < 3; ++q)
                if (length(ref_pos(g.indices[3 * best + size_t(q)]) - m.positions[v]) <
                    length(ref_pos(rv) - m.positions[v]))
                    rv = g.indices[3 * best + size_t(q)];
            auto track = [](float& w, float e) { w = std::max(w, e); };
            const Vec3 p = m.positions[v], nrm = m.normals[v];
            for (int a = 0; a < 3; ++a)
                track(worst.position, std::abs(p[a] - g.positions[3 * rv + a]));
            track(worst.normal, length(nrm - Vec3{g.normals[3 * rv], g.normals[3 * rv + 1],
                                                  g.normals[3 * rv + 2]}));
            for (int a = 0; a < 2; ++a) {
                track(worst.uv0, std::abs(m.uv0[v][a] - g.uv0[2 * rv + a]));
                track(worst.uv1, std::abs(m.uv1[v][a] - g.uv1[2 * rv + a]));
            }
            for (int a = 0; a < 4; ++a) {
                track(worst.tangent, std::abs(m.tangents[v][a] - g.tangents[4 * rv + a]));
                track(worst.color, std::abs(m.colors[v][a] - g.colors[4 * rv + a]));
            }
        }
    }
    EXPECT_LE(worst.position, tol.position);
    EXPECT_LE(worst.normal, tol.normal);
    EXPECT_LE(worst.uv0, tol.uv0);
    EXPECT_LE(worst.uv1, tol.uv1);
    EXPECT_LE(worst.tangent, tol.tangent);
    EXPECT_LE(worst.color, tol.color);
    return worst;
}

}  // namespace penumbra::test
