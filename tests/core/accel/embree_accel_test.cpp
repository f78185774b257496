#include "core/accel/embree_accel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/accel/triangle_intersect.h"
#include "core/accel/triangle_plane.h"
#include "core/facet.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "study/accel_check.h"
#include "support/accel_agreement.h"
#include "support/scene_builder.h"
#include "support/surface_point_checks.h"

namespace penumbra {
namespace {

TEST(EmbreeAccel, SharedMeshIsBuiltOnceAndBothInstancesAreHit) {
    Scene scene;
    const int mat = test::add_lambertian(scene, Spectrum(0.5f));
    const uint32_t cube = test::add_cube_object(scene, mat);
    test::add_instance(scene, cube, Transform::translate({-2, 0, 0}));
    test::add_instance(scene, cube, Transform::translate({2, 0, 0}));
    EmbreeBuildOptions two_levels;  // else the 24 triangles are flattened
    two_levels.flatten = false;
    EmbreeAccel accel(scene, two_levels);
    EXPECT_EQ(accel.stats().object_scenes, 1u);
    EXPECT_EQ(accel.stats().instances, 2u);

    for (uint32_t i = 0; i < 2; ++i) {
        const float x = i == 0 ? -2.0f : 2.0f;
        Ray r;
        r.o = {x, 0, 10};
        r.d = {0, 0, -1};
        const auto hit = accel.intersect(r);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hit->instance, i);
        EXPECT_EQ(hit->mesh, 0u);
        EXPECT_NEAR(hit->t, 9.5f, 1e-5f);
        EXPECT_TRUE(accel.occluded(r));
    }
    Ray miss;
    miss.o = {0, 0, 10};
    miss.d = {0, 0, -1};
    EXPECT_FALSE(accel.intersect(miss).has_value());
    EXPECT_FALSE(accel.occluded(miss));
    EXPECT_EQ(accel.rays_traced(), 6u);
}

TEST(EmbreeAccel, InstanceTransformsApplyToHits) {
    Scene scene;
    const uint32_t cube = test::add_cube_object(scene, -1);
    // Non-uniform scale and a mirror: the box spans z in [-2, 2] after the transform.
    test::add_instance(scene, cube, Transform::scale({1, 1, -4}));
    EmbreeAccel accel(scene);
    Ray r;
    r.o = {0.1f, 0.2f, 10};
    r.d = {0, 0, -1};
    const auto hit = accel.intersect(r);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 8.0f, 1e-5f);
}

TEST(EmbreeAccel, RespectsRayInterval) {
    Scene scene;
    const uint32_t cube = test::add_cube_object(scene, -1);
    test::add_instance(scene, cube, Transform());
    EmbreeAccel accel(scene);
    Ray r;
    r.o = {0, 0, 10};
    r.d = {0, 0, -1};
    r.tmax = 9.0f;  // stops short of the cube face at t = 9.5
    EXPECT_FALSE(accel.intersect(r).has_value());
    EXPECT_FALSE(accel.occluded(r));
    r.tmax = 100;
    r.tmin = 9.6f;  // starts inside: the far face at t = 10.5
    const auto hit = accel.intersect(r);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 10.5f, 1e-5f);
}

// Embree reads a mesh's positions in place when they have a spare element of capacity
// for its 16-byte loads, and its indices always; otherwise it copies the positions. Both
// ways give the same hits on a 4608-triangle sphere.
TEST(EmbreeAccel, SharesPaddedVertexArraysAndCopiesOthers) {
    Scene shared, copied;
    for (Scene* s : {&shared, &copied}) {
        const uint32_t sphere = test::add_sphere_object(*s, -1, 48, 48);
        test::add_instance(*s, sphere, Transform());
    }
    std::vector<Vec3>& padded = shared.meshes[0].positions;
    padded.reserve(padded.size() + 1);
    std::vector<Vec3>& exact = copied.meshes[0].positions;
    exact.shrink_to_fit();
    ASSERT_EQ(exact.capacity(), exact.size());  // libstdc++ honours shrink_to_fit
    const EmbreeAccel a(shared), b(copied);
    EXPECT_EQ(a.copied_bytes(), 0u);
    EXPECT_EQ(b.copied_bytes(), exact.size() * sizeof(Vec3));
    EXPECT_GT(b.stats().memory_bytes, a.stats().memory_bytes);

    Rng rng(11);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        Ray r;
        r.o = 3.0f * square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        // Aimed within 0.5 of the unit sphere's centre: every ray hits.
        r.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()}) * 0.5f - r.o;
        const auto ha = a.intersect(r), hb = b.intersect(r);
        ASSERT_EQ(ha.has_value(), hb.has_value());
        if (!ha) continue;
        ++hits;
        EXPECT_EQ(ha->prim, hb->prim);
        EXPECT_EQ(ha->t, hb->t);
    }
    EXPECT_EQ(hits, 2000);
}

