// The render loop's farm features: a render resumed from a film holding samples [0,k)
// (a checkpoint) ends bit for bit as an uninterrupted one, a row band renders exactly its
// rows of the whole image (beauty and AOVs), and checkpoints are offered between passes.
#include <gtest/gtest.h>

#include <cstring>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "integrators/render.h"
#include "job/checkpoint.h"
#include "support/gltf_builder.h"
#include "support/scene_builder.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

const AovSet kAovs = parse_aovs("albedo,normal,depth,position,variance,samples");
constexpr int kW = 24, kH = 18;

struct Fixture {
    Scene scene = test::make_lit_sphere_on_floor();
    EmbreeAccel accel{scene};
    LightSet lights{scene, nullptr};
    RenderContext ctx{scene, accel, lights};
    PerspectiveCamera camera{Transform::look_at({0, 0.5f, 4}, {0, 0, 0}, {0, 1, 0}), 0.8f, kW, kH};
    std::unique_ptr<Integrator> integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    Fixture() {
        opt.spp = 7;
        opt.seed = 11;
        opt.progress = false;
        opt.aovs = kAovs;
    }
};

std::vector<Image> images(const Film& film) {
    std::vector<Image> out = {film.resolve()};
    for (Aov a : {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Variance, Aov::Samples})
        out.push_back(film.resolve_aov(a));
    return out;
}

// Rows [y0, y1) of every image equal bit for bit.
bool same_rows(const std::vector<Image>& a, const std::vector<Image>& b, int y0, int y1) {
    for (size_t i = 0; i < a.size(); ++i) {
        const size_t row = size_t(a[i].width) * a[i].channels;
        if (std::memcmp(&a[i].pixels[row * y0], &b[i].pixels[row * y0],
                        row * (y1 - y0) * sizeof(float)) != 0)
            return false;
    }
    return true;
}

TEST(RenderResume, ResumedFromACheckpointEqualsAnUninterruptedRender) {
    Fixture f;
    const std::vector<Image> whole = images(render(f.ctx, f.camera, *f.integrator, f.opt));
    for (uint32_t k : {1u, 3u, 6u}) {
        // Samples [0,k) through a checkpoint file, then render() continues to spp.
        Film first(kW, kH, kAovs);
        ASSERT_TRUE(render_samples(f.ctx, f.camera, *f.integrator, f.opt, first, 0, k));
        const test::ScratchDir dir;
        write_checkpoint(dir.file("c.ckpt"), first, {"fp", k, 0, 0});
        Film loaded(kW, kH, kAovs);
        ASSERT_TRUE(read_checkpoint(dir.file("c.ckpt"), "fp", loaded));
        RenderOptions opt = f.opt;
        opt.resume = &loaded;
        opt.resume_spp = k;
        RenderStats stats;
        const Film resumed = render(f.ctx, f.camera, *f.integrator, opt, &stats);
        EXPECT_EQ(stats.spp, 7u);
        EXPECT_TRUE(same_rows(whole, images(resumed), 0, kH)) << "resumed at " << k;
    }
    // The test can fail: a resume that repeats sample indices (from 0) differs.
    Film first(kW, kH, kAovs);
    ASSERT_TRUE(render_samples(f.ctx, f.camera, *f.integrator, f.opt, first, 0, 3));
    RenderOptions wrong = f.opt;
    wrong.resume = &first;
    wrong.resume_spp = 0;
    EXPECT_FALSE(same_rows(whole, images(render(f.ctx, f.camera, *f.integrator, wrong)), 0, kH));
}

TEST(RenderResume, BandsRenderExactlyTheirRowsOfTheWholeImage) {
    Fixture f;
    f.opt.tile_size = 5;  // bands that do not start on a tile boundary
    const std::vector<Image> whole = images(render(f.ctx, f.camera, *f.integrator, f.opt));
    const int cuts[] = {0, 4, 5, 11, kH};
    for (int b = 0; b + 1 < int(std::size(cuts)); ++b) {
        RenderOptions opt = f.opt;
        opt.row_begin = cuts[b];
        opt.row_end = cuts[b + 1];
        opt.threads = 1 + b % 2;
        const Film band = render(f.ctx, f.camera, *f.integrator, opt);
        const std::vector<Image> img = images(band);
        EXPECT_TRUE(same_rows(whole, img, cuts[b], cuts[b + 1])) << "band " << b;
        // Rows outside the band hold no samples at all.
        const Image samples = band.resolve_aov(Aov::Samples);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                ASSERT_EQ(samples.at(x, y)[0], y >= cuts[b] && y < cuts[b + 1] ? 7.0f : 0.0f)
                    << x << "," << y;
    }
}

TEST(RenderResume, CheckpointsAreOfferedBetweenPassesOnly) {
    Fixture f;
    f.opt.spp = 16;
    f.opt.checkpoint_interval = 0;  // at every pass boundary
    std::vector<uint32_t> offered;
    f.opt.checkpoint = [&](const Film& film, uint32_t spp) {
        offered.push_back(spp);
        EXPECT_EQ(film.resolve_aov(Aov::Samples).at(0, 0)[0], float(spp));
    };
    RenderStats stats;
    render(f.ctx, f.camera, *f.integrator, f.opt, &stats);
    // Passes of 1, 1, 2, 4, 8 samples: checkpoints after each but the last (the final
    // image follows at once).
    ASSERT_EQ(stats.spp, 16u);
    EXPECT_EQ(offered, (std::vector<uint32_t>{1, 2, 4, 8}));
    f.opt.checkpoint_interval = 3600;
    offered.clear();
    render(f.ctx, f.camera, *f.integrator, f.opt);
    EXPECT_TRUE(offered.empty());
}

}  // namespace
}  // namespace penumbra
