#include "core/accel/grid_accel.h"

#include <gtest/gtest.h>

#include "core/sampling/rng.h"
#include "support/accel_scenes.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

TEST(GridAccel, ResolutionFollowsTheCubeRootRule) {
    int res[3];
    // 1000 triangles in a cube: 3 cbrt(1000) = 30 cells on each axis.
    GridAccel::resolution(1000, Vec3(2, 2, 2), res);
    EXPECT_EQ(res[0], 30);
    EXPECT_EQ(res[1], 30);
    EXPECT_EQ(res[2], 30);
    // A flat box: 30 along the long axes, 1 across.
    GridAccel::resolution(1000, Vec3(4, 2, 0), res);
    EXPECT_EQ(res[0], 30);
    EXPECT_EQ(res[1], 15);
    EXPECT_EQ(res[2], 1);
    // Capped for huge meshes, at least one cell for one triangle.
    GridAccel::resolution(1u << 30, Vec3(1, 1, 1), res);
    EXPECT_EQ(res[0], GridAccel::kMaxGridRes);
    GridAccel::resolution(1, Vec3(1, 1, 1), res);
    EXPECT_EQ(res[0], 3);
}

// A large triangle overlaps every cell and is met first by the walk (in the first cell),
// but its hit lies beyond a small triangle the ray reaches later in the walk. The grid
// must not stop at the first cell that reports a hit: it must keep walking until the
// cell that contains the closest hit so far.
TEST(GridAccel, TriangleSpanningCellsDoesNotHideANearerHit) {
    Scene scene;
    TriangleMesh m;
    // Big slanted triangle crossing the x axis at x = 20/3; its box spans x in [0, 10].
    m.positions = {{0, -5, -5}, {10, 5, -5}, {10, -5, 25}};
    m.indices = {0, 1, 2};
    // Small triangles along a line away from the ray, so the grid is fine in x.
    for (int i = 0; i < 200; ++i) {
        const float x = 0.05f * i;
        const uint32_t b = static_cast<uint32_t>(m.positions.size());
        m.positions.push_back({x, 3, 3});
        m.positions.push_back({x + 0.04f, 3, 3});
        m.positions.push_back({x, 3.04f, 3});
        m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
    }
    // The nearer target: a small triangle around the x axis at x = 4.
    const uint32_t b = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back({4, -0.1f, -0.1f});
    m.positions.push_back({4, 0.1f, -0.1f});
    m.positions.push_back({4, 0, 0.1f});
    m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
    for (const Vec3& p : m.positions) m.bounds.expand(p);
    scene.meshes.push_back(m);
    scene.objects.push_back({"spanning", {0}, m.bounds});
    test::add_instance(scene, 0, Transform());

    const GridAccel grid(scene);
    Ray r;
    r.o = {-1, 0, 0};
    r.d = {1, 0, 0};
    const auto hit = grid.intersect(r);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->prim, 201u);
    EXPECT_FLOAT_EQ(hit->t, 5.0f);
    // Starting past the small triangle, the big one is found.
    r.tmin = 5.5f;
    const auto far = grid.intersect(r);
    ASSERT_TRUE(far);
    EXPECT_EQ(far->prim, 0u);
    EXPECT_NEAR(far->t, 20.0f / 3 + 1, 1e-4f);
}

TEST(GridAccel, FlatObjectsAndSingleTrianglesWork) {
    Scene scene;
    test::add_instance(
        scene, test::add_quad_object(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, -1),
        Transform::translate({0, 0, 3}));
    const GridAccel grid(scene);
    Rng rng(4);
    for (int i = 0; i < 1000; ++i) {
        Ray r;
        r.o = {1.8f * rng.next_float() - 0.9f, 1.8f * rng.next_float() - 0.9f, 0};
        r.d = {0.01f * (rng.next_float() - 0.5f), 0.01f * (rng.next_float() - 0.5f), 1};
        const auto h = grid.intersect(r);
        ASSERT_TRUE(h && std::abs(h->t - 3) < 1e-4f) << i;
    }
    // Along the plane of the quad: a miss, not a hang.
    Ray along;
    along.o = {-5, 0, 3};
    along.d = {1, 0, 0};
    EXPECT_FALSE(grid.intersect(along));
}

}  // namespace
}  // namespace penumbra
