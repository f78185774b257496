#include "core/film/filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace penumbra {

namespace {
constexpr int kBins = 256;
}

Filter::Filter(std::string name, float radius) : m_name(std::move(name)), m_radius(radius) {}

void Filter::tabulate() {
    // Midpoint values: the samples follow |f| closely and f/pdf is nearly constant
    // (exactly constant for the box).
    std::vector<float> f(kBins);
    const float dx = 2 * m_radius / kBins;
    for (int i = 0; i < kBins; ++i) f[i] = std::abs(eval_1d(-m_radius + (i + 0.5f) * dx));
    m_distribution = Distribution1D(f);
}

float Filter::sample_1d(float u, float* pdf) const {
    // Distribution1D's density is over [0, 1); the filter's support is 2 * radius wide.
    const float x = m_distribution.sample_continuous(u, pdf);
    *pdf /= 2 * m_radius;
    return (2 * x - 1) * m_radius;
}

FilterSample Filter::sample(Vec2 u) const {
    float px, py;
    const float x = sample_1d(u.x, &px), y = sample_1d(u.y, &py);
    const float pdf = px * py;
    const float f = eval({x, y});
    return {{x, y}, pdf > 0 ? f / pdf : 0.0f};
}

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
    return a0 - a1 * std::cos(w) + a2 * std::cos(2 * w) - a3 * std::cos(3 * w);
}

std::unique_ptr<Filter> make_filter(const std::string& name) {
    if (name == "box") return std::make_unique<BoxFilter>();
    if (name == "gaussian") return std::make_unique<GaussianFilter>();
    if (name == "blackman-harris") return std::make_unique<BlackmanHarrisFilter>();
    throw std::invalid_argument("unknown filter '" + name +
                                "' (expected box, gaussian or blackman-harris)");
}

}  // namespace penumbra
