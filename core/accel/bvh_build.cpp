#include "core/accel/bvh_build.h"

#include <algorithm>
#include <limits>

#include "core/error.h"

namespace penumbra {

std::string bvh_split_name(BvhSplit split) {
    switch (split) {
        case BvhSplit::Sah:
            return "sah";
        case BvhSplit::Median:
            return "median";
        case BvhSplit::Center:
            return "center";
    }
    return "?";
}

namespace {

struct BuildPrim {
    Vec3 lo;
    uint32_t index;
    Vec3 hi;
    float pad;
    // Twice the centroid: the factor 1/2 changes no comparison, so it is never applied.
    float centroid(int axis) const { return lo[axis] + hi[axis]; }
};

struct Bin {
    Bounds3 bounds;
    uint32_t count = 0;
};

struct Split {
    uint32_t mid = 0;  // begin: make a leaf
    int axis = 0;
};

class Builder {
public:
    Builder(std::vector<BuildPrim>& prims, BvhSplit split, BvhTree& tree)
        : m_prims(prims), m_split(split), m_tree(tree) {}

    uint32_t build(uint32_t begin, uint32_t end, int depth) {
        const uint32_t index = static_cast<uint32_t>(m_tree.nodes.size());
        m_tree.nodes.emplace_back();
        m_tree.depth = std::max(m_tree.depth, depth);
        Bounds3 bounds, centroids;
        for (uint32_t i = begin; i < end; ++i) {
            const BuildPrim& p = m_prims[i];
            bounds.lo = min(bounds.lo, p.lo);
            bounds.hi = max(bounds.hi, p.hi);
            centroids.expand(p.lo + p.hi);
        }
        for (int a = 0; a < 3; ++a) {
            m_tree.nodes[index].lo[a] = bounds.lo[a];
            m_tree.nodes[index].hi[a] = bounds.hi[a];
        }
        const Split s = choose_split(begin, end, bounds, centroids, depth);
        if (s.mid == begin) {
            BvhNode& n = m_tree.nodes[index];
            n.offset = begin;
            n.count = static_cast<uint16_t>(end - begin);
            n.axis = 0;
            return index;
        }
        build(begin, s.mid, depth + 1);
        const uint32_t right = build(s.mid, end, depth + 1);
        BvhNode& n = m_tree.nodes[index];  // the vector may have grown: look it up again
        n.offset = right;
        n.count = 0;
        n.axis = static_cast<uint8_t>(s.axis);
        return index;
    }

private:
    Split choose_split(uint32_t begin, uint32_t end, const Bounds3& bounds,
                       const Bounds3& centroids, int depth) {
        const uint32_t n = end - begin;
        const Vec3 extent = centroids.diagonal();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        if (n <= 1) return {begin, 0};
        if (!(extent[axis] > 0)) {
            // All centroids coincide: no plane separates them and every division costs
            // the same, so halve by count only when the leaf would be too large.
            if (n <= kMaxLeafSize) return {begin, 0};
            return {begin + n / 2, axis};
        }
        const BvhSplit mode = depth >= kMedianBelowDepth ? BvhSplit::Median : m_split;
        if (mode == BvhSplit::Sah) return split_sah(begin, end, bounds, centroids);
        if (n <= kSplitLeafSize) return {begin, 0};
        if (mode == BvhSplit::Center) {
            const float plane = 0.5f * (centroids.lo[axis] + centroids.hi[axis]);
            const auto it =
                std::partition(m_prims.begin() + begin, m_prims.begin() + end,
                               [&](const BuildPrim& p) { return p.centroid(axis) < plane; });
            const uint32_t mid = static_cast<uint32_t>(it - m_prims.begin());
            // The plane can round onto the smallest centroid; fall back to the median.
            if (mid != begin && mid != end) return {mid, axis};
        }
        const uint32_t mid = begin + n / 2;
        std::nth_element(m_prims.begin() + begin, m_prims.begin() + mid, m_prims.begin() + end,
                         [&](const BuildPrim& a, const BuildPrim& b) {
                             return a.centroid(axis) < b.centroid(axis);
                         });
        return {mid, axis};
    }

