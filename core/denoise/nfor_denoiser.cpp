#include "core/denoise/nfor_denoiser.h"

#include <algorithm>
#include <cstdio>

#include "core/convergence.h"
#include "core/denoise/feature_regression.h"
#include "core/denoise/firefly_guard.h"
#include "core/denoise/nl_means.h"

namespace penumbra {

namespace {

Planes scaled(const Planes& p, float s) {
    Planes out = p;
    for (float& v : out.data) v *= s;
    return out;
}

Planes average(const Planes& a, const Planes& b) {
    Planes out = a;
    for (size_t i = 0; i < out.data.size(); ++i) out.data[i] = 0.5f * (a.data[i] + b.data[i]);
    return out;
}

// The guides' groups: albedo, normal, depth and visibility are each prefiltered with their own
// distances, so that one's edges do not blur another's.
struct GuideGroup {
    int first, count;
};
constexpr GuideGroup kGuideGroups[] = {
    {kGuideAlbedo, 3}, {kGuideNormal, 3}, {kGuideDepth, 1}, {kGuideVisibility, 1}};

// Each guide group of `image` filtered by non-local means with distances from `guide`.
Planes filter_guides(const Planes& image, const Planes& guide, const Planes& variance,
                     int patch_radius, int radius, float k) {
    Planes out(image.width, image.height, image.channels);
    for (const GuideGroup& g : kGuideGroups) {
        const Planes gi = channels(guide, g.first, g.count);
        const Planes vi = channels(variance, g.first, g.count);
        const Planes filtered =
            nl_means(channels(image, g.first, g.count), {&gi, &vi, patch_radius, k}, radius);
        std::copy(filtered.data.begin(), filtered.data.end(), out.plane(g.first));
    }
    return out;
}

// Per pixel and channel, the MSE of (fa + fb) / 2 against the true mean, where fa was
// filtered from half a alone and fb from b: b is an unbiased reference for fa that is
// independent of it (and a for fb), so (b - fa)^2 overestimates fa's squared error by
// b's variance, and (fb - fa)^2 / 4 is the part of their average's error that averaging
// removes (NFOR, section 5.3). b's variance is taken as realised, (a - b)^2 / 2, rather
// than as estimated from the samples: its chi-square fluctuation then cancels against
// the one in (b - fa)^2, which halves the estimate's own variance (measured over noise
// seeds on the synthetic test image: the spread of estimate / truth fell from 0.37-1.16
// to 0.78-1.24).
Planes cross_validated_mse(const Planes& a, const Planes& b, const Planes& fa, const Planes& fb) {
    Planes mse = a;
    for (size_t i = 0; i < mse.data.size(); ++i) {
        const float ea = b.data[i] - fa.data[i], eb = a.data[i] - fb.data[i];
        const float ab = a.data[i] - b.data[i], d = fb.data[i] - fa.data[i];
        mse.data[i] = 0.5f * (ea * ea + eb * eb - ab * ab) - d * d / 4;
    }
    return mse;
}

// Mean over pixels and channels of mse / (value^2 + epsilon): relMSE as
// core/convergence.h measures it, with the result standing in for the reference.
double relative_mse_estimate(const Planes& mse, const Planes& value) {
    double sum = 0;
    for (size_t i = 0; i < mse.data.size(); ++i)
        sum += double(mse.data[i]) / (double(value.data[i]) * value.data[i] + kRelMseEpsilon);
    return mse.data.empty() ? 0 : sum / double(mse.data.size());
}

struct Halves {
    Planes a, b;
};

// First pass: both halves fitted at both bandwidths; per pixel the bandwidth with the
// lower cross-validated error, the choice smoothed by non-local means on the colour.
Halves first_pass(const Planes& a, const Planes& b, const Planes& var, const Planes& guides_a,
                  const Planes& guides_b, const NforParams& p) {
    const Planes var_half = scaled(var, 2);
    const Planes color = average(a, b);
    const NlmGuide by_color{&color, &var, 1, 1.0f};
    Halves fit[2];
    // The two bandwidths' errors summed over the channels, as one image of two channels,
    // smoothed together (one set of weights).
    Planes errors(a.width, a.height, 2);
    const RegressionParams rp{p.window_radius, p.patch_radius, p.center_stride};
    // Cross: each half's colour fitted to the other half's guides, so that the guides'
    // noise is independent of the colour's.
    const std::vector<Planes> fa =
        collaborative_regression(a, var_half, guides_b, rp, {p.k_small, p.k_large});
    const std::vector<Planes> fb =
        collaborative_regression(b, var_half, guides_a, rp, {p.k_small, p.k_large});
    for (int i = 0; i < 2; ++i) {
        fit[i] = {fa[i], fb[i]};
        const Planes mse = cross_validated_mse(a, b, fit[i].a, fit[i].b);
        for (int c = 0; c < 3; ++c)
            for (size_t j = 0; j < errors.pixels(); ++j) errors.plane(i)[j] += mse.plane(c)[j];
    }
    errors = nl_means(errors, by_color, p.window_radius);
    Planes choice(a.width, a.height, 1);
    for (size_t j = 0; j < choice.pixels(); ++j)
        choice.data[j] = errors.plane(0)[j] <= errors.plane(1)[j] ? 1.0f : 0.0f;
    choice = nl_means(choice, by_color, p.window_radius);
    Halves out{a, b};
    for (int c = 0; c < 3; ++c)
        for (size_t j = 0; j < choice.pixels(); ++j) {
            const float s = choice.data[j];
            out.a.plane(c)[j] = s * fit[0].a.plane(c)[j] + (1 - s) * fit[1].a.plane(c)[j];
            out.b.plane(c)[j] = s * fit[0].b.plane(c)[j] + (1 - s) * fit[1].b.plane(c)[j];
        }
    return out;
}

}  // namespace

DenoiseResult denoise_nfor(const DenoiseInput& in, const NforParams& p) {
    Planes a = to_planes(in.color_a, 0, 3), b = to_planes(in.color_b, 0, 3);
    Planes var = to_planes(in.color_variance, 0, 3);
    DenoiseResult result;
    result.fireflies = guard_fireflies(a, b, var);

    // The guides, each half filtered with distances from the other (cross-filtering).
    const Planes ga = to_planes(in.guide_a), gb = to_planes(in.guide_b);
    const Planes guide_var_half = scaled(to_planes(in.guide_variance), 2);
    const int F = 3, Rf = p.feature_window_radius;
    const Planes guides_a = filter_guides(ga, gb, guide_var_half, F, Rf, 0.5f);
    const Planes guides_b = filter_guides(gb, ga, guide_var_half, F, Rf, 0.5f);

    Halves out = first_pass(a, b, var, guides_a, guides_b, p);

    Planes color = average(out.a, out.b);
    for (float& v : color.data) v = std::max(v, 0.0f);
    const Planes mse = cross_validated_mse(a, b, out.a, out.b);
    result.relmse_estimate = relative_mse_estimate(mse, color);
    result.color = to_image(color);
    return result;
}

std::string describe(const NforParams& p) {
    char text[320];
    std::snprintf(
        text, sizeof text,
        "NFOR (Bitterli et al. 2016): first-order regression on albedo, normal, depth "
        "and visibility, window %dx%d, fits on every %dx%d pixels, patch %dx%d, bandwidths k "
        "%g/%g chosen per pixel by cross-validation of two sample halves, guide "
        "window %dx%d; firefly guard at %gx the surroundings",
        2 * p.window_radius + 1, 2 * p.window_radius + 1, p.center_stride, p.center_stride,
        2 * p.patch_radius + 1, 2 * p.patch_radius + 1, p.k_small, p.k_large,
        2 * p.feature_window_radius + 1, 2 * p.feature_window_radius + 1, kFireflyRatio);
    return text;
}

}  // namespace penumbra
