// Absorbing volumes (KHR_materials_volume) through the path and direct integrators with
// Embree, on index-matched boxes (IOR 1: no Fresnel, no bending), where every path is
// one deterministic line and the answer is Beer-Lambert exactly: an emitting backdrop seen
// through chord x keeps exp(-sigma_a x) per channel; nested boxes take the inner medium;
// overlapping ones the medium entered last; grazing rays past edges and corners never
// stay in a medium they left; a light inside a volume lights through it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/lights/point_light.h"
#include "core/media/homogeneous_medium.h"
#include "integrators/integrator.h"
#include "support/scene_builder.h"
#include "support/option_names.h"

namespace penumbra {
namespace {

const float kInf = std::numeric_limits<float>::infinity();

// An index-matched volume: fully transmissive, smooth, IOR 1, absorbing colour at distance.
MaterialDesc volume(Spectrum color, float distance) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = 0;
    m.ior = 1;
    m.transmission = 1;
    m.thickness = 1;
    m.attenuation_color = color;
    m.attenuation_distance = distance;
    return m;
}

Spectrum sigma(Spectrum color, float distance) {
    return HomogeneousMedium::sigma_a_from_attenuation(color, distance);
}

Spectrum beer(Spectrum sigma_a, float x) {
    return {std::exp(-sigma_a.x * x), std::exp(-sigma_a.y * x), std::exp(-sigma_a.z * x)};
}

// Length of the ray o + t d (unit d) inside the box [lo, hi] (slab test).
float chord(Vec3 o, Vec3 d, Vec3 lo, Vec3 hi) {
    float t0 = 0, t1 = kInf;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1 / d[a];
        float n = (lo[a] - o[a]) * inv, f = (hi[a] - o[a]) * inv;
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
    }
    return t1 > t0 ? t1 - t0 : 0.0f;
}

struct Tracer {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    std::unique_ptr<LightSet> lights;

    void build(Spectrum environment) {
        accel = std::make_unique<EmbreeAccel>(scene);
        lights = std::make_unique<LightSet>(
            scene, is_black(environment) ? nullptr
                                         : std::make_unique<EnvironmentLight>(environment, 20.0f));
    }
    Spectrum Li(Vec3 o, Vec3 d, const std::string& integrator = "path", uint32_t index = 0) const {
        IntegratorOptions opt;
        opt.max_depth = 16;
        opt.rr_depth = 100;  // no Russian roulette: every path here is one exact line
        const auto integ = make_integrator(test::integrator_named(integrator), opt);
        IndependentSampler sampler(1, 0);
        sampler.start_pixel_sample({0, 0}, index);
        Ray r;
        r.o = o;
        r.d = d;
        return integ->Li(r, RenderContext{scene, *accel, *lights}, sampler);
    }
};

// A box [lo, hi] of material `material` (the cube object, scaled and moved).
void add_box(Scene& scene, int material, Vec3 lo, Vec3 hi) {
    const uint32_t cube = test::add_cube_object(scene, material);
    test::add_instance(scene, cube,
                       Transform::translate((lo + hi) * 0.5f) * Transform::scale(hi - lo));
}

// The background: a black box around everything, 20 away, that emits Le inwards. Unlike
// an environment it is reached at a finite distance, so a path wrongly still inside a
// medium after leaving it is attenuated on the way (by exp(-sigma 20)) and shows.
void add_backdrop(Scene& scene, float Le) {
    MaterialDesc m;
    m.base_color = {0, 0, 0, 1};
    m.metallic = 0;
    m.specular = 0;
    m.emissive = Spectrum(Le);
    m.double_sided = true;
    scene.materials.push_back(m);
    add_box(scene, int(scene.materials.size()) - 1, Vec3(-20), Vec3(20));
}

