#include "core/accel/bvh_build.h"

#include <gtest/gtest.h>

#include <functional>

#include "core/accel/object_triangles.h"
#include "core/sampling/rng.h"
#include "support/accel_scenes.h"

namespace penumbra {
namespace {

const BvhSplit kSplits[] = {BvhSplit::Sah, BvhSplit::Median, BvhSplit::Center};

std::vector<Bounds3> triangle_boxes(const ObjectTriangles& t) {
    std::vector<Bounds3> b(t.size());
    for (size_t i = 0; i < b.size(); ++i) b[i] = t.triangle_bounds(i);
    return b;
}

std::vector<Bounds3> random_soup(size_t n, uint64_t seed) {
    Rng rng(seed);
    std::vector<Bounds3> b(n);
    for (Bounds3& box : b) {
        // Clustered: most boxes in a corner, a few spread out (uneven on purpose).
        const float s = rng.next_float() < 0.9f ? 0.1f : 10.0f;
        const Vec3 p(s * rng.next_float(), s * rng.next_float(), s * rng.next_float());
        box.expand(p);
        box.expand(p + Vec3(0.01f * rng.next_float(), 0.01f, 0.01f * rng.next_float()));
    }
    return b;
}

// Every primitive in exactly one leaf, every box containing its subtree, leaves within
// their size limits, the depth as reported.
void check_tree(const BvhTree& tree, const std::vector<Bounds3>& prims, BvhSplit split) {
    ASSERT_FALSE(tree.nodes.empty());
    std::vector<int> seen(prims.size(), 0);
    int max_depth = 0;
    std::function<Bounds3(uint32_t, int)> visit = [&](uint32_t i, int depth) {
        const BvhNode& n = tree.nodes[i];
        max_depth = std::max(max_depth, depth);
        Bounds3 b;
        if (n.is_leaf()) {
            EXPECT_LE(n.count, kMaxLeafSize);
            for (uint32_t k = n.offset; k < n.offset + n.count; ++k) {
                ++seen[tree.order[k]];
                b.expand(prims[tree.order[k]]);
            }
        } else {
            EXPECT_GT(n.offset, i + 1);
            b.expand(visit(i + 1, depth + 1));
            b.expand(visit(n.offset, depth + 1));
        }
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(n.lo[a], b.lo[a]);  // exactly the union: min/max are exact
            EXPECT_EQ(n.hi[a], b.hi[a]);
        }
        return b;
    };
    visit(0, 0);
    for (size_t i = 0; i < prims.size(); ++i) EXPECT_EQ(seen[i], 1) << "primitive " << i;
    EXPECT_EQ(max_depth, tree.depth);
    EXPECT_LT(tree.depth, kBvhStackSize);
    if (split == BvhSplit::Median)  // balanced: leaves of <= 4 after log2(n / 4) levels
        EXPECT_LE(tree.depth, int(std::ceil(std::log2(double(prims.size())))));
}

TEST(BvhBuild, TreesAreWellFormed) {
    const ObjectTriangles sphere = [] {
        Scene s;
        test::add_sphere_object(s, Vec3(0.0f), 1, 64, 32);
        return gather_object_triangles(s, s.objects[0]);
    }();
    for (const auto& prims : {triangle_boxes(sphere), random_soup(5000, 1)})
        for (BvhSplit split : kSplits) {
            SCOPED_TRACE(bvh_split_name(split));
            check_tree(build_bvh(prims, split), prims, split);
        }
}

TEST(BvhBuild, DegenerateInputs) {
    // No primitives: an empty tree. One: a single leaf.
    EXPECT_TRUE(build_bvh({}, BvhSplit::Sah).nodes.empty());
    Bounds3 point;
    point.expand(Vec3(1, 2, 3));
    for (BvhSplit split : kSplits) {
        const BvhTree one = build_bvh({point}, split);
        ASSERT_EQ(one.nodes.size(), 1u);
        EXPECT_EQ(one.nodes[0].count, 1);
        // 1000 boxes with the same centroid cannot be separated by a plane: they are
        // halved by count until the leaves are small enough.
        const std::vector<Bounds3> same(1000, point);
        check_tree(build_bvh(same, split), same, split);
    }
}

// The SAH tree must have a lower expected cost than the center and median trees on
// every test mesh (it minimizes that cost greedily; the others ignore it).
TEST(BvhBuild, SahTreeIsCheaperThanCenterAndMedian) {
    std::vector<std::pair<std::string, std::vector<Bounds3>>> inputs;
    {
        Scene s;
        test::add_sphere_object(s, Vec3(0.0f), 1, 128, 64);
        inputs.emplace_back("sphere", triangle_boxes(gather_object_triangles(s, s.objects[0])));
    }
    inputs.emplace_back("clustered soup", random_soup(20000, 2));
    const Scene& cb = test::cornell_box();
    for (size_t o = 0; o < cb.objects.size(); ++o)
        inputs.emplace_back("cornell-box object " + std::to_string(o),
                            triangle_boxes(gather_object_triangles(cb, cb.objects[o])));
    for (const auto& [path, scene] : test::khronos_scenes())
        for (size_t o = 0; o < scene.objects.size(); ++o)
            inputs.emplace_back(path + " object " + std::to_string(o),
                                triangle_boxes(gather_object_triangles(scene, scene.objects[o])));
    int compared = 0;
    for (const auto& [name, prims] : inputs) {
        // Up to kMaxLeafSize primitives SAH may keep one leaf; nothing to compare.
        if (prims.size() <= kMaxLeafSize) continue;
        const double sah = sah_cost(build_bvh(prims, BvhSplit::Sah));
        const double median = sah_cost(build_bvh(prims, BvhSplit::Median));
        const double center = sah_cost(build_bvh(prims, BvhSplit::Center));
        EXPECT_LT(sah, median) << name;
        EXPECT_LT(sah, center) << name;
        ++compared;
    }
    EXPECT_GE(compared, 5);
}

TEST(BvhBuild, SahCostOfKnownTrees) {
    // Two unit boxes side by side: one interior node (P = 1) and two leaves of one box,
    // each with area 6 of the root's 10.
    Bounds3 a, b;
    a.expand(Vec3(0, 0, 0));
    a.expand(Vec3(1, 1, 1));
    b.expand(Vec3(1, 0, 0));
    b.expand(Vec3(2, 1, 1));
    for (BvhSplit split : {BvhSplit::Median, BvhSplit::Center}) {
        const BvhTree t = build_bvh({a, b}, split);
        ASSERT_EQ(t.nodes.size(), 1u);  // <= kSplitLeafSize: one leaf of two
        EXPECT_DOUBLE_EQ(sah_cost(t), 2 * kSahIntersectionCost);
    }
    std::vector<Bounds3> far = {a, b};
    for (int i = 0; i < 4; ++i) {
        Bounds3 c = a;
        c.lo += Vec3(100.0f + i, 0, 0);
        c.hi += Vec3(100.0f + i, 0, 0);
        far.push_back(c);
    }
    // Two clusters 100 apart: the center split separates them at the root, and each
    // side (2 and 4 boxes) is small enough to be a leaf.
    const BvhTree t = build_bvh(far, BvhSplit::Center);
    ASSERT_EQ(t.nodes.size(), 3u);
    const double root = 2 * (104.0 * 1 + 1 * 1 + 1 * 104.0);
    const double expected =
        kSahTraversalCost + kSahIntersectionCost * (2 * 10.0 / root + 4 * 18.0 / root);
    EXPECT_NEAR(sah_cost(t), expected, 1e-6 * expected);
    EXPECT_LE(sah_cost(build_bvh(far, BvhSplit::Sah)), expected);
}

}  // namespace
}  // namespace penumbra
