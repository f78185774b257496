#include "support/statistics/chi2.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "support/statistics/quadrature.h"

namespace penumbra::test {

namespace {

// Series for the lower function P(a, x), valid for x < a + 1 (Numerical Recipes 6.2).
double gamma_p_series(double a, double x) {
    double ap = a, sum = 1 / a, del = sum;
    for (int n = 0; n < 100000; ++n) {
        ap += 1;
        del *= x / ap;
        sum += del;
        if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction for Q(a, x), valid for x >= a + 1 (modified Lentz).
double gamma_q_fraction(double a, double x) {
    constexpr double kTiny = 1e-300;
    double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// The absolute tolerance of 1e-7 per cell keeps the error of an expected count far
// below its noise (2e5 samples give 0.02 counts).
constexpr double kCellTolerance = 1e-7;

std::string format(const char* fmt, double a, double b, double c, double d) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
    return buf;
}

}  // namespace

double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    if (x < a + 1) return 1 - gamma_p_series(a, x);
    return gamma_q_fraction(a, x);
}

double chi2_p_value(double statistic, int dof) {
    return dof > 0 ? gamma_q(0.5 * dof, 0.5 * statistic) : 0;
}

double sidak_significance(double alpha, int tests) { return 1 - std::pow(1 - alpha, 1.0 / tests); }

Chi2Result chi2_compare(const std::vector<double>& observed, const std::vector<double>& expected,
                        uint64_t samples, double significance,
                        const std::function<std::string(size_t)>& cell_name) {
    constexpr double kMinExpected = 5;
    Chi2Result r;
    r.samples = samples;
    r.significance = significance;
    std::string problems;

    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t i, size_t j) { return expected[i] < expected[j]; });
    // Pool the sparse cells, smallest expectation first, as pbrt-v4 does; while the pool
    // is still below the minimum it absorbs the next cell too.
    double pooled_obs = 0, pooled_exp = 0;
    for (size_t i : order) {
        if (expected[i] <= 0) {
            if (observed[i] > 0) r.invalid += static_cast<uint64_t>(observed[i]);
            if (observed[i] > 1e-5 * samples)
                problems += "  " + std::to_string(static_cast<uint64_t>(observed[i])) +
                            " samples in zero-density cell " + cell_name(i) + "\n";
        } else if (expected[i] < kMinExpected || (pooled_exp > 0 && pooled_exp < kMinExpected)) {
            pooled_obs += observed[i];
            pooled_exp += expected[i];
        } else {
            const double d = observed[i] - expected[i];
            r.statistic += d * d / expected[i];
            ++r.dof;
        }
    }
    if (pooled_exp > 0) {
        const double d = pooled_obs - pooled_exp;
        r.statistic += d * d / pooled_exp;
        ++r.dof;
    }
    r.dof -= 1;  // the counts sum to the sample count
    r.p_value = chi2_p_value(r.statistic, r.dof);
    if (r.dof < 1) problems += "  fewer than 2 cells with an expected count of 5\n";
    r.passed = problems.empty() && r.p_value > significance;

    r.report = format("chi2 = %.2f, dof = %.0f, p = %.3g (level %.3g)", r.statistic, r.dof,
                      r.p_value, significance) +
               format(", samples = %.0f\n", double(samples), 0, 0, 0) + problems;
    // The cells that contribute most, pooled ones included, to see where it goes wrong.
    std::vector<size_t> worst;
    for (size_t i = 0; i < observed.size(); ++i)
        if (expected[i] > 0) worst.push_back(i);
    auto contribution = [&](size_t i) {
        const double d = observed[i] - expected[i];
        return d * d / expected[i];
    };
    const size_t shown = std::min<size_t>(8, worst.size());
    std::partial_sort(worst.begin(), worst.begin() + shown, worst.end(),
                      [&](size_t i, size_t j) { return contribution(i) > contribution(j); });
    r.report += "  worst cells (observed / expected, contribution):\n";
    for (size_t k = 0; k < shown; ++k) {
        const size_t i = worst[k];
        r.report += "    " + cell_name(i) +
                    format(": %.0f / %.1f, %.1f\n", observed[i], expected[i], contribution(i), 0);
    }
    return r;
}

void check_pdf_integral(Chi2Result& r, double integral) {
    if (integral <= 1 + kPdfIntegralTolerance) return;
    r.passed = false;
    r.report = format("the pdf integrates to %.6f > 1\n", integral, 0, 0, 0) + r.report;
}

namespace {

// The common end of the domain tests: the integral check, the lost and invalid counts
// (any invalid sample fails), and the report's first line.
void finish(Chi2Result& r, double integral, double lost, uint64_t bad, const char* what_bad) {
    r.pdf_integral = integral;
    check_pdf_integral(r, integral);
    r.lost = static_cast<uint64_t>(lost);
    r.invalid += bad;
    if (bad > 0) {
        r.passed = false;
        r.report = std::to_string(bad) + " " + what_bad + "\n" + r.report;
    }
    r.report = format("pdf integral = %.6f, no sample = %.0f\n", integral, lost, 0, 0) + r.report;
}

}  // namespace

