#include "core/accel/accel.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>
#include <memory>

#include "core/accel/embree_accel.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

Ray ray_at(float x) {
    Ray r;
    r.o = {x, 0, 10};
    r.d = {0, 0, -1};
    return r;
}

TEST(IsTraceable, EachComponentAndTheIntervalCanMakeARayUntraceable) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(is_traceable(ray_at(0)));
    for (int a = 0; a < 3; ++a)
        for (float bad : {nan, inf, -inf, 1e19f, -1.9e18f}) {
            Ray o = ray_at(0), d = ray_at(0);
            o.o[a] = bad;
            d.d[a] = bad;
            EXPECT_FALSE(is_traceable(o)) << a << " " << bad;
            EXPECT_FALSE(is_traceable(d)) << a << " " << bad;
        }
    Ray big = ray_at(1.8e18f);  // just inside Embree's FLT_LARGE
    EXPECT_TRUE(is_traceable(big));
    // The bound itself, either sign, and the float above it (the test compares bits).
    EXPECT_TRUE(is_traceable(ray_at(1.844e18f)));
    EXPECT_TRUE(is_traceable(ray_at(-1.844e18f)));
    EXPECT_FALSE(is_traceable(ray_at(std::nextafter(1.844e18f, inf))));
    EXPECT_FALSE(is_traceable(ray_at(-std::nextafter(1.844e18f, inf))));
    EXPECT_FALSE(is_traceable(ray_at(-nan)));  // a NaN with its sign bit set
    Ray zero = ray_at(0);
    zero.d = {0, 0, 0};
    EXPECT_FALSE(is_traceable(zero));
    zero.d = {0, -0.0f, 1e-30f};
    EXPECT_TRUE(is_traceable(zero));
    Ray interval = ray_at(0);
    interval.tmin = interval.tmax = 2;
    EXPECT_TRUE(is_traceable(interval));
    interval.tmin = std::nextafter(2.0f, 3.0f);
    EXPECT_FALSE(is_traceable(interval));
    interval.tmin = nan;
    EXPECT_FALSE(is_traceable(interval));
    // tmin shares a 16-byte span with d in the SSE test, and d.x one with o: neither
    // interval end is bounded by the magnitude tests.
    interval.tmin = 1e30f;
    interval.tmax = inf;
    EXPECT_TRUE(is_traceable(interval));
    Ray along_x = ray_at(0);
    along_x.d = {-1, 0, 0};
    EXPECT_TRUE(is_traceable(along_x));
    along_x.d.x = 1e19f;  // in o's span as well as d's
    EXPECT_FALSE(is_traceable(along_x));
}

Scene cube_scene() {
    Scene scene;
    const uint32_t cube = test::add_cube_object(scene, -1);
    test::add_instance(scene, cube, Transform());
    return scene;
}

// The per-thread counter is cached in a thread_local keyed by the accelerator: switching
// between accelerators, replacing one (a new one may reuse the address) and tracing from
// several threads must all count exactly.
TEST(AccelRayCount, CountsPerAcceleratorAcrossSwitchesAndThreads) {
    const Scene scene = cube_scene();
    auto a = std::make_unique<EmbreeAccel>(scene);
    EmbreeAccel b(scene);
    for (int i = 0; i < 5; ++i) {
        a->intersect(ray_at(0));
        b.occluded(ray_at(0));
        b.intersect(ray_at(5));
    }
    EXPECT_EQ(a->rays_traced(), 5u);
    EXPECT_EQ(b.rays_traced(), 10u);
    a.reset();
    a = std::make_unique<EmbreeAccel>(scene);
    EXPECT_EQ(a->rays_traced(), 0u);
    a->occluded(ray_at(0));
    EXPECT_EQ(a->rays_traced(), 1u);
    EXPECT_EQ(b.rays_traced(), 10u);

    tbb::task_arena arena(4);
    arena.execute([&] {
        tbb::parallel_for(0, 20000, [&](int i) {
            const Ray r = ray_at(i % 2 ? 0.0f : 5.0f);
            (i % 3 ? a->intersect(r).has_value() : a->occluded(r));
            b.occluded(r);
        });
    });
    EXPECT_EQ(a->rays_traced(), 20001u);
    EXPECT_EQ(b.rays_traced(), 20010u);
}

}  // namespace
}  // namespace penumbra