TEST(VolumeAbsorption, BackgroundThroughASlabIsBeerLambertPerChannel) {
    struct Case {
        Spectrum color;
        float distance;
    };
    const Case cases[] = {{{0.8f, 0.5f, 0.2f}, 0.7f}, {{0.1f, 0.9f, 0.99f}, 2.5f},
                          {{0.5f, 0.5f, 0.5f}, 0.05f}, {{1, 1, 1}, 1.0f}};
    const Vec3 lo(-1, -0.5f, -2), hi(1.5f, 0.5f, 1);
    Rng rng(5);
    for (const Case& c : cases) {
        Tracer t;
        t.scene.materials.push_back(volume(c.color, c.distance));
        add_box(t.scene, 0, lo, hi);
        add_backdrop(t.scene, 1);
        t.build(Spectrum(0));
        const Spectrum s = sigma(c.color, c.distance);
        int checked = 0;
        for (int i = 0; i < 300; ++i) {
            // From outside, at random points and directions through the box.
            const Vec3 target(lo.x + (hi.x - lo.x) * rng.next_float(),
                              lo.y + (hi.y - lo.y) * rng.next_float(),
                              lo.z + (hi.z - lo.z) * rng.next_float());
            const Vec3 o(8 * rng.next_float() - 4, 3.0f, 8 * rng.next_float() - 4);
            const Vec3 d = normalize(target - o);
            const float x = chord(o, d, lo, hi);
            if (x < 1e-3f) continue;
            const Spectrum L = t.Li(o, d, i % 2 ? "path" : "direct");
            const Spectrum expected = beer(s, x);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(L[ch], expected[ch], 2e-5f + 1e-4f * expected[ch])
                    << "colour " << c.color[ch] << " at " << c.distance << ", chord " << x;
            ++checked;
        }
        EXPECT_GT(checked, 250);
    }
}

TEST(VolumeAbsorption, InfiniteDistanceIsClear) {
    Tracer t;
    t.scene.materials.push_back(volume({0.1f, 0.2f, 0.3f}, kInf));
    add_box(t.scene, 0, {-1, -1, -1}, {1, 1, 1});
    t.build(Spectrum(0.7f));
    EXPECT_EQ(t.Li({0, 0, 5}, {0.1f, 0.05f, -1}), Spectrum(0.7f));
}

