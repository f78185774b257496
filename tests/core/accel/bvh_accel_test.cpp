#include "core/accel/bvh_accel.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/accel/embree_accel.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "support/accel_agreement.h"
#include "support/accel_scenes.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

TEST(BvhAccel, NamesItsAccelerator) {
    Scene scene;
    test::add_instance(scene, test::add_cube_object(scene, -1), Transform());
    EXPECT_EQ(make_accel(AccelType::BvhMedian, scene)->stats().name, "bvh-median");
}

TEST(BvhAccel, SharedObjectIsBuiltOnceAndInstancesAreHit) {
    Scene scene;
    const uint32_t cube = test::add_cube_object(scene, -1);
    test::add_instance(scene, cube, Transform::translate({-2, 0, 0}));
    test::add_instance(scene, cube, Transform::translate({2, 0, 0}) * Transform::scale({1, 1, -4}));
    const BvhAccel accel(scene);
    EXPECT_EQ(accel.stats().object_scenes, 1u);
    EXPECT_EQ(accel.stats().instances, 2u);
    EXPECT_GT(accel.stats().memory_bytes, 12 * 3 * sizeof(Vec3));
    Ray r;
    r.o = {2, 0.1f, 10};
    r.d = {0, 0, -2};  // not unit: t is in units of |d| in both spaces
    const auto hit = accel.intersect(r);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, 1u);
    EXPECT_NEAR(hit->t, 4.0f, 1e-6f);  // the mirrored, stretched cube's face at z = 2
    EXPECT_TRUE(accel.occluded(r));
    r.o.x = 0;
    EXPECT_FALSE(accel.intersect(r));
    EXPECT_FALSE(accel.occluded(r));
    EXPECT_EQ(accel.rays_traced(), 4u);
}

// Accel's packet query, where an accelerator has no packet kernel: each ray as intersect()
// answers it (a miss and an untraceable ray included), counted as eight rays.
TEST(BvhAccel, PacketOfEightEqualsSingleRays) {
    Scene scene;
    const uint32_t cube = test::add_cube_object(scene, -1);
    test::add_instance(scene, cube, Transform::translate({-2, 0, 0}));
    test::add_instance(scene, cube, Transform::translate({2, 0, 0}));
    const BvhAccel accel(scene);
    Ray rays[8];
    for (int i = 0; i < 8; ++i) {
        rays[i].o = {-3.5f + i, 0.1f * i - 0.3f, 10};
        rays[i].d = {0, 0, -1};
    }
    rays[7].d = {0, 0, 0};  // untraceable
    std::optional<Hit> hits[8];
    accel.intersect8(rays, hits);
    EXPECT_EQ(accel.rays_traced(), 8u);
    int hit_count = 0;
    for (int i = 0; i < 8; ++i) {
        const std::optional<Hit> single = accel.intersect(rays[i]);
        ASSERT_EQ(bool(hits[i]), bool(single)) << i;
        if (!single) continue;
        ++hit_count;
        EXPECT_EQ(hits[i]->t, single->t);
        EXPECT_EQ(hits[i]->instance, single->instance);
        EXPECT_EQ(hits[i]->prim, single->prim);
        EXPECT_EQ(hits[i]->b1, single->b1);
        EXPECT_EQ(hits[i]->b2, single->b2);
    }
    EXPECT_GT(hit_count, 2);
    EXPECT_LT(hit_count, 8);
}

// Embree (robust mode) counts a hit at tmin <= t <= tmax; every accelerator must agree
// at both ends. The hit's exact t is 2 (all values are exact in float), which our BVH
// returns; Embree's kernels divide through a refined reciprocal whose last bit depends on
// the ISA it picks at run time (AVX2 machines give 2 - 1 ulp), so each accelerator's
// interval ends are checked at the t it reports itself, within an ulp of 2.
TEST(BvhAccel, IntervalEndsMatchEmbree) {
    Scene scene;
    test::add_instance(
        scene, test::add_quad_object(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, -1),
        Transform());
    for (const AccelType type : all_accel_types()) {
        const std::string name = accel_type_name(type);
        const auto accel = make_accel(type, scene);
        Ray r;
        r.o = {0.25f, 0.5f, 2};
        r.d = {0, 0, -1};
        const std::optional<Hit> open = accel->intersect(r);
        ASSERT_TRUE(open) << name;
        const float t = open->t;
        EXPECT_GE(t, std::nextafter(2.0f, 0.0f)) << name;
        EXPECT_LE(t, std::nextafter(2.0f, 3.0f)) << name;
        if (name != "embree") EXPECT_EQ(t, 2.0f) << name;
        r.tmax = t;
        EXPECT_TRUE(accel->intersect(r)) << name << ": t = tmax is a hit";
        EXPECT_TRUE(accel->occluded(r)) << name;
        r.tmax = std::nextafter(t, 0.0f);
        EXPECT_FALSE(accel->intersect(r)) << name;
        EXPECT_FALSE(accel->occluded(r)) << name;
        r.tmin = t;
        r.tmax = 10;
        EXPECT_TRUE(accel->intersect(r)) << name << ": t = tmin is a hit";
        EXPECT_TRUE(accel->occluded(r)) << name;
        r.tmin = std::nextafter(t, 3.0f);
        EXPECT_FALSE(accel->intersect(r)) << name;
        EXPECT_FALSE(accel->occluded(r)) << name;
    }
}

