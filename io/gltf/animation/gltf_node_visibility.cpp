#include "io/gltf/animation/gltf_node_visibility.h"

#include <algorithm>

namespace penumbra {

NodeVisibility::NodeVisibility(const GltfContext& ctx, const NodeMotion& motion)
    : m_motion(motion) {
    const tinygltf::Model& m = ctx.model;
    m_static.assign(m.nodes.size(), 1);
    m_curves.assign(m.nodes.size(), nullptr);
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        const auto it = m.nodes[i].extensions.find("KHR_node_visibility");
        if (it != m.nodes[i].extensions.end() && it->second.Has("visible")) {
            const tinygltf::Value& v = it->second.Get("visible");
            if (!v.IsBool())
                ctx.fail(element("nodes", i), "extensions.KHR_node_visibility.visible must be a boolean");
            m_static[i] = v.Get<bool>() ? 1 : 0;
            m_any = m_any || !v.Get<bool>();
        }
        const NodeChannels* nc = motion.animations().node(int(i));
        if (nc && nc->visible) {
            m_curves[i] = nc->visible;
            m_any = true;
        }
    }
}

bool NodeVisibility::at(int node, double t) const {
    if (!m_any) return true;
    // At most one step per node: a cycle in the parent links is reported by the scene
    // traversal, not here.
    size_t steps = 0;
    for (int n = node; n >= 0 && steps++ < m_static.size(); n = m_motion.parent(n)) {
        const AnimationCurve* c = m_curves[size_t(n)];
        double v = m_static[size_t(n)];
        if (c) c->sample(t, &v);
        if (v == 0) return false;
    }
    return true;
}

TimedVisibility NodeVisibility::over_shutter(int node) const {
    const Shutter& s = m_motion.shutter();
    TimedVisibility out;
    out.at_open = at(node, s.open);
    if (!m_any || s.still()) return out;
    // STEP curves change only at their keys: the chain's keys inside the shutter.
    std::vector<double> keys;
    size_t steps = 0;
    for (int n = node; n >= 0 && steps++ < m_static.size(); n = m_motion.parent(n))
        if (const AnimationCurve* c = m_curves[size_t(n)])
            for (double k : c->times)
                if (k > s.open && k < s.close) keys.push_back(k);
    std::sort(keys.begin(), keys.end());
    bool current = out.at_open;
    for (double k : keys) {
        if (at(node, k) == current) continue;
        current = !current;
        out.flips.push_back(float((k - s.open) / (s.close - s.open)));
    }
    return out;
}

}  // namespace penumbra