TEST(VolumeAbsorption, NestedVolumesTakeTheInnerMedium) {
    // Liquid [-0.5, 0.5]^3 in glass [-1, 1]^3, both index-matched: along the z axis 1 of
    // glass and 1 of liquid.
    Tracer t;
    const Spectrum cg(0.9f, 0.6f, 0.3f), cl(0.2f, 0.7f, 0.95f);
    t.scene.materials.push_back(volume(cg, 1.0f));
    t.scene.materials.push_back(volume(cl, 0.5f));
    add_box(t.scene, 0, {-1, -1, -1}, {1, 1, 1});
    add_box(t.scene, 1, {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    add_backdrop(t.scene, 1);
    t.build(Spectrum(0));
    const Spectrum expected = beer(sigma(cg, 1.0f), 1) * beer(sigma(cl, 0.5f), 1);
    const Spectrum L = t.Li({0.01f, 0.02f, 5}, {0, 0, -1});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(L[c], expected[c], 1e-5f + 1e-4f * expected[c]);
}

TEST(VolumeAbsorption, OverlapsTakeTheMediumEnteredLast) {
    // Along -z: enter A at z = 1, B at 0.5, leave A at 0 (out of order), leave B at -0.5.
    // Inside both (0.5 to 0) the path is in B, entered last: 0.5 of A, 1 of B.
    Tracer t;
    const Spectrum ca(0.3f, 0.6f, 0.9f), cb(0.8f, 0.4f, 0.7f);
    t.scene.materials.push_back(volume(ca, 1.0f));
    t.scene.materials.push_back(volume(cb, 1.0f));
    add_box(t.scene, 0, {-1, -1, 0}, {1, 1, 1});
    add_box(t.scene, 1, {-1.5f, -1.5f, -0.5f}, {1.5f, 1.5f, 0.5f});
    add_backdrop(t.scene, 1);
    t.build(Spectrum(0));
    const Spectrum expected = beer(sigma(ca, 1), 0.5f) * beer(sigma(cb, 1), 1);
    const Spectrum L = t.Li({0.1f, 0.2f, 4}, {0, 0, -1});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(L[c], expected[c], 1e-5f + 1e-4f * expected[c]);
}

TEST(VolumeAbsorption, GrazingRaysPastEdgesAndCornersDoNotStayInside) {
    // Rays skimming the box's edges and corners (within 1e-6 to 1e-2 of them, at grazing
    // angles to a face) must see the background through their chord; a path stuck in
    // the medium after it left would escape inside it and see black.
    Tracer t;
    const Spectrum c(0.3f, 0.3f, 0.3f);
    t.scene.materials.push_back(volume(c, 0.2f));
    const Vec3 lo(-1, -1, -1), hi(1, 1, 1);
    add_box(t.scene, 0, lo, hi);
    add_backdrop(t.scene, 1);
    t.build(Spectrum(0));
    const Spectrum s = sigma(c, 0.2f);
    Rng rng(11);
    int wrong = 0, stuck = 0, total = 0;
    float max_error = 0;
    for (int i = 0; i < 4000; ++i) {
        // A point near an edge (two coordinates near +-1) or a corner (three).
        Vec3 p;
        const bool corner = i % 4 == 0;
        const int free_axis = i % 3;
        for (int a = 0; a < 3; ++a) {
            const float sign = rng.next_float() < 0.5f ? -1.0f : 1.0f;
            const float offset = std::pow(10.0f, -6 + 4 * rng.next_float()) *
                                 (rng.next_float() < 0.5f ? -1.0f : 1.0f);
            p[a] = a == free_axis && !corner ? 2 * rng.next_float() - 1 : sign * (1 + offset);
        }
        // A direction nearly parallel to a face through p.
        Vec3 d(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1);
        d[i % 3] *= 1e-3f;
        d = normalize(d);
        const Vec3 o = p - d * 10.0f;
        const float x = chord(o, d, lo, hi);
        const Spectrum L = t.Li(o, d);
        const float expected = beer(s, x).x;
        ++total;
        const float err = std::abs(L.x - expected);
        max_error = std::max(max_error, err);
        if (err > 1e-3f) ++wrong;
        if (L.x < 1e-3f && expected > 0.1f) ++stuck;
    }
    // Along a face at 1e-4 radians, float rounding of the hit points (1e-7) moves the
    // chord by 1e-3: a few such rays are off by more than 1e-3 (10 of 4000 measured, at
    // most 2.3e-3), none by more than 5e-3. A path stuck in the medium (black) would
    // be off by up to 1; a hit at an edge that Embree reports within rounding outside
    // the face once entered the box and escaped at once: escaping rays have left.
    EXPECT_EQ(stuck, 0) << "of " << total;
    EXPECT_LE(wrong, total / 200) << "of " << total;
    EXPECT_LT(max_error, 5e-3f);
}

TEST(VolumeAbsorption, LightInsideAVolumeLightsThroughIt) {
    // A Lambertian floor (albedo 1) and a point light h above it, both inside an
    // absorbing index-matched box; looking straight down from outside through depth D
    // of the medium to the floor: L = (1 / pi) I / h^2 exp(-sigma (h + D)).
    for (const char* integrator : {"path", "direct"}) {
        Tracer t;
        const Spectrum c(0.5f, 0.8f, 0.95f);
        t.scene.materials.push_back(volume(c, 1.0f));
        add_box(t.scene, 0, {-5, -1, -5}, {5, 5, 5});
        const int floor = test::add_lambertian(t.scene, Spectrum(1));
        const uint32_t quad = test::add_quad_object(t.scene, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2},
                                                    {-2, 0, -2}, floor);
        test::add_instance(t.scene, quad, Transform::scale(Vec3(1)));
        const float h = 1.5f, I = 4;
        t.scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, h, 0), Spectrum(I)));
        t.build(Spectrum(0));
        const Spectrum L = t.Li({0.001f, 8, 0.002f}, {0, -1, 0}, integrator);
        const Spectrum expected = beer(sigma(c, 1.0f), h + 5) * (I / (kPi * h * h));
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(L[ch], expected[ch], 1e-4f * expected[ch]) << integrator;
    }
}

}  // namespace
}  // namespace penumbra
