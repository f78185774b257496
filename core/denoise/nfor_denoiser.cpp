#include "core/denoise/nfor_denoiser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/denoise/feature_regression.h"
#include "core/denoise/firefly_guard.h"
#include "core/denoise/nl_means.h"
#include "core/film/image_error.h"

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

// Each channel averaged over the (2r + 1)^2 pixels around each pixel (fewer at the
// border), separably.
Planes box_filter(const Planes& p, int r) {
    Planes rows = p, out = p;
    for (int c = 0; c < p.channels; ++c) {
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                double sum = 0;
                const int x0 = std::max(0, x - r), x1 = std::min(p.width - 1, x + r);
                for (int xq = x0; xq <= x1; ++xq) sum += p.at(c, xq, y);
                rows.at(c, x, y) = float(sum / (x1 - x0 + 1));
            }
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                double sum = 0;
                const int y0 = std::max(0, y - r), y1 = std::min(p.height - 1, y + r);
                for (int yq = y0; yq <= y1; ++yq) sum += rows.at(c, x, yq);
                out.at(c, x, y) = float(sum / (y1 - y0 + 1));
            }
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

// Mean over pixels and channels of mse / (reference^2 + epsilon): relMSE as
// core/film/image_error.h measures it, with an estimate standing in for the reference; and the
// standard error of that mean, from the spread of the pixels' terms.
struct RelMseEstimate {
    double mean = 0, standard_error = 0;
};
RelMseEstimate relative_mse_estimate(const Planes& mse, const Planes& reference) {
    const size_t n = mse.pixels();
    if (n == 0) return {};
    double sum = 0, sum2 = 0;
    for (size_t j = 0; j < n; ++j) {
        double t = 0;  // the pixel's term, averaged over its channels
        for (int c = 0; c < mse.channels; ++c) {
            const double r = reference.plane(c)[j];
            t += double(mse.plane(c)[j]) / (r * r + kRelMseEpsilon);
        }
        t /= mse.channels;
        sum += t;
        sum2 += t * t;
    }
    const double mean = sum / double(n);
    const double var = n > 1 ? std::max(0.0, (sum2 - sum * mean) / double(n - 1)) : 0;
    return {mean, std::sqrt(var / double(n))};
}

struct Filtered {
    Planes a, b;  // each half's result
    // The wide bandwidth's results in both windows, both halves, averaged: the
    // estimate's stand-in for the reference (denoise_nfor).
    Planes smooth;
};

// The radius of the box that averages the candidates' cross-validated errors before the
// choice. Chosen per pixel from noisy errors, the least error is biased low (the winner's
// curse), and the estimate of the chosen result with it: with non-local means on the
// colour (NFOR's choice) the estimate was 0.25-0.56 of the measured error on three
// bundled scenes at 96 x 96 pixels and 32 spp, with this box 0.43-0.66; at 160 pixels
// and 16 and 64 spp, 0.51-1.22 on four.
constexpr int kErrorRadius = 4;

// Per pixel, the candidate (fa[i], fb[i]) with the lowest cross-validated error averaged
// over a box, the choice smoothed by non-local means on the colour. The errors are
// relative, divided by denominator^2 + epsilon as relMSE divides, so that a dim region's
// choice counts as much as the metric counts it rather than being outvoted by its bright
// neighbours (32 spp, with both windows: glossy's relMSE 4% lower, dof's 3%,
// soft-shadows' 1%).
void choose(const Planes& a, const Planes& b, const std::vector<Planes>& fa,
            const std::vector<Planes>& fb, const Planes& denominator, const NlmGuide& by_color,
            int radius, Filtered& out) {
    const int n = int(fa.size());
    Planes errors(a.width, a.height, n);
    for (int i = 0; i < n; ++i) {
        const Planes mse = cross_validated_mse(a, b, fa[i], fb[i]);
        for (int c = 0; c < 3; ++c)
            for (size_t j = 0; j < errors.pixels(); ++j) {
                const float r = denominator.plane(c)[j];
                errors.plane(i)[j] += mse.plane(c)[j] / (r * r + float(kRelMseEpsilon));
            }
    }
    errors = box_filter(errors, kErrorRadius);
    Planes choice(a.width, a.height, n);
    for (size_t j = 0; j < choice.pixels(); ++j) {
        int best = 0;
        for (int i = 1; i < n; ++i)
            if (errors.plane(i)[j] < errors.plane(best)[j]) best = i;
        choice.plane(best)[j] = 1;
    }
    choice = nl_means(choice, by_color, radius);
    out.a = Planes(a.width, a.height, 3);
    out.b = Planes(a.width, a.height, 3);
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            for (size_t j = 0; j < choice.pixels(); ++j) {
                const float s = choice.plane(i)[j];
                out.a.plane(c)[j] += s * fa[i].plane(c)[j];
                out.b.plane(c)[j] += s * fb[i].plane(c)[j];
            }
}

