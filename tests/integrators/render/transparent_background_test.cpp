// A transparent background (IntegratorOptions::transparent_background with the film's
// Aov::Coverage) on scenes with known answers: an orthographic camera maps pixel (x, y)
// to world (x - 4, 4 - y), a box filter keeps each sample in its own pixel, and a
// Lambertian quad of albedo 0.5 facing the camera under a uniform white environment
// sends 0.5 (the white furnace). Alpha is the pixels' analytic coverage, the colour of
// misses is exactly 0, and what the camera sees of geometry is unchanged bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/lights/environment_light.h"
#include "core/scene/coverage.h"
#include "integrators/render.h"
#include "support/scene_builder.h"
#include "support/statistics/estimate.h"

namespace penumbra {
namespace {

constexpr int kSize = 8;
constexpr float kAlbedo = 0.5f;
// The quad's right edge, in pixels from the image's left: column 3 is 30% covered.
constexpr float kEdge = 3.3f;

// A quad in the plane z, from world x0 to x1 and y0 to y1, facing +z (the camera).
void add_quad(Scene& scene, float x0, float x1, float y0, float y1, float z, int material,
              int node = 0) {
    const uint32_t object =
        test::add_quad_object(scene, {x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}, material);
    const uint32_t instance = test::add_instance(scene, object, Transform());
    scene.instances[instance].node = node;
}

struct Options {
    bool transparent = true;
    IntegratorType integrator = IntegratorType::Path;
    uint32_t spp = 1024;
    int threads = 0;
    AovSet aovs;
    bool two_passes = false;
    double target_error = 0;  // adaptive sampling from 16 samples
};

Film render_scene(const Scene& scene, const Options& o) {
    EmbreeAccel accel(scene);
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(1), 20.0f));
    const RenderContext ctx{scene, accel, lights, scene_has_alpha(scene)};
    const OrthographicCamera camera(Transform::translate({0, 0, 5}), kSize / 2.0f, kSize / 2.0f,
                                    kSize, kSize);
    IntegratorOptions io;
    io.transparent_background = o.transparent;
    const auto integrator = make_integrator(o.integrator, io);
    RenderOptions opt;
    opt.spp = o.spp;
    opt.seed = 7;
    opt.threads = o.threads;
    opt.progress = false;
    opt.filter = FilterType::Box;
    // Independent samples, so that the tolerances below, derived for independent
    // samples, hold as stated (strata would only do better, unevenly).
    opt.sampler = SamplerType::Independent;
    opt.aovs = o.aovs;
    opt.target_error = o.target_error;
    opt.min_spp = 16;
    if (o.transparent) opt.aovs.add(Aov::Coverage);
    if (!o.two_passes) return render(ctx, camera, *integrator, opt);
    Film film(kSize, kSize, opt.aovs);
    render_samples(ctx, camera, *integrator, opt, film, 0, o.spp / 4);
    render_samples(ctx, camera, *integrator, opt, film, o.spp / 4, o.spp);
    return film;
}

// The quad left of kEdge, over the whole height.
Scene edge_scene(float albedo = kAlbedo) {
    Scene scene;
    add_quad(scene, -10, kEdge - kSize / 2.0f, -10, 10, 0,
             test::add_lambertian(scene, Spectrum(albedo)));
    return scene;
}

TEST(TransparentBackground, AlphaIsTheAnalyticCoverageOfAnEdge) {
    const Options o;
    const Image img = render_scene(edge_scene(), o).resolve();
    // Column 3's alpha is the share of its samples left of the edge: binomial, so within
    // 5 sigma = 5 sqrt(p (1 - p) / n) of p = 0.3 per pixel (0.072 at 1024 samples), and
    // the column's mean within 5 sigma / sqrt(8).
    const double p = kEdge - 3, sigma = std::sqrt(p * (1 - p) / o.spp);
    double column = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float* px = img.at(x, y);
            if (x < 3) {
                EXPECT_EQ(px[3], 1.0f) << x << "," << y;
            } else if (x > 3) {
                EXPECT_EQ(px[3], 0.0f) << x << "," << y;
                for (int c = 0; c < 3; ++c) EXPECT_EQ(px[c], 0.0f) << x << "," << y;
            } else {
                EXPECT_NEAR(px[3], p, 5 * sigma) << y;
                column += px[3] / kSize;
            }
        }
    }
    EXPECT_NEAR(column, p, 5 * sigma / std::sqrt(double(kSize)));
}

TEST(TransparentBackground, WhatTheCameraSeesOfGeometryIsUnchanged) {
    Options o;
    const Image clear = render_scene(edge_scene(), o).resolve();
    o.transparent = false;
    const Image opaque = render_scene(edge_scene(), o).resolve();
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                const float a = clear.at(x, y)[3], t = clear.at(x, y)[c], u = opaque.at(x, y)[c];
                EXPECT_EQ(opaque.at(x, y)[3], 1.0f);
                if (x < 3)  // the same samples along the same paths: the same bits
                    EXPECT_EQ(t, u) << x << "," << y;
                else if (x > 3)  // the environment seen directly
                    EXPECT_EQ(u, 1.0f) << x << "," << y;
                else  // the misses' share of the environment's radiance 1, and no more
                    EXPECT_NEAR(u - t, 1 - a, 1e-5f) << y;
            }
}