    // Binned SAH (Wald 2007): centroids are binned along each axis, and the bin
    // boundaries are the candidate planes; the boxes of the bins give both children's
    // areas in one sweep from each side.
    Split split_sah(uint32_t begin, uint32_t end, const Bounds3& bounds, const Bounds3& centroids) {
        const uint32_t n = end - begin;
        Bin bins[3][kSahBins];
        float scale[3];
        for (int a = 0; a < 3; ++a) {
            const float extent = centroids.hi[a] - centroids.lo[a];
            scale[a] = extent > 0 ? kSahBins / extent : 0;
        }
        for (uint32_t i = begin; i < end; ++i) {
            const BuildPrim& p = m_prims[i];
            for (int a = 0; a < 3; ++a) {
                if (scale[a] == 0) continue;
                Bin& bin = bins[a][bin_index(p, a, centroids.lo[a], scale[a])];
                ++bin.count;
                bin.bounds.lo = min(bin.bounds.lo, p.lo);
                bin.bounds.hi = max(bin.bounds.hi, p.hi);
            }
        }
        const float inv_area = 1.0f / std::max(surface_area(bounds), 1e-30f);
        float best_cost = std::numeric_limits<float>::infinity();
        int best_axis = -1, best_bin = 0;
        for (int a = 0; a < 3; ++a) {
            if (scale[a] == 0) continue;
            // right_cost[s]: area * count of bins s .. end, for the plane before bin s.
            float right_cost[kSahBins];
            Bounds3 acc;
            uint32_t count = 0;
            for (int s = kSahBins - 1; s > 0; --s) {
                acc.expand(bins[a][s].bounds);
                count += bins[a][s].count;
                right_cost[s] = count ? surface_area(acc) * count : -1.0f;
            }
            acc = Bounds3();
            count = 0;
            for (int s = 1; s < kSahBins; ++s) {
                acc.expand(bins[a][s - 1].bounds);
                count += bins[a][s - 1].count;
                if (count == 0 || right_cost[s] < 0) continue;
                const float cost =
                    kSahTraversalCost +
                    kSahIntersectionCost * inv_area * (surface_area(acc) * count + right_cost[s]);
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = a;
                    best_bin = s;
                }
            }
        }
        // A non-zero centroid extent puts the extreme centroids in the first and last
        // bins, so a plane with primitives on both sides always exists.
        CHECK(best_axis >= 0, "binned SAH found no split for " << n << " primitives");
        if (n <= kMaxLeafSize && kSahIntersectionCost * n <= best_cost) return {begin, 0};
        const float lo = centroids.lo[best_axis], sc = scale[best_axis];
        const auto it = std::partition(
            m_prims.begin() + begin, m_prims.begin() + end,
            [&](const BuildPrim& p) { return bin_index(p, best_axis, lo, sc) < best_bin; });
        return {static_cast<uint32_t>(it - m_prims.begin()), best_axis};
    }

    static int bin_index(const BuildPrim& p, int axis, float lo, float scale) {
        const int k = static_cast<int>((p.centroid(axis) - lo) * scale);
        return std::min(std::max(k, 0), kSahBins - 1);
    }

    std::vector<BuildPrim>& m_prims;
    BvhSplit m_split;
    BvhTree& m_tree;
};

}  // namespace

BvhTree build_bvh(const std::vector<Bounds3>& prim_bounds, BvhSplit split) {
    BvhTree tree;
    if (prim_bounds.empty()) return tree;
    CHECK(prim_bounds.size() < (1ull << 32), "too many primitives for one BVH");
    std::vector<BuildPrim> prims(prim_bounds.size());
    for (size_t i = 0; i < prims.size(); ++i) {
        CHECK(!prim_bounds[i].empty(), "primitive " << i << " has an empty box");
        prims[i].lo = prim_bounds[i].lo;
        prims[i].hi = prim_bounds[i].hi;
        prims[i].index = static_cast<uint32_t>(i);
    }
    // A binary tree with leaves of >= 1 primitive has fewer than 2N nodes.
    tree.nodes.reserve(2 * prims.size());
    Builder(prims, split, tree).build(0, static_cast<uint32_t>(prims.size()), 0);
    CHECK(tree.depth < kBvhStackSize, "BVH depth " << tree.depth << " exceeds the stack");
    tree.nodes.shrink_to_fit();
    tree.order.resize(prims.size());
    for (size_t i = 0; i < prims.size(); ++i) tree.order[i] = prims[i].index;
    return tree;
}

double sah_cost(const BvhTree& tree) {
    if (tree.nodes.empty()) return 0;
    const BvhNode& root = tree.nodes[0];
    auto area = [](const BvhNode& n) {
        Bounds3 b;
        b.lo = {n.lo[0], n.lo[1], n.lo[2]};
        b.hi = {n.hi[0], n.hi[1], n.hi[2]};
        return double(surface_area(b));
    };
    const double root_area = area(root);
    if (!(root_area > 0)) return kSahIntersectionCost * tree.order.size();
    double cost = 0;
    for (const BvhNode& n : tree.nodes)
        cost += area(n) / root_area *
                (n.is_leaf() ? kSahIntersectionCost * n.count : kSahTraversalCost);
    return cost;
}

}  // namespace penumbra
