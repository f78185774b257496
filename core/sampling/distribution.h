// Piecewise-constant distributions by inversion of the CDF, in 1D and 2D (a marginal
// over rows and a conditional per row), as in PBRT's environment map sampling. Inversion
// keeps stratification of the input, unlike the alias method.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math/vec.h"

namespace penumbra {

// Density over [0, 1) proportional to func (n equal bins).
class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(const std::vector<float>& func);
    // Continuous sample in [0,1); pdf is the density at it, offset the bin index.
    float sample_continuous(float u, float* pdf, int* offset = nullptr) const;
    float pdf(float x) const;  // density at x in [0,1)
    size_t size() const { return m_func.size(); }
    float integral() const { return m_integral; }  // mean of func

private:
    std::vector<float> m_func, m_cdf;
    // m_func[i] / m_integral, the density of bin i (the same division, made once).
    std::vector<float> m_pdf;
    // Guide table (Chen & Asau 1974): m_guide[j] is the bin that upper_bound finds for
    // u = j / G, G a power of two, so a u in [j / G, (j + 1) / G) starts its search
    // there and walks on, on average n / G CDF entries, instead of a binary search over
    // all of them (log2 n dependent, often mispredicted branches at every
    // sample). The result is upper_bound's, exactly.
    std::vector<uint32_t> m_guide;
    float m_guide_scale = 0;  // G
    float m_integral = 0;
};

// Density over [0,1)^2 proportional to a nu x nv grid of values (row-major, v = row).
class Distribution2D {
public:
    Distribution2D() = default;
    Distribution2D(const std::vector<float>& func, int nu, int nv);
    Vec2 sample(Vec2 u, float* pdf) const;
    float pdf(Vec2 p) const;
    float integral() const { return m_marginal.integral(); }

private:
    std::vector<Distribution1D> m_conditional;
    Distribution1D m_marginal;
};

}  // namespace penumbra
