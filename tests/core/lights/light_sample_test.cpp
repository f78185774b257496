// LightSample::p: every light sample at a finite distance gives the point it sampled,
// which shadow rays aim at (spawn_ray_to), so it must be the point at dist along wi.
#include <gtest/gtest.h>

#include <cmath>

#include "core/lights/point_light.h"
#include "core/lights/spot_light.h"
#include "core/lights/triangle_light.h"
#include "core/sampling/rng.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// ls.p is ref + wi * dist to within rounding (a few ULPs of the distance).
void expect_point_at_dist(const LightSample& ls, Vec3 ref, const char* light) {
    const Vec3 along = ref + ls.wi * ls.dist;
    EXPECT_LT(length(ls.p - along), 1e-5f * (ls.dist + length(ref))) << light;
}

TEST(LightSample, PunctualLightsGiveTheirPosition) {
    const Vec3 at(1.5f, 4, -2);
    const PointLight point(at, Spectrum(10));
    const SpotLight spot(at, {0, -1, 0}, Spectrum(10), 0.3f, 0.6f);
    for (const Vec3 ref : {Vec3(0, 0, 0), Vec3(1, 0.5f, -2.5f), Vec3(-30, 2, 7)}) {
        const std::optional<LightSample> a = point.sample_Li({ref, {0, 1, 0}}, {0.3f, 0.7f}, 0);
        ASSERT_TRUE(a);
        EXPECT_EQ(a->p, at);
        expect_point_at_dist(*a, ref, "point");
    }
    // Inside the spot's cone (straight below it).
    const Vec3 below = at - Vec3(0.1f, 3, 0);
    const std::optional<LightSample> b = spot.sample_Li({below, {0, 1, 0}}, {0.3f, 0.7f}, 0);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->p, at);
    expect_point_at_dist(*b, below, "spot");
}

// Both of a triangle's strategies: solid-angle sampling near it, area sampling far away
// (where the spherical triangle is too small to map).
TEST(LightSample, TriangleLightsGiveThePointOnTheTriangle) {
    Scene scene;
    MaterialDesc m;
    m.emissive = Spectrum(1);
    m.double_sided = true;
    scene.materials.push_back(m);
    const Vec3 v0(2, 3, 1), v1(4, 3.5f, 1), v2(2.5f, 3, 3);
    const uint32_t quad = test::add_quad_object(scene, v0, v1, v2, v0 + v2 - v1, 0);
    test::add_instance(scene, quad, Transform());
    const TriangleLight light(scene, 0, 0, 0, Spectrum(1));
    const Vec3 n = normalize(cross(v1 - v0, v2 - v0));
    Rng rng(5);
    int samples = 0;
    for (const Vec3 ref : {Vec3(3, 1, 2), Vec3(3, 0, 1.5f), Vec3(3e4f, -2e4f, 1e4f)})
        for (int i = 0; i < 64; ++i) {
            const std::optional<LightSample> ls =
                light.sample_Li({ref, {0, 1, 0}}, {rng.next_float(), rng.next_float()}, 0);
            if (!ls) continue;
            ++samples;
            expect_point_at_dist(*ls, ref, "triangle");
            EXPECT_NEAR(dot(ls->p - v0, n), 0, 1e-5f);  // on the triangle's plane
        }
    EXPECT_GT(samples, 100);
}

}  // namespace
}  // namespace penumbra
