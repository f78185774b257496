#include "core/accel/hit_refiner.h"

#include <gtest/gtest.h>

#include "core/sampling/rng.h"
#include "support/accel_scenes.h"
#include "support/float_bits.h"

namespace penumbra {
namespace {

using test::bits_of;

TEST(HitRefiner, KeptPlanesGiveTheBitsOfPlanesBuiltPerHit) {
    const Scene scene = test::make_instanced_spheres(20, 5);
    const HitRefiner built(scene);
    HitRefiner kept(scene);
    size_t bytes = 0;
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) bytes += kept.keep_planes(m);
    size_t triangles = 0;
    for (const TriangleMesh& mesh : scene.meshes) triangles += mesh.triangle_count();
    EXPECT_EQ(bytes, triangles * sizeof(TrianglePlane));
    EXPECT_EQ(kept.keep_planes(0), 0u);  // already kept

    // Rays from anywhere at a point inside a random triangle of a random instance, as
    // Embree's hits name them.
    Rng rng(3);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const auto instance = static_cast<uint32_t>(rng.next_float() * scene.instances.size());
        const Instance& inst = scene.instances[instance];
        const uint32_t mesh_index = scene.objects[inst.object].meshes[0];
        const TriangleMesh& mesh = scene.meshes[mesh_index];
        const auto prim = static_cast<uint32_t>(rng.next_float() * mesh.triangle_count());
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = mesh.positions[mesh.indices[3 * size_t(prim) + k]];
        const float u = rng.next_float(), v = rng.next_float() * (1 - u);
        const Vec3 target = inst.to_world.point(p[0] + (p[1] - p[0]) * u + (p[2] - p[0]) * v);
        Ray ray;
        ray.o = Vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 30.0f - Vec3(15.0f);
        ray.d = target - ray.o;
        TriangleHit a{}, b{};
        const bool hit_a = built.plane_hit(ray, instance, mesh_index, prim, &a);
        ASSERT_EQ(kept.plane_hit(ray, instance, mesh_index, prim, &b), hit_a) << i;
        if (!hit_a) continue;
        ++hits;
        EXPECT_EQ(bits_of(b.t), bits_of(a.t)) << i;
        EXPECT_EQ(bits_of(b.b1), bits_of(a.b1)) << i;
        EXPECT_EQ(bits_of(b.b2), bits_of(a.b2)) << i;
        // The target is on the triangle up to the placement's rounding: t is near 1.
        EXPECT_NEAR(a.t, 1.0f, 1e-2f) << i;
    }
    EXPECT_GT(hits, 19000);
}

}  // namespace
}  // namespace penumbra