TEST(BvhAccel, AgreesWithEmbreeOnTheCornellBox) {
    test::expect_agreement(test::cornell_box(), 30000, 15000, "cornell-box");
}

TEST(BvhAccel, AgreesWithEmbreeOnTheKhronosModels) {
    ASSERT_GE(test::khronos_scenes().size(), 5u);
    for (const auto& [path, scene] : test::khronos_scenes())
        test::expect_agreement(scene, 10000, 5000, path);
}

TEST(BvhAccel, AgreesWithEmbreeOnManyMirroredAndScaledInstances) {
    const Scene scene = test::make_instanced_spheres(300, 5);
    // Each side rounds its own world-to-object transform of the ray, which moves hits
    // near edges by ~1e-5 of these small, stretched triangles: edge disagreements ran at
    // 0.5 to 2.5 in 100,000 rays here (4 seeds of 965,536 rays, none "other"). Double
    // precision settles them for our BVH (it applies the inverse in double, Embree in
    // float), so they are not counted and the default 1 in 100,000 holds.
    const auto reports = test::expect_agreement(scene, 30000, 10000, "instanced spheres");
    // The rays must actually reach the instances, or the agreement means nothing.
    const EmbreeAccel embree(scene);
    const auto rays = test::agreement_rays(scene, embree, 30000, 0);
    std::vector<int> hit_instances(scene.instances.size(), 0);
    for (const CheckRay& r : rays)
        if (const auto h = embree.intersect(r.ray)) hit_instances[h->instance] = 1;
    int reached = 0;
    for (int h : hit_instances) reached += h;
    EXPECT_GT(reached, 250);
}

// Rays from inside closed meshes must hit (Embree's embree_verify "watertight" idea):
// a fine sphere, a cube (rays aimed exactly at its vertices and edges), and a sphere
// whose vertices are 1e4 from the origin, where float spacing is ~1e-3.
TEST(Watertight, RaysFromInsideClosedMeshesAlwaysHit) {
    struct Case {
        std::string name;
        Scene scene;
        Vec3 center;
        float radius;  // of the ball the origins are drawn from
    };
    std::vector<Case> cases;
    {
        Case c{"fine sphere", {}, Vec3(0.1f, -0.2f, 0.3f), 0.5f};
        test::add_instance(c.scene, test::add_sphere_object(c.scene, c.center, 1, 256, 128),
                           Transform());
        cases.push_back(std::move(c));
    }
    {
        Case c{"cube", {}, Vec3(0.0f), 0.3f};
        test::add_instance(c.scene, test::add_cube_object(c.scene, -1), Transform());
        cases.push_back(std::move(c));
    }
    {
        Case c{"far sphere", {}, Vec3(1e4f, -1e4f, 1e4f), 0.5f};
        test::add_instance(c.scene, test::add_sphere_object(c.scene, c.center, 1, 64, 32),
                           Transform());
        cases.push_back(std::move(c));
    }
    {
        Case c{"instanced far sphere", {}, Vec3(1e4f, 2e4f, -1e4f), 0.5f};
        test::add_instance(c.scene, test::add_sphere_object(c.scene, Vec3(0.0f), 1, 64, 32),
                           Transform::translate(c.center));
        cases.push_back(std::move(c));
    }
    for (const Case& c : cases) {
        // Targets: every vertex and edge midpoint (the hardest places), then random
        // directions.
        std::vector<Vec3> vertices, midpoints;
        const Instance& inst = c.scene.instances[0];
        const TriangleMesh& mesh = c.scene.meshes[0];
        for (size_t t = 0; t < mesh.triangle_count() && vertices.size() < 1500; ++t)
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = mesh.positions[mesh.indices[3 * t + k]];
                const Vec3 b = mesh.positions[mesh.indices[3 * t + (k + 1) % 3]];
                vertices.push_back(inst.to_world.point(a));
                midpoints.push_back(inst.to_world.point((a + b) * 0.5f));
            }
        Rng rng(9);
        enum Kind { kVertex, kEdge, kRandom };
        std::vector<std::vector<Ray>> rays(3);
        auto origin = [&] {
            const Vec3 u = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
            return c.center + u * (c.radius * std::cbrt(rng.next_float()));
        };
        for (const auto& [kind, targets] : {std::pair{kVertex, &vertices}, {kEdge, &midpoints}})
            for (const Vec3& target : *targets) {
                Ray r;
                r.o = origin();
                r.d = target - r.o;
                rays[kind].push_back(r);
            }
        for (int i = 0; i < 3000; ++i) {
            Ray r;
            r.o = origin();
            r.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
            rays[kRandom].push_back(r);
        }
        ASSERT_GE(rays[kVertex].size(), 36u);
        for (const AccelType type : all_accel_types()) {
            const std::string name = accel_type_name(type);
            const auto accel = make_accel(type, c.scene);
            int missed[3] = {0, 0, 0}, not_occluded = 0;
            for (int kind = 0; kind < 3; ++kind)
                for (const Ray& r : rays[kind]) {
                    missed[kind] += !accel->intersect(r).has_value();
                    not_occluded += !accel->occluded(r);
                }
            const std::string what = c.name + ", " + name;
            EXPECT_EQ(missed[kEdge], 0) << what << ": rays at edge midpoints";
            EXPECT_EQ(missed[kRandom], 0) << what << ": random rays";
            if (name == "embree") {
                // Embree 3.13.5, even in its robust mode, misses a few rays aimed exactly
                // at vertices where many thin triangles meet (30 of 1500 at the fine
                // sphere's poles; the same rays hit with the origin moved by 1e-6). Its
                // default mode missed 521 of these 6000 rays. Bound it, and record it.
                RecordProperty(c.name + " embree vertex misses", missed[kVertex]);
                EXPECT_LE(missed[kVertex], int(rays[kVertex].size()) / 25) << what;
                continue;
            }
            EXPECT_EQ(missed[kVertex], 0) << what << ": rays at vertices";
            EXPECT_EQ(not_occluded, 0) << what;
        }
    }
}

