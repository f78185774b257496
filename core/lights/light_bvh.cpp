#include "core/lights/light_bvh.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/math/float4.h"
#include "core/math/portable_math.h"

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
                                            (2 * theta_w * sin_o - portable_cos(theta_o - 2 * theta_w) -
                                             2 * theta_o * sin_o + b.cos_theta_o);
    const Vec3 d = b.hi - b.lo;
    const float area = 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    // A box flat along the axis (coplanar emitters) is not stretched.
    const float kr = d[axis] > 0 ? max_component(d) / d[axis] : 1.0f;
    return b.phi * m_omega * kr * area;
}

// cos(max(0, a - b)), sin(max(0, a - b)) lane by lane (pbrt-v4's cosSubClamped /
// sinSubClamped, as LightBounds::importance uses them).
inline F4 cos_sub_clamped(F4 sin_a, F4 cos_a, F4 sin_b, F4 cos_b) {
    return select(gt(cos_a, cos_b), F4(1.0f), cos_a * cos_b + sin_a * sin_b);
}
inline F4 sin_sub_clamped(F4 sin_a, F4 cos_a, F4 sin_b, F4 cos_b) {
    return select(gt(cos_a, cos_b), F4(0.0f), sin_a * cos_b - cos_a * sin_b);
}

// LightBounds::importance for four children of a node at once (children h to h + 3),
// from the node's precomputed bounds. One difference: "p inside the box" is read as "p
// inside the box's bounding sphere" (which holds the box), so no box is stored.
// The divider (square roots too) bounds the descent: every sine and cosine is a square
// root of the squared distance less a squared projection, times inv_len (sin_w =
// |d x w| / |d| as sqrt(|d|^2 - (d.w)^2) / |d|), so the roots run side by side instead
// of one after another, and the inverse squared distance is inv_len^2 outside the box's
// sphere and a per-child constant inside: 5 square roots and 1 division for four
// children, where the formulas read 5 and 3, three deep.
F4 importance4(const LightBvh::Node& node, int h, Vec3 p, Vec3 n, bool has_n) {
    const F4 dx = F4(p.x) - F4::load(node.cx + h), dy = F4(p.y) - F4::load(node.cy + h),
             dz = F4(p.z) - F4::load(node.cz + h);
    const F4 r2 = F4::load(node.r2 + h);
    const F4 ld2 = dx * dx + dy * dy + dz * dz;
    const F4 has_dir = gt(ld2, F4(0.0f));
    const F4 inv_len = F4(1.0f) / sqrt4(ld2);  // inf at 0: those lanes are not selected
    // At the centroid the direction is the cone's axis, as in LightBounds::importance.
    const F4 dw = dx * F4::load(node.wx + h) + dy * F4::load(node.wy + h) +
                  dz * F4::load(node.wz + h);
    const F4 cos_w = select(has_dir, clear_bits(dw, node.two_sided + h) * inv_len, F4(1.0f));
    const F4 sin_w =
        select(has_dir, min4(sqrt4(max4(F4(0.0f), ld2 - dw * dw)) * inv_len, F4(1.0f)), F4(0.0f));

    // theta_b: the cone from p that holds the box's bounding sphere (sin = radius over
    // distance); all directions inside it. 1 / max(d^2, r^2, 1e-20) is inv_len^2 outside
    // and the child's own constant inside.
    const F4 outside = gt(ld2, r2);
    const F4 cos_b = select(outside, min4(sqrt4(ld2 - r2) * inv_len, F4(1.0f)), F4(-1.0f));
    const F4 sin_b = select(outside, min4(F4::load(node.r + h) * inv_len, F4(1.0f)), F4(0.0f));
    const F4 inv_d2 = select(outside, min4(inv_len * inv_len, F4(1e20f)), F4::load(node.inv_r2 + h));

    const F4 cos_o = F4::load(node.cos_o + h), sin_o = F4::load(node.sin_o + h);
    const F4 cos_x = cos_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    const F4 sin_x = sin_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    const F4 cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
    F4 importance = F4::load(node.phi + h) * max4(F4(0.0f), cos_p) * inv_d2;
    if (has_n) {
        const F4 dn = dx * F4(n.x) + dy * F4(n.y) + dz * F4(n.z);
        const F4 cos_i = select(has_dir, max4(dn, F4(0.0f) - dn) * inv_len, F4(1.0f));
        const F4 sin_i = select(
            has_dir, min4(sqrt4(max4(F4(0.0f), ld2 - dn * dn)) * inv_len, F4(1.0f)), F4(0.0f));
        importance = importance * max4(F4(0.0f), cos_sub_clamped(sin_i, cos_i, sin_b, cos_b));
    }
    // Strictly outside the emission spread nothing arrives (cos_p < cos_theta_e).
    return select(gt(F4::load(node.cos_e + h), cos_p), F4(0.0f), importance);
}

