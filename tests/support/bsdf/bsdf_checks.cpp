#include "support/bsdf/bsdf_checks.h"

#include <cmath>

namespace penumbra::test {

Chi2Result bsdf_chi2(const Bsdf& bsdf, Vec3 wo, const BsdfChi2Options& o, Transport mode) {
    SphereChi2Options so;
    so.hemisphere = !o.full_sphere;
    so.cos_bins = o.cos_bins;
    so.samples = o.samples;
    so.seed = o.seed;
    so.significance = o.significance;
    return chi2_sphere(
        [&](Rng& rng) -> std::optional<Vec3> {
            const float u_lobe = rng.next_float();
            const Vec2 u(rng.next_float(), rng.next_float());
            const std::optional<BsdfSample> s = bsdf.sample(wo, u_lobe, u, mode);
            if (!s || (s->is_specular() && !o.keep_specular)) return std::nullopt;
            return s->wi;
        },
        [&](Vec3 wi) { return double(bsdf.pdf(wo, wi, mode)); }, so);
}

AlbedoEstimate directional_albedo(const Bsdf& bsdf, Vec3 wo, int samples, uint64_t seed,
                                  Transport mode) {
    Rng rng(seed);
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int i = 0; i < samples; ++i) {
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> s = bsdf.sample(wo, u_lobe, u, mode);
        if (!s || !(s->pdf > 0)) continue;
        const Spectrum w = s->weight();
        for (int c = 0; c < 3; ++c) {
            sum[c] += w[c];
            sum2[c] += double(w[c]) * w[c];
        }
    }
    AlbedoEstimate a;
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / samples;
        const double var = std::max(0.0, sum2[c] / samples - mean * mean);
        a.mean[c] = float(mean);
        a.std_error[c] = float(std::sqrt(var / (samples - 1)));
    }
    return a;
}

Vec3 spherical_direction(float cos_theta, float phi) {
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace penumbra::test
