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
    m_size = static_cast<float>(n);
    m_last = static_cast<uint32_t>(n - 1);
    m_equal = std::all_of(m_bins.begin(), m_bins.end(), [&](const Bin& b) {
        return b.q == 1 && b.alias == static_cast<uint32_t>(&b - m_bins.data());
    });
}

}  // namespace penumbra