// Both halves fitted at both bandwidths in both windows; per pixel the candidate with the
// lowest cross-validated error. The raw halves are a further candidate, whose error is
// their variance: where the render has nothing left to gain (converged, or detail no
// guide explains) the filter steps aside (soft-shadows.gltf at 64 spp: the filtered
// image's relMSE was 1.2x the raw one's without it, 0.5x with it).
Filtered filter_halves(const Planes& a, const Planes& b, const Planes& var, const Planes& guides_a,
                       const Planes& guides_b, const NforParams& p) {
    const Planes var_half = scaled(var, 2);
    const Planes color = average(a, b);
    const NlmGuide by_color{&color, &var, 1, 1.0f};
    const std::vector<float> ks{p.k_small, p.k_large};
    std::vector<Planes> fa, fb;
    for (int radius : {p.window_radius, p.small_window_radius}) {
        const RegressionParams rp{radius, p.patch_radius, p.center_stride};
        for (Planes& f : collaborative_regression(a, var_half, guides_a, rp, ks))
            fa.push_back(std::move(f));
        for (Planes& f : collaborative_regression(b, var_half, guides_b, rp, ks))
            fb.push_back(std::move(f));
    }
    Filtered out;
    // Both windows' results at the wide bandwidth, averaged.
    out.smooth = average(average(fa[1], fb[1]), average(fa[3], fb[3]));
    fa.push_back(a);
    fb.push_back(b);
    choose(a, b, fa, fb, out.smooth, by_color, p.window_radius, out);
    return out;
}

// The squared bias the firefly guard adds, per pixel and channel: what it took from each
// half (guarded from raw), averaged over the window around each pixel, so that a
// firefly's energy counts at the rate fireflies occur rather than where one happened to
// land. The cross-validated error compares guarded halves and cannot see it
// (cornell-box.gltf at 16 spp: an estimate of 0.45 the measured error without, 0.86
// with). The square is the product of the two halves' averages, which are independent:
// its expectation is the squared bias alone, where the square of one average adds that
// average's variance, which a few rare fireflies make far larger than the bias
// (TransmissionRoughnessTest at 32 spp: an estimate of 2.3 the measured error with the
// square, 0.99 with the product). A pixel's term may be negative; their mean is not biased.
Planes guard_bias_squared(const Planes& raw_a, const Planes& raw_b, const Planes& a,
                          const Planes& b, int radius) {
    Planes removed_a(a.width, a.height, 3), removed_b(a.width, a.height, 3);
    for (size_t i = 0; i < removed_a.data.size(); ++i) {
        removed_a.data[i] = raw_a.data[i] - a.data[i];
        removed_b.data[i] = raw_b.data[i] - b.data[i];
    }
    Planes bias2 = box_filter(removed_a, radius);
    const Planes bias_b = box_filter(removed_b, radius);
    for (size_t i = 0; i < bias2.data.size(); ++i) bias2.data[i] *= bias_b.data[i];
    return bias2;
}

}  // namespace

