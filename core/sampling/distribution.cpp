#include "core/sampling/distribution.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

Distribution1D::Distribution1D(const std::vector<float>& func) : m_func(func) {
    const size_t n = m_func.size();
    for (float& f : m_func) f = (f > 0 && std::isfinite(f)) ? f : 0.0f;
    m_cdf.assign(n + 1, 0);
    double acc = 0;
    for (size_t i = 0; i < n; ++i) {
        acc += double(m_func[i]) / n;
        m_cdf[i + 1] = static_cast<float>(acc);
    }
    m_integral = static_cast<float>(acc);
    if (!(acc > 0)) {
        // All zero: fall back to uniform so sampling still works (pdf 1).
        for (size_t i = 0; i <= n; ++i) m_cdf[i] = float(i) / n;
        std::fill(m_func.begin(), m_func.end(), 1.0f);
        m_integral = 1;
    } else {
        for (size_t i = 1; i <= n; ++i) m_cdf[i] = static_cast<float>(m_cdf[i] / acc);
    }
    m_cdf[n] = 1;
    m_pdf.resize(n);
    for (size_t i = 0; i < n; ++i) m_pdf[i] = m_func[i] / m_integral;
    size_t guides = 1;
    while (guides < n) guides *= 2;
    m_guide.resize(guides);
    // upper_bound of each j / G in one sweep (both ascend): the first entry above it.
    size_t k = 0;
    for (size_t j = 0; j < guides; ++j) {
        const float target = float(j) / guides;
        while (k <= n && m_cdf[k] <= target) ++k;
        m_guide[j] = static_cast<uint32_t>(k);
    }
    m_guide_scale = float(guides);
}

float Distribution1D::sample_continuous(float u, float* pdf, int* offset) const {
    const size_t n = m_func.size();
    // Last bin whose CDF start is <= u (empty bins have equal CDF start and end): one
    // past it is upper_bound(u), the first entry above u. G is a power of two, so j / G
    // and u * G are exact and j / G <= u < (j + 1) / G: every entry before m_guide[j]
    // is <= j / G <= u, and the walk stops at the first above u.
    size_t i;
    if (u >= 0 && u < 1) {
        i = m_guide[static_cast<size_t>(u * m_guide_scale)];
        while (i <= n && m_cdf[i] <= u) ++i;
    } else {
        i = std::upper_bound(m_cdf.begin(), m_cdf.end(), u) - m_cdf.begin();
    }
    i = std::clamp<size_t>(i, 1, n) - 1;
    while (i + 1 < n && m_func[i] == 0) ++i;  // never land in a zero bin
    if (offset) *offset = static_cast<int>(i);
    float du = u - m_cdf[i];
    const float width = m_cdf[i + 1] - m_cdf[i];
    if (width > 0) du /= width;
    if (pdf) *pdf = m_pdf[i];
    return std::min((i + std::clamp(du, 0.0f, 1.0f)) / n, 0x1.fffffep-1f);
}

float Distribution1D::pdf(float x) const {
    const size_t n = m_func.size();
    const size_t i = std::min(static_cast<size_t>(std::max(x, 0.0f) * n), n - 1);
    return m_pdf[i];
}

Distribution2D::Distribution2D(const std::vector<float>& func, int nu, int nv) {
    m_conditional.reserve(nv);
    std::vector<float> marginal(nv);
    for (int v = 0; v < nv; ++v) {
        m_conditional.emplace_back(
            std::vector<float>(func.begin() + size_t(v) * nu, func.begin() + size_t(v + 1) * nu));
        marginal[v] = m_conditional.back().integral();
    }
    // Rows that were all zero report integral 1 after their uniform fallback; they must
    // not be chosen, so use the raw row sums for the marginal.
    for (int v = 0; v < nv; ++v) {
        double s = 0;
        for (int u = 0; u < nu; ++u) {
            const float f = func[size_t(v) * nu + u];
            if (f > 0 && std::isfinite(f)) s += f;
        }
        marginal[v] = static_cast<float>(s / nu);
    }
    m_marginal = Distribution1D(marginal);
}

Vec2 Distribution2D::sample(Vec2 u, float* pdf) const {
    float pdf_v, pdf_u;
    int v;
    const float y = m_marginal.sample_continuous(u.y, &pdf_v, &v);
    const float x = m_conditional[v].sample_continuous(u.x, &pdf_u);
    if (pdf) *pdf = pdf_u * pdf_v;
    return {x, y};
}

float Distribution2D::pdf(Vec2 p) const {
    const size_t nv = m_conditional.size();
    const size_t v = std::min(static_cast<size_t>(std::max(p.y, 0.0f) * nv), nv - 1);
    return m_conditional[v].pdf(p.x) * m_marginal.pdf(p.y);
}

}  // namespace penumbra
