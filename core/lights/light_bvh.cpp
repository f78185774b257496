#include "core/lights/light_bvh.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
constexpr int kBuckets = 12;
constexpr int kMaxCostDepth = 32;

// pbrt-v4's EvaluateCost: power times the orientation measure M_Omega (the solid angle
// the cone of normals widened by the emission spread sweeps, Conty Estevez & Kulla eq. 1)
// times the box's surface area, stretched by Kr so long thin boxes split across.
float split_cost(const LightBounds& b, int axis) {
    const float theta_o = std::acos(std::clamp(b.cos_theta_o, -1.0f, 1.0f));
    const float theta_e = std::acos(std::clamp(b.cos_theta_e, -1.0f, 1.0f));
    const float theta_w = std::min(theta_o + theta_e, kPi);
    const float sin_o = std::sqrt(std::max(0.0f, 1 - b.cos_theta_o * b.cos_theta_o));
    const float m_omega =
        2 * kPi * (1 - b.cos_theta_o) + kPi / 2 *
                                            (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) -
                                             2 * theta_o * sin_o + b.cos_theta_o);
    const Vec3 d = b.hi - b.lo;
    const float area = 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    // A box flat along the axis (coplanar emitters) is not stretched.
    const float kr = d[axis] > 0 ? max_component(d) / d[axis] : 1.0f;
    return b.phi * m_omega * kr * area;
}

}  // namespace

LightBvh::LightBvh(std::vector<std::pair<uint32_t, LightBounds>> lights) {
    lights.erase(std::remove_if(lights.begin(), lights.end(),
                                [](const auto& l) { return !(l.second.phi > 0); }),
                 lights.end());
    if (lights.empty()) return;
    uint32_t max_index = 0;
    for (const auto& l : lights) max_index = std::max(max_index, l.first);
    m_trail.assign(size_t(max_index) + 1, kNotInTree);
    m_nodes.reserve(2 * lights.size() - 1);
    build(lights, 0, lights.size(), 0, 0);
}

uint32_t LightBvh::build(std::vector<std::pair<uint32_t, LightBounds>>& lights, size_t begin,
                         size_t end, int depth, uint64_t trail) {
    const uint32_t node = static_cast<uint32_t>(m_nodes.size());
    m_nodes.emplace_back();
    if (end - begin == 1) {
        m_nodes[node] = Node{lights[begin].second, lights[begin].first, true};
        m_trail[lights[begin].first] = trail;
        return node;
    }
    LightBounds all;
    Vec3 c_lo(INFINITY), c_hi(-INFINITY);
    for (size_t i = begin; i < end; ++i) {
        all = merge(all, lights[i].second);
        c_lo = min(c_lo, lights[i].second.centroid());
        c_hi = max(c_hi, lights[i].second.centroid());
    }
    const Vec3 extent = c_hi - c_lo;

    // The cheapest bucket boundary over the three axes.
    float best_cost = INFINITY;
    int best_axis = -1, best_bucket = -1;
    auto bucket_of = [&](const LightBounds& b, int axis) {
        const float t = (b.centroid()[axis] - c_lo[axis]) / extent[axis];
        return std::min(kBuckets - 1, std::max(0, int(t * kBuckets)));
    };
    for (int axis = 0; axis < 3 && depth < kMaxCostDepth; ++axis) {
        if (!(extent[axis] > 0)) continue;
        LightBounds bucket[kBuckets];
        for (size_t i = begin; i < end; ++i) {
            const int b = bucket_of(lights[i].second, axis);
            bucket[b] = merge(bucket[b], lights[i].second);
        }
        for (int split = 0; split < kBuckets - 1; ++split) {
            LightBounds below, above;
            for (int b = 0; b <= split; ++b) below = merge(below, bucket[b]);
            for (int b = split + 1; b < kBuckets; ++b) above = merge(above, bucket[b]);
            if (!(below.phi > 0) || !(above.phi > 0)) continue;
            const float cost = split_cost(below, axis) + split_cost(above, axis);
            if (cost < best_cost) best_cost = cost, best_axis = axis, best_bucket = split;
        }
    }
    size_t mid;
    if (best_axis >= 0) {
        const auto it = std::partition(
            lights.begin() + begin, lights.begin() + end,
            [&](const auto& l) { return bucket_of(l.second, best_axis) <= best_bucket; });
        mid = size_t(it - lights.begin());
    } else {
        mid = begin;
    }
    if (mid == begin || mid == end) {
        // Coincident centroids, a bucketing that failed, or deep in the tree: halve by
        // count along the longest centroid axis, which bounds the depth by log2(n).
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        mid = (begin + end) / 2;
        std::nth_element(lights.begin() + begin, lights.begin() + mid, lights.begin() + end,
                         [axis](const auto& a, const auto& b) {
                             return a.second.centroid()[axis] < b.second.centroid()[axis];
                         });
    }
    build(lights, begin, mid, depth + 1, trail);
    const uint32_t second = build(lights, mid, end, depth + 1, trail | (uint64_t(1) << depth));
    m_nodes[node] = Node{all, second, false};
    return node;
}

std::pair<float, float> LightBvh::child_importance(uint32_t i, Vec3 p, Vec3 n) const {
    return {m_nodes[i + 1].bounds.importance(p, n),
            m_nodes[m_nodes[i].index].bounds.importance(p, n)};
}

std::optional<std::pair<uint32_t, float>> LightBvh::sample(Vec3 p, Vec3 n, float u) const {
    if (m_nodes.empty()) return std::nullopt;
    uint32_t i = 0;
    float pmf = 1;
    while (!m_nodes[i].leaf) {
        const auto [i0, i1] = child_importance(i, p, n);
        if (!(i0 > 0) && !(i1 > 0)) return std::nullopt;
        const float p0 = i0 / (i0 + i1), p1 = i1 / (i0 + i1);  // as pmf() computes them
        // Reuse u for the rest of the descent, rescaled into the chosen interval.
        if (u < p0) {
            i = i + 1;
            u = std::min(u / p0, kOneMinusEpsilon);
            pmf *= p0;
        } else {
            i = m_nodes[i].index;
            u = std::min((u - p0) / (1 - p0), kOneMinusEpsilon);
            pmf *= p1;
        }
    }
    // A lone light at the root was never weighed against a sibling.
    if (i == 0 && !(m_nodes[0].bounds.importance(p, n) > 0)) return std::nullopt;
    return std::pair{m_nodes[i].index, pmf};
}

float LightBvh::pmf(Vec3 p, Vec3 n, uint32_t light) const {
    if (light >= m_trail.size() || m_trail[light] == kNotInTree) return 0;
    uint64_t trail = m_trail[light];
    uint32_t i = 0;
    float pmf = 1;
    while (!m_nodes[i].leaf) {
        const auto [i0, i1] = child_importance(i, p, n);
        if (!(i0 > 0) && !(i1 > 0)) return 0;
        if (trail & 1) {
            pmf *= i1 / (i0 + i1);
            i = m_nodes[i].index;
        } else {
            pmf *= i0 / (i0 + i1);
            i = i + 1;
        }
        trail >>= 1;
    }
    if (i == 0 && !(m_nodes[0].bounds.importance(p, n) > 0)) return 0;
    return pmf;
}

}  // namespace penumbra
