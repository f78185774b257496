// Chi-square goodness-of-fit tests of a sampling routine against its density, in the
// style of pbrt-v4's bsdfs_test.cpp, Nori's chi2test and Mitsuba's chi2.py: histogram
// the samples, integrate the pdf over each cell for the expected counts, pool sparse
// cells and compare. Seeds are fixed, so a failure is reproducible.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/math/vec.h"
#include "core/sampling/rng.h"

namespace penumbra::test {

struct Chi2Result {
    double statistic = 0;
    int dof = 0;
    double p_value = 0;
    double significance = 0;  // the per-test level the p-value was compared with
    double pdf_integral = 0;  // numerical integral of the pdf over the whole domain
    uint64_t samples = 0;     // attempts, including those that returned no sample
    uint64_t lost = 0;        // attempts that returned no sample
    uint64_t invalid = 0;     // NaN, off the domain, or in a cell of zero density
    bool passed = false;
    std::string report;  // statistic, counts and the worst cells, for failure messages
};

// Regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double gamma_q(double a, double x);
// P(X >= statistic) for X ~ chi-square with dof degrees of freedom.
double chi2_p_value(double statistic, int dof);
// Per-test level so that a suite of `tests` independent tests has overall level alpha.
double sidak_significance(double alpha, int tests);

// The generic test: observed counts against expected counts (the pdf's integral per
// cell times the number of attempts). Cells with an expected count below 5 are pooled,
// a cell of zero expectation holding more than 1e-5 of the samples fails outright
// (pbrt-v4's leniency for rounding), and cell_name labels cells in the report.
Chi2Result chi2_compare(const std::vector<double>& observed, const std::vector<double>& expected,
                        uint64_t samples, double significance,
                        const std::function<std::string(size_t)>& cell_name);

// A density integrates to at most 1 (the rest is the chance of no sample). The
// "no sample" cell's expected count is clamped at 0, so a pdf too large everywhere by a
// few percent would pass the statistic almost unnoticed; this fails r outright when
// the integral exceeds 1 by more than the quadrature's tolerance.
constexpr double kPdfIntegralTolerance = 1e-3;
void check_pdf_integral(Chi2Result& r, double integral);

// Directions: cells uniform in (cos theta, phi), so all have equal solid angle.
struct SphereChi2Options {
    bool hemisphere = false;  // z in [0, 1] instead of [-1, 1]
    int cos_bins = 10;
    int phi_bins = 20;
    int samples = 200000;
    uint64_t seed = 1;
    double significance = 0.01;  // already Sidak-corrected for the suite
};
// Draws one direction (unit length) from the routine under test; empty: no sample.
using DirectionSampler = std::function<std::optional<Vec3>(Rng&)>;
// Density per unit solid angle.
using DirectionPdf = std::function<double(Vec3)>;
// Expected counts come from nested adaptive Gauss-Kronrod integration per cell, which
// resolves lobes far narrower than a cell (GGX at alpha 1e-3) and jumps of the density.
Chi2Result chi2_sphere(const DirectionSampler& sample, const DirectionPdf& pdf,
                       const SphereChi2Options& options);

// Points of a planar rectangle [lo, hi] (unit square, disk, filter support).
struct PlanarChi2Options {
    Vec2 lo{0, 0}, hi{1, 1};
    int x_bins = 20;
    int y_bins = 20;
    int samples = 200000;
    uint64_t seed = 1;
    double significance = 0.01;
};
using PointSampler = std::function<std::optional<Vec2>(Rng&)>;
using PointPdf = std::function<double(Vec2)>;  // density per unit area
Chi2Result chi2_planar(const PointSampler& sample, const PointPdf& pdf,
                       const PlanarChi2Options& options);

}  // namespace penumbra::test