// Packets and streams (bench/accel_bench.cpp measures them) answer exactly what single
// rays do, including rays with short intervals and untraceable ones.
TEST(EmbreeAccel, PacketsAndStreamsAgreeWithSingleRays) {
    Scene scene;
    const int mat = test::add_lambertian(scene, Spectrum(0.5f));
    const uint32_t cube = test::add_cube_object(scene, mat);
    test::add_instance(scene, cube, Transform::translate({-1, 0, 0}));
    test::add_instance(scene, cube,
                       Transform::trs({1, 0.3f, 0}, Quat{0, 0.38f, 0, 0.92f}, {1, 2, 1}));
    EmbreeAccel accel(scene);
    Rng rng(5);
    std::vector<Ray> rays(8 * 64);
    for (Ray& r : rays) {
        r.o =
            Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f) * 6.0f;
        // Aimed near the cubes, so that about half the rays hit.
        const Vec3 target(4 * rng.next_float() - 2, 2 * rng.next_float() - 1,
                          2 * rng.next_float() - 1);
        r.d = normalize(target - r.o);
        r.tmax = rng.next_float() < 0.3f ? 1.5f : std::numeric_limits<float>::infinity();
    }
    rays[3].d = {0, 0, 0};
    rays[20].o.x = std::numeric_limits<float>::quiet_NaN();
    int hits = 0, blocked = 0;
    for (size_t start = 0; start < rays.size(); start += 8) {
        std::optional<Hit> packet[8];
        accel.intersect8(*reinterpret_cast<const Ray(*)[8]>(&rays[start]), packet);
        for (size_t i = 0; i < 8; ++i) {
            const auto single = accel.intersect(rays[start + i]);
            ASSERT_EQ(single.has_value(), packet[i].has_value()) << start + i;
            if (!single) continue;
            ++hits;
            EXPECT_EQ(single->t, packet[i]->t);
            EXPECT_EQ(single->instance, packet[i]->instance);
            EXPECT_EQ(single->prim, packet[i]->prim);
            EXPECT_EQ(single->b1, packet[i]->b1);
        }
    }
    for (bool coherent : {false, true}) {
        std::unique_ptr<bool[]> stream(new bool[rays.size()]);
        accel.occluded_stream(rays.data(), rays.size(), stream.get(), coherent);
        for (size_t i = 0; i < rays.size(); ++i) {
            ASSERT_EQ(stream[i], accel.occluded(rays[i])) << i;
            blocked += stream[i];
        }
    }
    // Not vacuous: both answers occur.
    EXPECT_GT(hits, 50);
    EXPECT_LT(hits, int(rays.size()) - 50);
    EXPECT_GT(blocked, 100);
}

// Objects that instancing does not pay for go into the top level as world-space
// triangles (EmbreeBuildOptions::flatten): small in all (here at most 1000 triangles),
// however transformed; larger objects and moving instances stay instanced. The Hit is the one
// through instances: same instance, mesh and triangle, t and u, v within the
// cross-check's tolerances (accel_check.h), on every kind of check ray.
// The flattening tests' objects: a sphere of 528 triangles placed once (mirrored, scaled
// non-uniformly), a cube of 12 placed twice, and a sphere of 2208 placed once, the object
// the flattening budget of 1000 triangles leaves instanced; returns the last.
uint32_t add_flattening_objects(Scene& scene) {
    const uint32_t once = test::add_sphere_object(scene, -1, 12, 24);
    test::add_instance(scene, once,
                       Transform::trs({-3, 0, 0}, Quat{0, 0.38f, 0, 0.92f}, {1, 2, -1}));
    const uint32_t small = test::add_cube_object(scene, -1);
    test::add_instance(scene, small, Transform::translate({0, 2, 0}));
    test::add_instance(scene, small,
                       Transform::trs({0, -2, 0}, Quat{0.38f, 0, 0, 0.92f}, {0.5f, 1, 1}));
    const uint32_t big = test::add_sphere_object(scene, -1);
    test::add_instance(scene, big, Transform::translate({3, 1.5f, 0}));
    return big;
}

