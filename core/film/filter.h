// Pixel reconstruction filters, used by filter importance sampling (as pbrt-v4 does):
// each camera sample's film offset is drawn from the filter itself and carries the
// weight f/pdf, so a sample only ever touches its own pixel. That keeps rendering
// deterministic across threads with no shared splatting.
#pragma once

#include <memory>
#include <string>

#include "core/math/vec.h"
#include "core/sampling/distribution.h"

namespace penumbra {

struct FilterSample {
    Vec2 offset;   // from the pixel center, in pixels
    float weight;  // f(offset) / pdf(offset)
};

class Filter {
public:
    // Separable filter f(x) f(y) with support [-radius, radius]^2.
    Filter(std::string name, float radius);
    virtual ~Filter() = default;
    virtual float eval_1d(float x) const = 0;
    float eval(Vec2 p) const { return eval_1d(p.x) * eval_1d(p.y); }
    // u in [0,1)^2, e.g. a stratified pixel sample. By the tabulated distribution unless
    // a filter has a closed form.
    virtual FilterSample sample(Vec2 u) const;
    float radius() const { return m_radius; }
    const std::string& name() const { return m_name; }

protected:
    // Tabulates |f| for sampling; derived constructors call it once eval_1d is usable.
    void tabulate();

private:
    float sample_1d(float u, float* pdf) const;
    std::string m_name;
    float m_radius;
    // |f| at the midpoints of kBins bins over [-radius, radius], sampled by inversion
    // with Distribution1D's guide table: one lookup and a short walk per camera sample,
    // where a binary search over the CDF was 6.5% of a default-filter render of glossy.
    Distribution1D m_distribution;
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

// "box" | "gaussian" | "blackman-harris"; throws std::invalid_argument otherwise.
std::unique_ptr<Filter> make_filter(const std::string& name);

}  // namespace penumbra
