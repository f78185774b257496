#include "support/bsdf/bsdf_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "materials/lobes/fresnel.h"
#include "support/statistics/quadrature.h"

namespace penumbra::test {

namespace {

bool close(float a, float b, float rel_tol) {
    return std::abs(a - b) <= rel_tol * std::max(std::abs(a), std::abs(b)) + 1e-30f;
}

std::string str(Vec3 v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

// A float stands for every real that rounds to it: a uniform point of that interval.
double dither(float v, Rng& rng) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const double lo = 0.5 * (double(std::nextafter(v, -kInf)) + v);
    const double hi = 0.5 * (double(std::nextafter(v, kInf)) + v);
    return lo + (hi - lo) * ((rng.next_u32() + 0.5) * 0x1p-32);
}

// The plane the half-vector test bins h in: cells of 0.1 x 0.1 over [-2, 0] x [-1, 1]
// (reflection) and [0, 2] x [-1, 1] (refraction, where eta is not 0), and a last cell
// for no sample. Anisotropic lobes bin h by its stretched slope (x / alpha.x, y /
// alpha.y) / z, in which they are round.
struct HalfVectorPlane {
    Vec2 alpha;
    float eta, etap;
    int nx, ny;
    double cell = 0.1;
    size_t cells;
    HalfVectorPlane(Vec3 wo, Vec2 alpha_, float eta_)
        : alpha(alpha_),
          eta(eta_),
          etap(eta_ == 0 ? 0 : (wo.z > 0 ? eta_ : 1 / eta_)),
          nx(eta_ == 0 ? 20 : 40),
          ny(20),
          cells(size_t(nx) * ny) {}
};

// Counts o.samples BSDF samples into the plane's cells; returns how many were NaN or
// transmitted by a reflector.
//
// The disk magnifies wi's float grid: at grazing wo, reflection gives
// |wo + wi| = 2 wo.h ~ 2 wo.z, so one ulp of wi.x or wi.y (3e-8 or 6e-8 for
// wo.xy ~ 0.5, 0.9) moves h by ulp / (2 wo.z). At alpha 1e-4 and wo.z 0.02 that is
// 0.0075 and 0.015 across the 0.1 cells near the centre: the samples lie on a grid
// of 13 x 6 or 7 lines a cell, which the integrated pdf cannot know, and the counts
// alias by up to +-20% (p 1e-6). So each sample is binned as a uniform point of
// its float rounding box (in double; wo + wi itself is exact, by Sterbenz): the
// continuous density blurred over one ulp, far below the counts' noise.
uint64_t observe_half_vectors(const Bsdf& bsdf, Vec3 wo, const HalfVectorPlane& g,
                              const BsdfChi2Options& o, Transport mode,
                              std::vector<double>& observed) {
    Rng rng(o.seed), dither_rng(o.seed, 0x5bd1e995);
    uint64_t bad = 0;
    for (int i = 0; i < o.samples; ++i) {
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> s = bsdf.sample(wo, u_lobe, u, mode);
        if (!s || s->is_specular()) {
            observed[g.cells] += 1;
            continue;
        }
        const bool reflection = s->wi.z * wo.z > 0;
        if (!is_finite(s->wi) || (!reflection && g.eta == 0)) {
            ++bad;
            continue;
        }
        const double e = reflection ? 1 : g.etap;
        double h[3] = {wo.x + e * dither(s->wi.x, dither_rng),
                       wo.y + e * dither(s->wi.y, dither_rng),
                       wo.z + e * dither(s->wi.z, dither_rng)};
        if (h[2] < 0)
            for (double& c : h) c = -c;
        const double sx = h[0] / g.alpha.x, sy = h[1] / g.alpha.y;
        const double t = std::sqrt(sx * sx + sy * sy) / h[2], q = t / std::sqrt(1 + t * t);
        const double phi = std::atan2(sy, sx);
        const double x = q * std::cos(phi) + (reflection ? 1 : 3), y = q * std::sin(phi) + 1;
        const int ix = std::clamp(int(x / g.cell), 0, g.nx - 1),
                  iy = std::clamp(int(y / g.cell), 0, g.ny - 1);
        observed[size_t(iy) * g.nx + ix] += 1;
    }
    return bad;
}

// The samples' density per unit area of the plane (x in [0, 4), y in [0, 2)).
double half_vector_density(const Bsdf& bsdf, Vec3 wo, const HalfVectorPlane& g, Transport mode,
                           double x, double y) {
    const bool reflection = x < 2;
    const double qx = x - (reflection ? 1 : 3), qy = y - 1;
    const double q2 = qx * qx + qy * qy;
    if (q2 >= 1) return 0;
    const double t2 = q2 / (1 - q2), t = std::sqrt(t2);
    const double phi = std::atan2(qy, qx);
    const double tx = g.alpha.x * t * std::cos(phi), ty = g.alpha.y * t * std::sin(phi);
    const double cos_theta = 1 / std::sqrt(1 + tx * tx + ty * ty);
    const Vec3 h(float(tx * cos_theta), float(ty * cos_theta), float(cos_theta));
    const float woh = dot(wo, h);
    if (woh * wo.z <= 0) return 0;
    Vec3 wi;
    double jacobian;  // d omega_i / d omega_h
    if (reflection) {
        wi = reflect(wo, h);
        if (wi.z * wo.z <= 0) return 0;
        jacobian = 4 * std::abs(woh);
    } else {
        const std::optional<Vec3> w = refract(wo, woh > 0 ? h : -h, g.etap);
        if (!w || w->z * wo.z >= 0 || dot(*w, h) * w->z <= 0) return 0;
        wi = *w;
        const double wih = dot(wi, h), d = wih + woh / g.etap;
        jacobian = d * d / std::abs(wih);
    }
    // d omega_h / d area of the disk: alpha_x alpha_y cos^3 (1 + t^2)^2.
    const double dh_da =
        double(g.alpha.x) * g.alpha.y * cos_theta * cos_theta * cos_theta * (1 + t2) * (1 + t2);
    return double(bsdf.pdf(wo, wi, mode)) * jacobian * dh_da;
}

// Each cell's expected count (the last: no sample); returns the density's integral.
// At alpha 1e-3, pdf() at a wi rebuilt from h in float is only good to ~1e-4
// relative, so the cells are integrated to that (a bias far below the counts' noise),
// not to chi2_sphere's 1e-5, which float noise would never let converge.
double expect_half_vectors(const Bsdf& bsdf, Vec3 wo, const HalfVectorPlane& g, int samples,
                           Transport mode, std::vector<double>& expected) {
    double integral = 0;
    for (int iy = 0; iy < g.ny; ++iy)
        for (int ix = 0; ix < g.nx; ++ix) {
            const double x0 = ix * g.cell, y0 = iy * g.cell;
            const double p = integrate_1d(
                [&](double x) {
                    return integrate_1d(
                        [&](double y) { return half_vector_density(bsdf, wo, g, mode, x, y); }, y0,
                        y0 + g.cell, 1e-9, 3e-4, 2, 60);
                },
                x0, x0 + g.cell, 1e-8, 3e-4, 2, 60);
            expected[size_t(iy) * g.nx + ix] = p * samples;
            integral += p;
        }
    expected[g.cells] = std::max(0.0, 1 - integral) * samples;
    return integral;
}

}  // namespace

Chi2Result bsdf_chi2_sphere(const Bsdf& bsdf, Vec3 wo, const BsdfChi2Options& o, Transport mode) {
    BsdfChi2Options sphere = o;
    sphere.full_sphere = true;
    sphere.cos_bins = 20;
    return bsdf_chi2(bsdf, wo, sphere, mode);
}

Chi2Result bsdf_chi2_half_vector(const Bsdf& bsdf, Vec3 wo, float alpha, float eta,
                                 const BsdfChi2Options& o, Transport mode) {
    return bsdf_chi2_half_vector(bsdf, wo, Vec2(alpha, alpha), eta, o, mode);
}

Chi2Result bsdf_chi2_half_vector(const Bsdf& bsdf, Vec3 wo, Vec2 alpha, float eta,
                                 const BsdfChi2Options& o, Transport mode) {
    const HalfVectorPlane g(wo, alpha, eta);
    std::vector<double> observed(g.cells + 1, 0), expected(g.cells + 1, 0);
    const uint64_t bad = observe_half_vectors(bsdf, wo, g, o, mode, observed);
    const double integral = expect_half_vectors(bsdf, wo, g, o.samples, mode, expected);

    Chi2Result r = chi2_compare(observed, expected, o.samples, o.significance, [&](size_t i) {
        if (i == g.cells) return std::string("[no sample]");
        const bool reflection = int(i % g.nx) < 20;
        const double qx = (i % g.nx) * g.cell - (reflection ? 1 : 3), qy = (i / g.nx) * g.cell - 1;
        std::ostringstream s;
        s << (reflection ? "reflection" : "refraction") << " h cell q [" << qx << ", " << qy << "]";
        return s.str();
    });
    r.pdf_integral = integral;
    check_pdf_integral(r, integral);
    r.lost = static_cast<uint64_t>(observed[g.cells]);
    r.invalid += bad;
    if (bad > 0) {
        r.passed = false;
        r.report =
            std::to_string(bad) + " samples were NaN or transmitted by a reflector\n" + r.report;
    }
    r.report = "pdf integral = " + std::to_string(integral) +
               ", no sample = " + std::to_string(r.lost) + "\n" + r.report;
    return r;
}

std::string check_sample_agreement(const Bsdf& bsdf, Vec3 wo, int n, uint64_t seed, Transport mode,
                                   float rel_tol) {
    Rng rng(seed);
    for (int i = 0; i < n; ++i) {
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> s = bsdf.sample(wo, u_lobe, u, mode);
        if (!s) continue;
        std::ostringstream what;
        what << "wo " << str(wo) << ", wi " << str(s->wi) << ", f " << str(s->f) << ", pdf "
             << s->pdf << ": ";
        if (std::abs(length(s->wi) - 1) > 1e-4f) return what.str() + "wi is not unit length";
        if (!is_finite(s->weight())) return what.str() + "weight is not finite";
        if (s->is_specular()) {
            if (!(s->pdf > 0 && s->pdf <= 1)) return what.str() + "lobe probability off (0, 1]";
            continue;
        }
        if (!(s->pdf > 0)) return what.str() + "non-positive pdf";
        const Spectrum f = bsdf.eval(wo, s->wi, mode);
        const float pdf = bsdf.pdf(wo, s->wi, mode);
        for (int c = 0; c < 3; ++c)
            if (!close(s->f[c], f[c], rel_tol)) return what.str() + "eval() gives " + str(f);
        if (!close(s->pdf, pdf, rel_tol)) return what.str() + "pdf() gives " + std::to_string(pdf);
        const Spectrum w = f * (std::abs(s->wi.z) / pdf);
        for (int c = 0; c < 3; ++c)
            if (!close(s->weight()[c], w[c], rel_tol))
                return what.str() + "weight " + str(s->weight()) + " is not f cos / pdf";
    }
    return "";
}

std::string check_reciprocity(const Bsdf& bsdf, int n, uint64_t seed, float tol, float min_cos) {
    Rng rng(seed);
    for (int i = 0; i < n; ++i) {
        const Vec3 wo = random_direction(rng, min_cos), wi = random_direction(rng, min_cos);
        for (Transport mode : {Transport::Radiance, Transport::Importance}) {
            const Spectrum a = bsdf.eval(wo, wi, mode), b = bsdf.eval(wi, wo, mode);
            for (int c = 0; c < 3; ++c)
                if (!close(a[c], b[c], tol))
                    return "f(" + str(wo) + ", " + str(wi) + ") = " + str(a) +
                           " but the swapped pair gives " + str(b);
        }
    }
    return "";
}

Vec3 random_direction(Rng& rng, float min_cos, bool lower) {
    const float c = min_cos + (1 - min_cos) * rng.next_float();
    const Vec3 w = spherical_direction(c, 2 * kPi * rng.next_float());
    return lower ? Vec3(w.x, w.y, -w.z) : w;
}

}  // namespace penumbra::test
