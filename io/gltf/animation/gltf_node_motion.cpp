#include "io/gltf/animation/gltf_node_motion.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// glTF's T * R * S in double, without an inverse (a zero scale is allowed here: a joint
// or parent may hide its subtree for a while).
Mat4 pose_matrix(const NodePose& p) {
    double q[4] = {p.r[0], p.r[1], p.r[2], p.r[3]};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c = n > 0 ? c / n : 0;
    if (!(n > 0)) q[3] = 1;
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Mat4 m = Mat4::identity();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m(i, j) = float(r[i][j] * p.s[j]);
        m(i, 3) = float(p.t[i]);
    }
    return m;
}

bool same(const Mat4& a, const Mat4& b) { return a.m == b.m; }

// Rotation angle between two unit quaternions (either sign is the same rotation).
double angle_between(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (int i = 0; i < 4; ++i) d += a[size_t(i)] * b[size_t(i)];
    return 2 * std::acos(std::min(1.0, std::abs(d)));
}

}  // namespace

NodePose rest_pose(const tinygltf::Node& node) {
    NodePose p;
    for (size_t i = 0; i < 3 && node.translation.size() == 3; ++i) p.t[i] = node.translation[i];
    for (size_t i = 0; i < 4 && node.rotation.size() == 4; ++i) p.r[i] = node.rotation[i];
    for (size_t i = 0; i < 3 && node.scale.size() == 3; ++i) p.s[i] = node.scale[i];
    return p;
}

NodeMotion::NodeMotion(const GltfContext& ctx, const GltfAnimations& animations, Shutter shutter)
    : m_ctx(ctx), m_animations(animations), m_shutter(shutter) {
    const auto& nodes = ctx.model.nodes;
    const size_t n = nodes.size();
    m_parent.assign(n, -1);
    m_rest.resize(n);
    for (size_t i = 0; i < n; ++i) {
        m_rest[i] = rest_pose(nodes[i]);
        // A node with two parents or a cycle is reported by the scene traversal; here
        // the first parent is kept.
        for (int c : nodes[i].children)
            if (c >= 0 && size_t(c) < n && m_parent[size_t(c)] < 0 && size_t(c) != i)
                m_parent[size_t(c)] = int(i);
    }
    m_chain_animated.assign(n, false);
    if (animations.empty()) return;
    // 0: unknown, 1: no, 2: yes; each node is settled once, walking up to a settled one.
    std::vector<uint8_t> state(n, 0);
    std::vector<int> walk;
    for (size_t i = 0; i < n; ++i) {
        walk.clear();
        int v = int(i);
        uint8_t result = 1;
        while (v >= 0 && state[size_t(v)] == 0 && walk.size() <= n) {
            const NodeChannels* nc = animations.node(v);
            if (nc && nc->animates_transform()) {
                result = 2;
                break;
            }
            walk.push_back(v);
            v = m_parent[size_t(v)];
        }
        if (v >= 0 && state[size_t(v)] != 0) result = state[size_t(v)];
        if (v >= 0 && result == 2) state[size_t(v)] = 2;
        for (int w : walk) state[size_t(w)] = result;
    }
    for (size_t i = 0; i < n; ++i) m_chain_animated[i] = state[i] == 2;
}

Mat4 NodeMotion::local(int node, double t) const {
    const tinygltf::Node& gn = m_ctx.model.nodes[size_t(node)];
    const NodeChannels* nc = m_animations.node(node);
    if (nc && nc->animates_transform())
        return pose_matrix(m_animations.pose(node, m_rest[size_t(node)], t));
    if (gn.matrix.size() == 16) return Mat4::from_column_major(gn.matrix.data());
    return pose_matrix(m_rest[size_t(node)]);
}

Mat4 NodeMotion::world(int node, double t) const {
    std::vector<int> chain;
    for (int v = node; v >= 0; v = m_parent[size_t(v)]) {
        if (chain.size() > m_parent.size())
            m_ctx.fail(element("nodes", size_t(node)), "is its own ancestor (a node cycle)");
        chain.push_back(v);
    }
    Mat4 m = local(chain.back(), t);
    for (size_t i = chain.size() - 1; i-- > 0;) m = m * local(chain[i], t);
    return m;
}

std::vector<const AnimationCurve*> NodeMotion::chain_curves(int node) const {
    std::vector<const AnimationCurve*> curves;
    // At most one pass over all nodes: a parent cycle outside the scene tree must not
    // loop forever (world() reports it).
    size_t visited = 0;
    for (int v = node; v >= 0 && visited++ <= m_parent.size(); v = m_parent[size_t(v)])
        if (const NodeChannels* nc = m_animations.node(v))
            for (const AnimationCurve* c : {nc->translation, nc->rotation, nc->scale})
                if (c) curves.push_back(c);
    return curves;
}

int NodeMotion::steps(const std::vector<const AnimationCurve*>& curves) const {
    if (m_shutter.still()) return 1;
    const double a = m_shutter.open, b = m_shutter.close, duration = b - a;
    double segments = 0, angle = 0;
    for (const AnimationCurve* c : curves) {
        const std::vector<double>& t = c->times;
        // Clamped outside its keys, a curve is constant there.
        if (t.size() < 2 || b <= t.front() || a >= t.back()) continue;
        // The key intervals the shutter overlaps, first to last; at least one step per
        // interval (four for CUBICSPLINE, whose curve bends inside it).
        const size_t first = size_t(std::max<std::ptrdiff_t>(
            0, std::upper_bound(t.begin(), t.end(), a) - t.begin() - 1));
        const size_t last = size_t(std::lower_bound(t.begin(), t.end(), b) - t.begin() - 1);
        double shortest = t.back() - t.front();
        for (size_t k = first; k <= last && k + 1 < t.size(); ++k)
            shortest = std::min(shortest, t[k + 1] - t[k]);
        const double per_interval = c->interpolation == Interpolation::CubicSpline ? 4 : 1;
        // Key times are floats: 0.1f steps are not exactly 0.1 apart, hence the margin.
        segments = std::max(segments, std::ceil(duration * per_interval / shortest * (1 - 1e-6)));
        if (c->quaternion) {
            // The angle swept inside the shutter: through every key inside it (slerp is
            // exact between keys) and 16 points across it for CUBICSPLINE.
            std::vector<double> when = {a, b};
            for (size_t k = first; k <= last + 1 && k < t.size(); ++k)
                if (t[k] > a && t[k] < b) when.push_back(t[k]);
            if (c->interpolation == Interpolation::CubicSpline)
                for (int i = 1; i < 16; ++i) when.push_back(a + duration * i / 16);
            std::sort(when.begin(), when.end());
            for (size_t i = 0; i + 1 < when.size(); ++i)
                angle += angle_between(c->sample(when[i]), c->sample(when[i + 1]));
        }
    }
    if (segments == 0) return 1;
    segments = std::max(segments, std::ceil(angle / kMaxStepRotation * (1 - 1e-6)));
    return int(std::min<double>(segments, kMaxTimeSteps - 1)) + 1;
}

std::vector<Transform> NodeMotion::world_motion(int node) const {
    if (m_shutter.still() || !moves(node)) return {};
    const int k_steps = steps(chain_curves(node));
    if (k_steps < 2) return {};
    std::vector<Mat4> m;
    bool changes = false;
    for (int k = 0; k < k_steps; ++k) {
        m.push_back(world(node, m_shutter.time(k, k_steps)));
        changes = changes || !same(m.back(), m.front());
    }
    if (!changes) return {};
    std::vector<Transform> out;
    for (const Mat4& x : m) out.emplace_back(x);
    return out;
}

}  // namespace penumbra
