// Pixel reconstruction filters, used by filter importance sampling: each camera sample's
// film offset is drawn from the filter itself, so a sample only ever touches its own
// pixel. That keeps rendering deterministic across threads with no shared splatting.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/math/vec.h"

namespace penumbra {

struct FilterSample {
    Vec2 offset;   // from the pixel center, in pixels
    float weight;  // 1: the offsets' density is the filter (Filter::sample)
};

class Filter {
public:
    // Separable filter f(x) f(y) >= 0 with support [-radius, radius]^2.
    Filter(std::string name, float radius);
    virtual ~Filter() = default;
    virtual float eval_1d(float x) const = 0;
    float eval(Vec2 p) const { return eval_1d(p.x) * eval_1d(p.y); }
    // u in [0,1)^2, e.g. a stratified pixel sample. Each axis goes through the filter's
    // tabulated inverse CDF (unless a filter has a closed form), so the offsets' density
    // is the normalized filter, up to the table's steps, and every weight is 1 (as
    // Cycles' filter table). Weighting by f/pdf instead, as pbrt-v4 does, evaluates the
    // filter (an exp per axis) and searches a CDF per camera sample, 4-6% of a render
    // (docs/performance.md); the table's density is within an L1 distance of 1.2e-4 of
    // the filter, all of it in the tails.
    virtual FilterSample sample(Vec2 u) const;
    // The offset along one axis for u in [0, 1): nondecreasing in u.
    float sample_1d(float u) const;
    float radius() const { return m_radius; }
    const std::string& name() const { return m_name; }

    // Equal-probability steps of the inverse CDF: the offsets' density is constant
    // between two nodes, each span holding 1 / kInverseSteps of the filter's mass.
    static constexpr int kInverseSteps = 16384;

protected:
    // Tabulates the inverse CDF; derived constructors call it once eval_1d is usable.
    void tabulate();

private:
    std::string m_name;
    float m_radius;
    // kInverseSteps + 1 offsets: node k is where the filter's CDF reaches k / kInverseSteps,
    // so a sample is one multiply, two loads and one interpolation per axis.
    std::vector<float> m_inverse_cdf;
};

// Box of width 1 (radius 0.5): every sample has weight 1.
class BoxFilter final : public Filter {
public:
    BoxFilter();
    float eval_1d(float x) const override { return std::abs(x) <= 0.5f ? 1.0f : 0.0f; }
    // The inverse CDF is u - 1/2: no table search per camera ray (3.5% of a render).
    FilterSample sample(Vec2 u) const override { return {{u.x - 0.5f, u.y - 0.5f}, 1.0f}; }
};

// Gaussian of standard deviation sigma truncated at radius (shifted to reach 0 there).
class GaussianFilter final : public Filter {
public:
    GaussianFilter(float radius = 1.5f, float sigma = 0.5f);
    float eval_1d(float x) const override;

private:
    float m_sigma, m_edge;
};

// Blackman-Harris window over [-radius, radius]: a smooth, nearly band-limited filter
// with negligible ringing.
class BlackmanHarrisFilter final : public Filter {
public:
    explicit BlackmanHarrisFilter(float radius = 1.5f);
    float eval_1d(float x) const override;
};

enum class FilterType { Box, Gaussian, BlackmanHarris };

std::unique_ptr<Filter> make_filter(FilterType type);
// The process's one filter of that type, built on first use (thread-safe): a filter is
// immutable once tabulated, and tabulating costs about a millisecond, which every pass
// of every render paid when each made its own.
const Filter& shared_filter(FilterType type);

}  // namespace penumbra