// Every child's importance at (p, n) into imp (kWidth floats, aligned), and their sum,
// in one fixed order so that sample() and pmf() agree.
inline float weigh(const LightBvh::Node& node, Vec3 p, Vec3 n, bool has_n, float* imp) {
    for (int h = 0; h < LightBvh::kWidth; h += 4) importance4(node, h, p, n, has_n).store(imp + h);
    float sum = 0;
    for (int h = 0; h < LightBvh::kWidth; h += 4)
        sum += (imp[h] + imp[h + 1]) + (imp[h + 2] + imp[h + 3]);
    return sum;
}

inline bool has_normal(Vec3 n) { return n.x != 0 || n.y != 0 || n.z != 0; }

}  // namespace

LightBvh::LightBvh(std::vector<std::pair<uint32_t, LightBounds>> lights) {
    lights.erase(std::remove_if(lights.begin(), lights.end(),
                                [](const auto& l) { return !(l.second.phi > 0); }),
                 lights.end());
    if (lights.empty()) return;
    uint32_t max_index = 0;
    for (const auto& l : lights) max_index = std::max(max_index, l.first);
    m_trail.assign(size_t(max_index) + 1, kNotInTree);
    m_binary.reserve(2 * lights.size() - 1);
    build(lights, 0, lights.size(), 0);
    m_nodes.reserve(lights.size() / 2 + 1);
    collapse(0, 0, 0);
    m_binary = {};
}