TEST(Degenerate, ZeroAreaAndNonFiniteTrianglesAreSkippedOrMissed) {
    Scene scene;
    TriangleMesh m;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {nan, 0, 0}, {0, 0, 5}};
    // A line (collinear), a point (repeated vertex), one with a NaN vertex, and one good
    // triangle far away in z, so the object is not empty.
    m.indices = {0, 1, 2, 3, 3, 3, 0, 4, 3, 0, 1, 5};
    for (const Vec3& p : m.positions)
        if (is_finite(p)) m.bounds.expand(p);
    scene.meshes.push_back(m);
    scene.objects.push_back({"degenerate", {0}, m.bounds});
    test::add_instance(scene, 0, Transform());
    for (const AccelType type : all_accel_types()) {
        const std::string name = accel_type_name(type);
        const auto accel = make_accel(type, scene);
        Ray along;  // through the collinear triangle and the point
        along.o = {-1, 0, 0};
        along.d = {1, 0, 0};
        Ray at_point;
        at_point.o = {0, 1, -1};
        at_point.d = {0, 0, 1};
        for (const Ray& r : {along, at_point}) {
            const auto h = accel->intersect(r);
            EXPECT_TRUE(!h || h->prim == 3) << name;  // only the good triangle may be hit
        }
    }
}

TEST(Degenerate, NanAndInfiniteRaysMissWithoutCrashing) {
    const Scene& scene = test::cornell_box();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<Ray> rays;
    for (Vec3 o : {Vec3(nan, 0, 0), Vec3(0, inf, 0), Vec3(-inf, -inf, -inf), Vec3(0.0f)})
        for (Vec3 d : {Vec3(nan, 0, 0), Vec3(0, 0, inf), Vec3(nan, nan, nan), Vec3(0.0f),
                       Vec3(0.3f, -0.2f, 0.9f)}) {
            if (is_finite(o) && is_finite(d) && d != Vec3(0.0f)) continue;  // a valid ray
            Ray r;
            r.o = o;
            r.d = d;
            rays.push_back(r);
        }
    Ray nan_interval;
    nan_interval.d = {0, 0, 1};
    nan_interval.tmin = nan;
    rays.push_back(nan_interval);
    Ray huge;  // finite, but beyond what Embree accepts
    huge.o = {-1e19f, 0, 0};
    huge.d = {1, 0, 0};
    rays.push_back(huge);
    for (const AccelType type : all_accel_types()) {
        const std::string name = accel_type_name(type);
        const auto accel = make_accel(type, scene);
        for (const Ray& r : rays) {
            // Embree itself aborts on such rays (its ray.valid() assertion): Accel must
            // answer them before they get there.
            const auto h = accel->intersect(r);
            const bool occluded = accel->occluded(r);
            EXPECT_FALSE(h) << name << " o=" << r.o.x << "," << r.o.y << "," << r.o.z
                            << " d=" << r.d.x << "," << r.d.y << "," << r.d.z;
            EXPECT_FALSE(occluded) << name;
        }
    }
}

TEST(BvhAccel, EmptySceneAndEmptyObjectsMiss) {
    Scene empty;
    Scene hollow;  // an instance of an object without triangles
    hollow.objects.push_back({"nothing", {}, {}});
    test::add_instance(hollow, 0, Transform());
    for (const Scene* s : {&empty, &hollow})
        for (const AccelType type : all_accel_types()) {
            const std::string name = accel_type_name(type);
            const auto accel = make_accel(type, *s);
            Ray r;
            r.d = {0, 0, 1};
            EXPECT_FALSE(accel->intersect(r)) << name;
            EXPECT_FALSE(accel->occluded(r)) << name;
        }
}

}  // namespace
}  // namespace penumbra