Chi2Result chi2_sphere(const DirectionSampler& sample, const DirectionPdf& pdf,
                       const SphereChi2Options& o) {
    const int nz = o.cos_bins, nphi = o.phi_bins;
    const double z_lo = o.hemisphere ? 0.0 : -1.0, dz = (1 - z_lo) / nz;
    const double dphi = 2 * M_PI / nphi;
    const size_t cells = size_t(nz) * nphi;
    // The last cell stands for "no sample": expected 1 - integral of the pdf.
    std::vector<double> observed(cells + 1, 0), expected(cells + 1, 0);

    Rng rng(o.seed);
    uint64_t bad = 0;
    for (int i = 0; i < o.samples; ++i) {
        const std::optional<Vec3> w = sample(rng);
        if (!w) {
            observed[cells] += 1;
            continue;
        }
        const double len2 = double(w->x) * w->x + double(w->y) * w->y + double(w->z) * w->z;
        if (!is_finite(*w) || std::abs(len2 - 1) > 1e-4 || w->z < z_lo) {
            ++bad;
            continue;
        }
        const int iz = std::clamp(static_cast<int>((w->z - z_lo) / dz), 0, nz - 1);
        double phi = std::atan2(double(w->y), double(w->x));
        if (phi < 0) phi += 2 * M_PI;
        const int iphi = std::clamp(static_cast<int>(phi / dphi), 0, nphi - 1);
        observed[size_t(iz) * nphi + iphi] += 1;
    }

    double integral = 0;
    for (int iz = 0; iz < nz; ++iz)
        for (int iphi = 0; iphi < nphi; ++iphi) {
            // dw = dz dphi in these coordinates.
            const double z0 = z_lo + iz * dz, phi0 = iphi * dphi;
            const double p = integrate_2d(
                [&](double z, double phi) {
                    const double s = std::sqrt(std::max(0.0, 1 - z * z));
                    return pdf(Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
                },
                z0, z0 + dz, phi0, phi0 + dphi, kCellTolerance);
            expected[size_t(iz) * nphi + iphi] = p * o.samples;
            integral += p;
        }
    expected[cells] = std::max(0.0, 1 - integral) * o.samples;

    Chi2Result r = chi2_compare(observed, expected, o.samples, o.significance, [&](size_t i) {
        if (i == cells) return std::string("[no sample]");
        const double z0 = z_lo + (i / nphi) * dz, phi0 = (i % nphi) * dphi;
        return format("cos [%+.2f, %+.2f] phi [%.2f, %.2f]", z0, z0 + dz, phi0, phi0 + dphi);
    });
    finish(r, integral, observed[cells], bad, "samples were NaN, not unit length or off the domain");
    return r;
}

Chi2Result chi2_planar(const PointSampler& sample, const PointPdf& pdf,
                       const PlanarChi2Options& o) {
    const int nx = o.x_bins, ny = o.y_bins;
    const double dx = (double(o.hi.x) - o.lo.x) / nx, dy = (double(o.hi.y) - o.lo.y) / ny;
    const size_t cells = size_t(nx) * ny;
    std::vector<double> observed(cells + 1, 0), expected(cells + 1, 0);

    Rng rng(o.seed);
    uint64_t bad = 0;
    for (int i = 0; i < o.samples; ++i) {
        const std::optional<Vec2> p = sample(rng);
        if (!p) {
            observed[cells] += 1;
            continue;
        }
        if (!std::isfinite(p->x) || !std::isfinite(p->y) || p->x < o.lo.x || p->x > o.hi.x ||
            p->y < o.lo.y || p->y > o.hi.y) {
            ++bad;
            continue;
        }
        const int ix = std::clamp(static_cast<int>((p->x - o.lo.x) / dx), 0, nx - 1);
        const int iy = std::clamp(static_cast<int>((p->y - o.lo.y) / dy), 0, ny - 1);
        observed[size_t(iy) * nx + ix] += 1;
    }

    double integral = 0;
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) {
            const double x0 = o.lo.x + ix * dx, y0 = o.lo.y + iy * dy;
            const double p =
                integrate_2d([&](double x, double y) { return pdf(Vec2(float(x), float(y))); }, x0,
                             x0 + dx, y0, y0 + dy, kCellTolerance);
            expected[size_t(iy) * nx + ix] = p * o.samples;
            integral += p;
        }
    expected[cells] = std::max(0.0, 1 - integral) * o.samples;

    Chi2Result r = chi2_compare(observed, expected, o.samples, o.significance, [&](size_t i) {
        if (i == cells) return std::string("[no sample]");
        const double x0 = o.lo.x + (i % nx) * dx, y0 = o.lo.y + (i / nx) * dy;
        return format("x [%+.3f, %+.3f] y [%+.3f, %+.3f]", x0, x0 + dx, y0, y0 + dy);
    });
    finish(r, integral, observed[cells], bad, "samples were NaN or outside the rectangle");
    return r;
}

}  // namespace penumbra::test