TEST(EmbreeAccel, FlattenedObjectsGiveTheHitsOfInstances) {
    Scene scene;
    const uint32_t big = add_flattening_objects(scene);  // the big sphere twice
    test::add_instance(scene, big,
                       Transform::scale({1, 1, -1}) * Transform::translate({3, -1.5f, 0}));
    const uint32_t moving = test::add_cube_object(scene, -1);
    test::add_instance(scene, moving, Transform::translate({0, 0, 3}));
    scene.instances.back().motion = {Transform::translate({0, 0, 3}),
                                     Transform::translate({0.5f, 0, 3})};
    EmbreeBuildOptions options;
    options.flatten_triangles = 1000;
    const EmbreeAccel flat(scene, options);
    EmbreeBuildOptions two_levels;
    two_levels.flatten = false;
    const EmbreeAccel nested(scene, two_levels);
    EXPECT_EQ(flat.flattened(), 3u);
    EXPECT_EQ(flat.stats().instances, 3u);
    EXPECT_EQ(flat.stats().object_scenes, 2u);
    EXPECT_EQ(nested.flattened(), 0u);
    EXPECT_EQ(nested.stats().object_scenes, 4u);

    const std::vector<CheckRay> rays = test::agreement_rays(scene, nested, 20000, 5000);
    const TraceResults flat_hits = trace_rays(flat, rays);
    const AgreementReport rep = compare_results(scene, rays, trace_rays(nested, rays), flat_hits,
                                                "two levels", "flattened");
    std::string examples;
    for (const std::string& e : rep.examples) examples += "\n  " + e;
    EXPECT_EQ(rep.count(Disagreement::Other), 0u) << examples;
    EXPECT_TRUE(rep.passes(1e-4)) << rep.disagreements() << " of " << rep.rays << examples;
    // Not vacuous: the rays reach every instance through both paths.
    std::vector<int> reached(scene.instances.size(), 0);
    for (const auto& h : flat_hits.hits)
        if (h) ++reached[h->instance];
    for (size_t i = 0; i < reached.size(); ++i) EXPECT_GT(reached[i], 100) << i;
}

// Hits on flattened objects point to their triangle's precomputed facet (core/facet.h),
// and the surface point built from it is the one built without it, bit for bit: smooth
// (a mirrored, non-uniformly scaled sphere) and flat (a cube placed twice) triangles.
// Instanced objects' hits carry none.
TEST(EmbreeAccel, FlattenedHitsCarryFacetsThatGiveTheSameSurfacePoints) {
    Scene scene;
    add_flattening_objects(scene);
    EmbreeBuildOptions options;
    options.flatten_triangles = 1000;
    const EmbreeAccel accel(scene, options);
    ASSERT_EQ(accel.flattened(), 3u);
    EXPECT_EQ(accel.facet_bytes(), (528 + 2 * 12) * (sizeof(Facet) + sizeof(TrianglePlane)));

    const std::vector<CheckRay> rays = test::agreement_rays(scene, accel, 5000, 2000);
    const TraceResults traced = trace_rays(accel, rays);
    std::vector<int> with_facet(scene.instances.size(), 0);
    for (size_t i = 0; i < rays.size(); ++i) {
        const std::optional<Hit>& hit = traced.hits[i];
        if (!hit) continue;
        const bool flattened = hit->instance < 3;
        ASSERT_EQ(hit->facet != nullptr, flattened) << "instance " << hit->instance;
        if (!hit->facet) continue;
        ++with_facet[hit->instance];
        Hit bare = *hit;
        bare.facet = nullptr;
        test::expect_same_surface_point(make_surface_point(scene, rays[i].ray, *hit),
                                        make_surface_point(scene, rays[i].ray, bare),
                                        "ray " + std::to_string(i));
    }
    for (size_t ii = 0; ii < 3; ++ii) EXPECT_GT(with_facet[ii], 100) << ii;
}

}  // namespace
}  // namespace penumbra
