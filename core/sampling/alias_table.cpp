#include "core/sampling/alias_table.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

AliasTable::AliasTable(const std::vector<float>& weights) {
    double sum = 0;
    for (float w : weights)
        if (w > 0 && std::isfinite(w)) sum += w;
    if (!(sum > 0)) return;
    const size_t n = weights.size();
    m_bins.resize(n);
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        const double w = weights[i] > 0 && std::isfinite(weights[i]) ? weights[i] : 0.0;
        m_bins[i].p = static_cast<float>(w / sum);
        scaled[i] = w / sum * n;
        (scaled[i] < 1 ? small : large).push_back(static_cast<uint32_t>(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back(), l = large.back();
        small.pop_back();
        m_bins[s].q = static_cast<float>(scaled[s]);
        m_bins[s].alias = l;
        scaled[l] -= 1 - scaled[s];
        if (scaled[l] < 1) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Leftovers are 1 up to rounding.
    for (uint32_t i : large) m_bins[i].q = 1, m_bins[i].alias = i;
    for (uint32_t i : small) m_bins[i].q = 1, m_bins[i].alias = i;
}

uint32_t AliasTable::sample(float u, float* pmf, float* u_remapped) const {
    const float scaled = u * m_bins.size();
    const uint32_t i = std::min(static_cast<uint32_t>(scaled), static_cast<uint32_t>(m_bins.size() - 1));
    const float up = scaled - i;
    const uint32_t chosen = up < m_bins[i].q ? i : m_bins[i].alias;
    if (pmf) *pmf = m_bins[chosen].p;
    if (u_remapped) {
        // The alias branch only runs when q < 1 (up < 1 always).
        const float q = m_bins[i].q;
        *u_remapped = std::min(up < q ? up / q : (up - q) / (1 - q), 0x1.fffffep-1f);
    }
    return chosen;
}

}  // namespace penumbra
