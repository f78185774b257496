#include "core/film/filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/math/portable_math.h"

namespace penumbra {

namespace {
// Cells of the midpoint rule behind the CDF: its error is far below a float's rounding.
constexpr int kCdfCells = 1 << 15;
}  // namespace

Filter::Filter(std::string name, float radius) : m_name(std::move(name)), m_radius(radius) {}

void Filter::tabulate() {
    // The CDF at the cells' ends, in double, from the filter at their midpoints (clamped
    // at 0: the Blackman-Harris window's sum of cosines rounds to -1e-8 at its ends).
    const double r = m_radius, dx = 2 * r / kCdfCells;
    std::vector<double> cdf(kCdfCells + 1, 0.0);
    for (int i = 0; i < kCdfCells; ++i)
        cdf[i + 1] = cdf[i] + std::max(0.0f, eval_1d(float(-r + (i + 0.5) * dx))) * dx;
    const double total = cdf[kCdfCells];
    // Node k: where the CDF reaches k / kInverseSteps of the total, linear inside the cell
    // that holds it (the midpoint rule's own density is constant there). The targets
    // rise with k, so one walk over the cells serves all nodes.
    m_inverse_cdf.resize(kInverseSteps + 1);
    int j = 0;
    for (int k = 0; k <= kInverseSteps; ++k) {
        const double target = total * k / kInverseSteps;
        while (j + 1 < kCdfCells && cdf[j + 1] < target) ++j;
        const double mass = cdf[j + 1] - cdf[j];
        const double into = mass > 0 ? std::clamp((target - cdf[j]) / mass, 0.0, 1.0) : 0.0;
        m_inverse_cdf[k] = float(-r + (j + into) * dx);
    }
}

float Filter::sample_1d(float u) const {
    const float s = u * kInverseSteps;
    const int k = std::clamp(static_cast<int>(s), 0, kInverseSteps - 1);
    const float a = m_inverse_cdf[k], b = m_inverse_cdf[k + 1];
    return a + (b - a) * std::clamp(s - k, 0.0f, 1.0f);
}

FilterSample Filter::sample(Vec2 u) const { return {{sample_1d(u.x), sample_1d(u.y)}, 1.0f}; }

BoxFilter::BoxFilter() : Filter("box", 0.5f) { tabulate(); }

GaussianFilter::GaussianFilter(float radius, float sigma)
    : Filter("gaussian", radius), m_sigma(sigma) {
    m_edge = std::exp(-radius * radius / (2 * sigma * sigma));
    tabulate();
}

float GaussianFilter::eval_1d(float x) const {
    if (std::abs(x) > radius()) return 0;
    return std::max(0.0f, std::exp(-x * x / (2 * m_sigma * m_sigma)) - m_edge);
}

BlackmanHarrisFilter::BlackmanHarrisFilter(float radius) : Filter("blackman-harris", radius) {
    tabulate();
}

float BlackmanHarrisFilter::eval_1d(float x) const {
    if (std::abs(x) > radius()) return 0;
    // Window over [0, 1] with t = (x + r) / 2r; coefficients from Harris 1978.
    const float t = (x + radius()) / (2 * radius());
    const float a0 = 0.35875f, a1 = 0.48829f, a2 = 0.14128f, a3 = 0.01168f;
    const float w = 2 * kPi * t;
    return a0 - a1 * portable_cos(w) + a2 * portable_cos(2 * w) - a3 * portable_cos(3 * w);
}

std::unique_ptr<Filter> make_filter(FilterType type) {
    switch (type) {
        case FilterType::Box: return std::make_unique<BoxFilter>();
        case FilterType::Gaussian: return std::make_unique<GaussianFilter>();
        case FilterType::BlackmanHarris: return std::make_unique<BlackmanHarrisFilter>();
    }
    throw std::invalid_argument("unknown filter type");
}

const Filter& shared_filter(FilterType type) {
    static const BoxFilter box;
    static const GaussianFilter gaussian;
    static const BlackmanHarrisFilter blackman_harris;
    switch (type) {
        case FilterType::Box: return box;
        case FilterType::Gaussian: return gaussian;
        case FilterType::BlackmanHarris: return blackman_harris;
    }
    throw std::invalid_argument("unknown filter type");
}

}  // namespace penumbra