TEST(TransparentBackground, TheLitObjectKeepsItsFurnaceRadianceAndEdgesArePremultiplied) {
    const Options o;
    const Image img = render_scene(edge_scene(), o).resolve();
    // The covered pixels' spread estimates one pixel's standard error s (1024 samples).
    double sum = 0, sum2 = 0;
    const int n = 3 * kSize;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < 3; ++x) {
            const double v = img.at(x, y)[0];
            sum += v;
            sum2 += v * v;
        }
    const double mean = sum / n, s = std::sqrt(std::max(0.0, sum2 / n - mean * mean) * n / (n - 1));
    EXPECT_NEAR(mean, kAlbedo, std::max(5 * s / std::sqrt(double(n)), 1e-6));
    // An edge pixel's colour over its alpha is the surface's own radiance, from 0.3 of the
    // samples: within 5 s / sqrt(0.3) of it (plus the alpha's own noise, which cancels).
    for (int y = 0; y < kSize; ++y) {
        const float* px = img.at(3, y);
        ASSERT_GT(px[3], 0.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(px[c] / px[3], kAlbedo, std::max(5 * s / std::sqrt(0.3), 1e-5)) << y;
    }
}

TEST(TransparentBackground, DirectAndBasicIntegratorsLeaveMissesBlack) {
    for (IntegratorType type : {IntegratorType::Direct, IntegratorType::Basic}) {
        Options o;
        o.integrator = type;
        o.spp = 16;
        const Image clear = render_scene(edge_scene(), o).resolve();
        o.transparent = false;
        const Image opaque = render_scene(edge_scene(), o).resolve();
        for (int y = 0; y < kSize; ++y) {
            EXPECT_EQ(clear.at(6, y)[0], 0.0f);
            EXPECT_EQ(clear.at(6, y)[3], 0.0f);
            EXPECT_EQ(opaque.at(6, y)[0], 1.0f);
            EXPECT_EQ(clear.at(1, y)[0], opaque.at(1, y)[0]);
            EXPECT_EQ(clear.at(1, y)[3], 1.0f);
        }
    }
}

TEST(TransparentBackground, AdaptiveSamplingFollowsTheAlphasNoise) {
    // A black quad: its colour is 0 on both sides of the edge, so only alpha tells that
    // the edge column is uncertain. It goes on sampling; the empty and the covered columns
    // out of its reach (adaptive sampling's windows spread activity 2 pixels), exact in
    // colour and alpha, stop at the first 16 samples.
    Options o;
    o.spp = 256;
    o.target_error = 0.05;
    const Film film = render_scene(edge_scene(0), o);
    const Image samples = film.resolve_aov(Aov::Samples), img = film.resolve();
    for (int y = 0; y < kSize; ++y) {
        EXPECT_EQ(samples.at(0, y)[0], 16.0f) << y;
        EXPECT_EQ(samples.at(6, y)[0], 16.0f) << y;
        EXPECT_GT(samples.at(3, y)[0], 16.0f) << y;
        EXPECT_EQ(img.at(0, y)[3], 1.0f);
        EXPECT_EQ(img.at(6, y)[3], 0.0f);
    }
}

// A material of constant alpha: BLEND (its alpha is its coverage) or MASK.
int add_alpha(Scene& scene, float alpha, AlphaMode mode) {
    const int m = test::add_lambertian(scene, Spectrum(kAlbedo));
    scene.materials[m].base_color.w = alpha;
    scene.materials[m].alpha_mode = mode;
    return m;
}

TEST(TransparentBackground, BlendedSurfacesCoverByTheirOpacity) {
    // Left half: a 0.4-opaque BLEND quad over nothing. Right half: the same quad over an
    // opaque one. And over everything, a MASK quad cut away entirely (alpha under the
    // cutoff), which every ray passes.
    Scene scene;
    const int blend = add_alpha(scene, 0.4f, AlphaMode::Blend);
    add_quad(scene, -10, 10, -10, 10, 1, blend);
    add_quad(scene, 0, 10, -10, 10, 0, test::add_lambertian(scene, Spectrum(kAlbedo)));
    add_quad(scene, -10, 10, -10, 10, 2, add_alpha(scene, 0.2f, AlphaMode::Mask));
    Options o;
    o.spp = 256;
    const Image img = render_scene(scene, o).resolve();
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize / 2; ++x) {
            // Every sample covers 0.4 and the same (no coin flips in the coverage).
            EXPECT_FLOAT_EQ(img.at(x, y)[3], 0.4f) << x << "," << y;
            EXPECT_EQ(img.at(x, y)[3], img.at(0, 0)[3]) << x << "," << y;
        }
        for (int x = kSize / 2; x < kSize; ++x) EXPECT_EQ(img.at(x, y)[3], 1.0f);
    }
    // Premultiplied: the blended surface's own 0.5 times 0.4 (its share of the shading),
    // nothing of the background. The coin between passing and bouncing makes each pixel
    // noisy: a t-test over the left half's 32 independent pixels, at 5 standard errors.
    const test::Estimate e = test::estimate(kSize * kSize / 2, [&](uint64_t i) {
        const float* px = img.at(int(i % (kSize / 2)), int(i / (kSize / 2)));
        return double(px[0]) / px[3];
    });
    EXPECT_TRUE(test::within(e, kAlbedo, 5)) << e.mean << " +- " << e.std_error;
}

