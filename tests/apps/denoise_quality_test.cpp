// The denoiser on bundled scenes against references: a converging render changes by less
// than its noise and loses at most 0.1% of its energy to the firefly guard; at 32 spp the
// denoised image beats the raw one by the margin each scene states, and the header's
// estimate of its relMSE lies within a factor of 2 of the measured one.
//
// The reference is the mean of two renders at 1024 spp with other seeds; its own relMSE
// (a quarter of the two's relMSE against each other: each has twice the variance of their
// mean, and their difference twice that) is subtracted from every measured value. Every
// render is deterministic, so these figures are the same on every machine.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/film/image_error.h"
#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;
constexpr int kWidth = 128;

std::string out_path(const std::string& name) {
    return test::binary_path("denoise_quality_" + name + ".exr");
}

// Renders the bundled scene to `name`, returning its pixels.
test::Pixels render(const std::string& scene, const std::string& name, const Args& more) {
    Args args = {"render",      test::source_path("scenes/" + scene + ".gltf"),
                 "--width",     std::to_string(kWidth),
                 "-o",          out_path(name),
                 "--overwrite", "--no-preview",
                 "-q"};
    args.insert(args.end(), more.begin(), more.end());
    const test::CliResult r = test::run_penumbra(args);
    EXPECT_EQ(r.status, 0) << r.output;
    return test::read_pixels(out_path(name));
}

// The three channels `prefix`R, G, B of an EXR as an image.
Image layer(const test::Pixels& p, const std::string& prefix) {
    Image img(p.width, p.height, 3);
    const size_t nc = p.channels.size();
    for (int c = 0; c < 3; ++c) {
        const std::string name = prefix + "RGB"[c];
        size_t k = 0;
        while (k < nc && p.channels[k] != name) ++k;
        EXPECT_LT(k, nc) << name;
        if (k == nc) return img;
        for (size_t i = 0; i < size_t(p.width) * p.height; ++i)
            img.pixels[i * 3 + c] = p.data[i * nc + k];
    }
    return img;
}

// A numeric header attribute penumbra writes as a string; NaN when absent.
double header_value(const std::string& path, const std::string& key) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
    const std::string v = in ? in->spec().get_string_attribute(key) : "";
    EXPECT_FALSE(v.empty()) << path << ": no " << key;
    return v.empty() ? std::nan("") : std::stod(v);
}

struct Case {
    const char* scene;
    // The largest denoised / raw relMSE ratio accepted at 32 spp (measured: the comment).
    double max_ratio;
    // Whether the estimate is checked: the Cornell box's caustics through the mirror
    // sphere leave its 2048-spp reference too noisy to measure the denoised error by
    // (docs/validation.md measures it against 8192 spp).
    bool estimate;
};

TEST(DenoiseQualityLong, OnBundledScenes) {
    const Case cases[] = {
        {"cornell-box", 0.1, false},   // measured 0.031
        {"glossy", 0.35, true},        // 0.22, estimate 0.98 of the measured error
        {"dof", 0.2, true},            // 0.12, estimate 0.68
        {"soft-shadows", 0.25, true},  // 0.13, estimate 0.80
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.scene);
        const std::string name = c.scene;
        // Two converging renders, denoised: their raw images make the reference.
        const Args converging = {"--spp", "1024", "--denoise"};
        Args args1 = converging, args2 = converging;
        args1.insert(args1.end(), {"--seed", "11"});
        args2.insert(args2.end(), {"--seed", "12"});
        const test::Pixels p1 = render(name, name + "_ref1", args1);
        const test::Pixels p2 = render(name, name + "_ref2", args2);
        const Image r1 = layer(p1, "Noisy."), r2 = layer(p2, "Noisy.");
        Image ref = r1;
        for (size_t i = 0; i < ref.pixels.size(); ++i)
            ref.pixels[i] = 0.5f * (r1.pixels[i] + r2.pixels[i]);
        const double render_noise = relative_mse(r1, r2) / 2, ref_noise = render_noise / 2;

        // No harm where there is nothing to gain: denoising a converging render changes it
        // by less than its own noise, and the firefly guard holds back at most 0.1% of its
        // energy (the bias it adds to the converged mean; measured: nothing on any of the
        // four, whose caustics are not lone samples at 1024 spp).
        EXPECT_LT(relative_mse(layer(p1, ""), r1), render_noise);
        EXPECT_LE(header_value(out_path(name + "_ref1"), "penumbra:denoise_firefly_energy"), 1e-3);

        // At 32 spp: better than raw by the stated margin, and an honest estimate.
        const test::Pixels x = render(name, name + "_32", {"--spp", "32", "--denoise"});
        const double denoised = relative_mse(layer(x, ""), ref) - ref_noise;
        const double raw = relative_mse(layer(x, "Noisy."), ref) - ref_noise;
        EXPECT_LT(denoised, c.max_ratio * raw) << "denoised " << denoised << ", raw " << raw;
        if (c.estimate) {
            const double estimate =
                header_value(out_path(name + "_32"), "penumbra:denoise_relmse_estimate");
            EXPECT_GT(estimate, denoised / 2) << "measured " << denoised;
            EXPECT_LT(estimate, denoised * 2) << "measured " << denoised;
        }
    }
}

}  // namespace
}  // namespace penumbra