uint32_t LightBvh::build(std::vector<std::pair<uint32_t, LightBounds>>& lights, size_t begin,
                         size_t end, int depth) {
    const uint32_t node = static_cast<uint32_t>(m_binary.size());
    m_binary.emplace_back();
    if (end - begin == 1) {
        m_binary[node] = BinaryNode{lights[begin].second, lights[begin].first, true};
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
        // Bounds of the buckets above each split, swept once from the top (the build spent
        // most of its time re-merging them for every split).
        LightBounds above_of[kBuckets];
        for (int b = kBuckets - 1; b > 0; --b)
            above_of[b - 1] = merge(bucket[b], b + 1 < kBuckets ? above_of[b] : LightBounds{});
        LightBounds below;
        for (int split = 0; split < kBuckets - 1; ++split) {
            below = merge(below, bucket[split]);
            const LightBounds& above = above_of[split];
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
    build(lights, begin, mid, depth + 1);
    const uint32_t second = build(lights, mid, end, depth + 1);
    m_binary[node] = BinaryNode{all, second, false};
    return node;
}


void LightBvh::gather(uint32_t binary, int levels, uint32_t* slots, int* count) const {
    const BinaryNode& b = m_binary[binary];
    if (b.leaf || levels == 0) {
        slots[(*count)++] = binary;
        return;
    }
    gather(binary + 1, levels - 1, slots, count);
    gather(b.index, levels - 1, slots, count);
}

uint32_t LightBvh::collapse(uint32_t binary, int depth, uint64_t trail) {
    // Up to kWidth slots: the binary node's descendants kLevels levels down, or the
    // leaves above them. A lone light at the root is its own (single) slot.
    // The trail holds kLevels bits a level: 64 binary levels, which the build's depth
    // (32 + log2 of the light count) reaches only past 2^31 lights.
    if (kLevels * (depth + 1) > 64)
        throw InternalError("light BVH deeper than its trails can record");
    uint32_t slots[kWidth];
    int count = 0;
    if (m_binary[binary].leaf) slots[count++] = binary;
    else gather(binary, kLevels, slots, &count);
    const uint32_t index = static_cast<uint32_t>(m_nodes.size());
    m_nodes.emplace_back();
    Node node{};
    for (int k = 0; k < kWidth; ++k) {
        node.wz[k] = 1, node.cos_o[k] = 1;  // an empty slot: phi 0, importance 0
        if (k >= count) continue;
        const BinaryNode& s = m_binary[slots[k]];
        const LightBounds& l = s.bounds;
        const Vec3 c = l.centroid();
        node.cx[k] = c.x, node.cy[k] = c.y, node.cz[k] = c.z;
        node.r2[k] = 0.25f * length_squared(l.hi - l.lo);
        node.r[k] = std::sqrt(node.r2[k]);
        node.inv_r2[k] = 1 / std::max(node.r2[k], 1e-20f);
        node.phi[k] = l.phi;
        node.wx[k] = l.w.x, node.wy[k] = l.w.y, node.wz[k] = l.w.z;
        node.cos_o[k] = l.cos_theta_o;
        node.sin_o[k] = std::sqrt(std::max(0.0f, 1 - l.cos_theta_o * l.cos_theta_o));
        node.cos_e[k] = l.cos_theta_e;
        node.two_sided[k] = l.two_sided ? 0x80000000u : 0u;
        const uint64_t t = trail | (uint64_t(k) << (kLevels * depth));
        if (s.leaf) {
            node.child[k] = s.index;
            node.leaf_mask |= 1u << k;
            m_trail[s.index] = t;
        } else {
            node.child[k] = collapse(slots[k], depth + 1, t);
        }
    }
    m_nodes[index] = node;
    return index;
}

void LightBvh::child_importance(uint32_t node, Vec3 p, Vec3 n, float out[kWidth]) const {
    alignas(16) float imp[kWidth];
    weigh(m_nodes[node], p, n, has_normal(n), imp);
    std::copy(imp, imp + kWidth, out);
}

std::optional<std::pair<uint32_t, float>> LightBvh::sample(Vec3 p, Vec3 n, float u) const {
    if (m_nodes.empty()) return std::nullopt;
    const bool has_n = has_normal(n);
    uint32_t i = 0;
    float pmf = 1;
    for (;;) {
        const Node& node = m_nodes[i];
        alignas(16) float imp[kWidth];
        const float sum = weigh(node, p, n, has_n, imp);
        if (!(sum > 0)) return std::nullopt;
        // The slot whose share of sum holds u * sum; never one of importance 0, even when
        // rounding leaves the running remainder past the last positive one.
        float rest = u * sum;
        int k = 0, last = -1;
        for (; k < kWidth; ++k) {
            if (!(imp[k] > 0)) continue;
            last = k;
            if (rest < imp[k]) break;
            rest -= imp[k];
        }
        if (k == kWidth) k = last, rest = imp[k] * kOneMinusEpsilon;
        pmf *= imp[k] / sum;  // as pmf() computes it
        // Reuse u for the rest of the descent, rescaled into the chosen interval.
        u = std::min(rest / imp[k], kOneMinusEpsilon);
        if (node.leaf_mask >> k & 1) return std::pair{node.child[k], pmf};
        i = node.child[k];
    }
}

float LightBvh::pmf(Vec3 p, Vec3 n, uint32_t light) const {
    if (light >= m_trail.size() || m_trail[light] == kNotInTree) return 0;
    const bool has_n = has_normal(n);
    uint64_t trail = m_trail[light];
    uint32_t i = 0;
    float pmf = 1;
    for (;;) {
        const Node& node = m_nodes[i];
        alignas(16) float imp[kWidth];
        const float sum = weigh(node, p, n, has_n, imp);
        const int k = int(trail & (kWidth - 1));
        if (!(sum > 0) || !(imp[k] > 0)) return 0;
        pmf *= imp[k] / sum;
        if (node.leaf_mask >> k & 1) return pmf;
        i = node.child[k];
        trail >>= kLevels;
    }
}

}  // namespace penumbra