DenoiseResult denoise_nfor(const DenoiseInput& in, const NforParams& p) {
    const Planes raw_a = to_planes(in.color_a, 0, 3), raw_b = to_planes(in.color_b, 0, 3);
    Planes a = raw_a, b = raw_b, var = to_planes(in.color_variance, 0, 3);
    DenoiseResult result;
    result.fireflies = guard_fireflies(a, b, var);
    double total = 0, kept = 0;
    for (size_t i = 0; i < a.data.size(); ++i) {
        total += double(raw_a.data[i]) + raw_b.data[i];
        kept += double(a.data[i]) + b.data[i];
    }
    result.firefly_energy = total > 0 ? (total - kept) / total : 0;
    // The colour's variance, as the weights read it, averaged over 3 x 3 pixels: a
    // pixel's own sample variance is carried by its outliers, so a half's filter, which
    // weighs the pixel by it, depended on the other half's samples, and the
    // cross-validated error came out low (glossy.gltf: 0.7-0.8 of the measured error;
    // 1.0 with the average, whose relMSE is also 10% lower).
    var = box_filter(var, 1);

    // Each half's guides prefiltered from its own samples. NFOR filters each with
    // distances from the other half; but a sample's guides and colour are correlated
    // (the same camera ray), so a half's result then depended on the other half's
    // colour, and the cross-validated error missed part of it (dof.gltf at 16 spp: an
    // estimate of -0.08 the measured error; 0.8 with own guides, at 20% more error).
    const Planes ga = to_planes(in.guide_a), gb = to_planes(in.guide_b);
    const Planes guide_var_half = scaled(to_planes(in.guide_variance), 2);
    const int F = p.feature_patch_radius, Rf = p.feature_window_radius;
    const Planes guides_a = filter_guides(ga, ga, guide_var_half, F, Rf, 0.5f);
    const Planes guides_b = filter_guides(gb, gb, guide_var_half, F, Rf, 0.5f);

    const Filtered out = filter_halves(a, b, var, guides_a, guides_b, p);
    Planes color = average(out.a, out.b);
    for (float& v : color.data) v = std::max(v, 0.0f);

    Planes mse = cross_validated_mse(a, b, out.a, out.b);
    const Planes bias2 = guard_bias_squared(raw_a, raw_b, a, b, p.window_radius);
    for (size_t i = 0; i < mse.data.size(); ++i) mse.data[i] += bias2.data[i];
    // A smoothed candidate stands in for the reference in relMSE's denominator: the
    // result keeps what is left of outliers where the raw halves or the narrow bandwidth
    // were chosen, and dividing by their square hid their error (glossy.gltf at 16 spp:
    // an estimate of 0.52 the measured error; 0.82 with the large window's wide
    // bandwidth). The large window alone spreads small bright details into their dark
    // surroundings and leaves the details too dim (32 spp, estimate / measured: GolfBall
    // 1.83, glossy 1.52); the small window alone is noisy where the image is (the
    // synthetic test at a half's noise of 100%: 2.06); their average gives GolfBall 1.22,
    // glossy 1.09, the synthetic 1.37.
    const RelMseEstimate e = relative_mse_estimate(mse, out.smooth);
    // Each pixel's term carries the product of its halves' noise, so the mean has a
    // standard error of about the raw relMSE over sqrt(pixels): an image denoised far
    // below that (a large, nearly converged render: the default Cornell box at 640 x 640
    // and 64 spp gave -1.7e-4) cannot be resolved, and the standard error stands in as
    // the estimate, a bound rather than a measurement.
    result.relmse_estimate = std::max(e.mean, e.standard_error);
    result.relmse_estimate_stderr = e.standard_error;
    result.color = to_image(color);
    return result;
}

std::string describe(const NforParams& p) {
    auto square = [](int r) { return std::to_string(2 * r + 1) + "x" + std::to_string(2 * r + 1); };
    char ks[64];
    std::snprintf(ks, sizeof ks, "%g/%g", p.k_small, p.k_large);
    char guard[32];
    std::snprintf(guard, sizeof guard, "%g", kFireflyRatio);
    return "NFOR after Bitterli et al. 2016: each half of the samples fitted by first-order "
           "regression to its own guides (albedo, normal, depth, visibility), window " +
           square(p.window_radius) + " and " + square(p.small_window_radius) + ", fits on every " +
           std::to_string(p.center_stride) + "x" + std::to_string(p.center_stride) +
           " pixels, non-local means weights patch " + square(p.patch_radius) +
           "; per pixel the least cross-validated relative error of bandwidths k " + ks +
           " in either window and the raw halves; guides prefiltered in " +
           square(p.feature_window_radius) + ", patch " + square(p.feature_patch_radius) +
           "; firefly guard at " + guard + "x the surroundings";
}

}  // namespace penumbra