TEST(TransparentBackground, GlassCoversAndShowsTheEnvironmentThroughIt) {
    // A clear, smooth transmissive quad over the whole view: every camera ray hits it
    // (alpha 1, as Cycles' Film > Transparent without "Transparent Glass"), and what it
    // shows is the environment through refraction, the same bits as without the option.
    Scene scene;
    const int glass = test::add_lambertian(scene, Spectrum(1));
    scene.materials[glass].transmission = 1;
    scene.materials[glass].roughness = 0;
    scene.materials[glass].specular = 1;
    add_quad(scene, -10, 10, -10, 10, 0, glass);
    Options o;
    o.spp = 16;
    const Image clear = render_scene(scene, o).resolve();
    o.transparent = false;
    const Image opaque = render_scene(scene, o).resolve();
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            EXPECT_EQ(clear.at(x, y)[3], 1.0f);
            EXPECT_GT(clear.at(x, y)[0], 0.5f);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(clear.at(x, y)[c], opaque.at(x, y)[c]);
        }
}

TEST(TransparentBackground, TheBackOfASingleSidedSurfaceDoesNotCover) {
    // Seen from behind, a single-sided quad is culled for camera rays (camera_culling.h).
    Scene scene;
    const int m = test::add_lambertian(scene, Spectrum(kAlbedo));
    const uint32_t object =
        test::add_quad_object(scene, {-10, -10, 0}, {-10, 10, 0}, {10, 10, 0}, {10, -10, 0}, m);
    test::add_instance(scene, object, Transform());
    Options o;
    o.spp = 4;
    const Image img = render_scene(scene, o).resolve();
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            EXPECT_EQ(img.at(x, y)[3], 0.0f);
            EXPECT_EQ(img.at(x, y)[0], 0.0f);
        }
}

// Two objects side by side (nodes 5 and 9; material 1 and the default material), the
// top two rows empty, and in front of all a MASK quad (node 2) cut away entirely.
Scene id_scene() {
    Scene scene;
    test::add_lambertian(scene, Spectrum(0.9f));  // material 0: unused
    const int m1 = test::add_lambertian(scene, Spectrum(kAlbedo));
    add_quad(scene, -4, kEdge - 4, -4, 2, 0, m1, 5);
    add_quad(scene, kEdge - 4, 4, -4, 2, 0, -1, 9);
    add_quad(scene, -10, 10, -10, 10, 1, add_alpha(scene, 0.1f, AlphaMode::Mask), 2);
    return scene;
}

TEST(TransparentBackground, IdLayersHoldTheFirstVisibleSurfacesNodeAndMaterial) {
    Options o;
    o.spp = 64;
    o.aovs = {Aov::ObjectId, Aov::MaterialId};
    const Film film = render_scene(id_scene(), o);
    const Image object = film.resolve_aov(Aov::ObjectId),
                material = film.resolve_aov(Aov::MaterialId);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            // Rows 0 and 1 (world y 4 to 2) miss; column 3's centre (3.5) lies right of
            // the edge (3.3), and of 64 samples one lies nearer the centre than 0.2.
            const bool miss = y < 2, left = x < 3;
            EXPECT_EQ(object.at(x, y)[0], miss ? -1.0f : left ? 5.0f : 9.0f) << x << "," << y;
            EXPECT_EQ(material.at(x, y)[0], miss ? -1.0f : left ? 1.0f : -2.0f) << x << "," << y;
        }
}

TEST(TransparentBackground, IdsCryptomatteAndAlphaAreBitwiseIdenticalForAnyThreadsAndPasses) {
    Options o;
    o.spp = 16;
    o.aovs = {Aov::ObjectId, Aov::MaterialId, Aov::CryptoObject, Aov::CryptoMaterial};
    o.threads = 1;
    const Film a = render_scene(id_scene(), o);
    o.threads = 2;
    const Film b = render_scene(id_scene(), o);
    o.two_passes = true;
    const Film c = render_scene(id_scene(), o);
    for (const Film* f : {&b, &c}) {
        EXPECT_EQ(a.resolve().pixels, f->resolve().pixels);
        EXPECT_EQ(a.resolve_aov(Aov::ObjectId).pixels, f->resolve_aov(Aov::ObjectId).pixels);
        EXPECT_EQ(a.resolve_aov(Aov::MaterialId).pixels, f->resolve_aov(Aov::MaterialId).pixels);
        for (Aov crypto : {Aov::CryptoObject, Aov::CryptoMaterial})
            EXPECT_EQ(a.resolve_aov(crypto).pixels, f->resolve_aov(crypto).pixels);
    }
}

}  // namespace
}  // namespace penumbra
