// The render loop with AOVs: the beauty is bit for bit the one rendered without them
// (AOVs draw no numbers from the sampler), and every AOV is bitwise identical for any
// thread count and any split into passes. Denoising splits the samples as the error
// AOV does, and its buffers are bitwise identical in the same way.
#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "integrators/render.h"
#include "support/scene_builder.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

struct Result {
    Image beauty;
    std::vector<Image> aovs;
    DenoiseInput denoise;  // with Aov::Denoise
};

Result render_sphere(AovSet aovs, int threads, bool in_two_passes = false) {
    const Scene scene = test::make_lit_sphere_on_floor();
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({0, 0.5f, 4}, {0, 0, 0}, {0, 1, 0}), 0.8f, 24,
                                   18);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = 6;
    opt.seed = 3;
    opt.progress = false;
    opt.threads = threads;
    opt.aovs = aovs;
    Film film(24, 18, aovs);
    if (in_two_passes) {
        render_samples(ctx, camera, *integrator, opt, film, 0, 2);
        render_samples(ctx, camera, *integrator, opt, film, 2, 6);
    } else {
        film = render(ctx, camera, *integrator, opt);
    }
    Result r{film.resolve(), {}};
    for (Aov a : {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Variance, Aov::Samples,
                  Aov::ObjectId, Aov::MaterialId})
        r.aovs.push_back(film.resolve_aov(a));
    if (aovs.has(Aov::Denoise)) r.denoise = film.denoise_input();
    return r;
}

TEST(RenderAov, BeautyIsUnchangedByAovs) {
    const Result plain = render_sphere({}, 2), with = render_sphere(parse_aovs("all"), 2);
    EXPECT_EQ(plain.beauty.pixels, with.beauty.pixels);
    // And the AOVs are really there: the sphere's albedo at the centre.
    EXPECT_NEAR(with.aovs[0].at(12, 9)[0], 0.6f, 1e-6f);
}

TEST(RenderAov, AovsAreBitwiseIdenticalForAnyThreadCountAndPasses) {
    const AovSet all = parse_aovs("all");
    const Result a = render_sphere(all, 1), b = render_sphere(all, 2),
                 c = render_sphere(all, 2, true);
    EXPECT_EQ(a.beauty.pixels, b.beauty.pixels);
    EXPECT_EQ(a.beauty.pixels, c.beauty.pixels);
    for (size_t i = 0; i < a.aovs.size(); ++i) {
        EXPECT_EQ(a.aovs[i].pixels, b.aovs[i].pixels) << i;
        EXPECT_EQ(a.aovs[i].pixels, c.aovs[i].pixels) << i;
    }
}

std::vector<const Image*> images(const DenoiseInput& in) {
    return {&in.color_a, &in.color_b, &in.color_variance,
            &in.guide_a, &in.guide_b, &in.guide_variance};
}

TEST(RenderAov, DenoisingSplitsTheSamplesAsTheErrorAovDoes) {
    const AovSet error = {Aov::Error}, denoise = {Aov::Denoise};
    const Result e = render_sphere(error, 2), d = render_sphere(denoise, 2);
    EXPECT_EQ(e.beauty.pixels, d.beauty.pixels);
    EXPECT_NE(render_sphere({}, 2).beauty.pixels, d.beauty.pixels);
    // The guides are there: the sphere's albedo and the camera-facing normal at its centre.
    for (const Image* g : {&d.denoise.guide_a, &d.denoise.guide_b}) {
        EXPECT_NEAR(g->at(12, 9)[kGuideAlbedo], 0.6f, 1e-6f);
        EXPECT_GT(g->at(12, 9)[kGuideNormal + 2], 0.9f);
        EXPECT_NEAR(g->at(12, 9)[kGuideDepth], 3.0f, 0.1f);
    }
}

TEST(RenderAov, DenoiseInputIsBitwiseIdenticalForAnyThreadCountAndPasses) {
    const AovSet aovs = {Aov::Denoise, Aov::Albedo};
    const Result a = render_sphere(aovs, 1), b = render_sphere(aovs, 2),
                 c = render_sphere(aovs, 2, true);
    EXPECT_EQ(a.beauty.pixels, b.beauty.pixels);
    EXPECT_EQ(a.beauty.pixels, c.beauty.pixels);
    const auto ia = images(a.denoise), ib = images(b.denoise), ic = images(c.denoise);
    for (size_t i = 0; i < ia.size(); ++i) {
        EXPECT_EQ(ia[i]->pixels, ib[i]->pixels) << i;
        EXPECT_EQ(ia[i]->pixels, ic[i]->pixels) << i;
    }
}

}  // namespace
}  // namespace penumbra
