// Internal to io/: KHR_node_visibility. A node is shown when its own `visible` (default
// true, animated through KHR_animation_pointer) and every ancestor's are true; a hidden
// node hides its mesh and its KHR_lights_punctual light, never its camera. Evaluated
// over the shutter as the times at which that flips.
#pragma once

#include <vector>

#include "core/scene/scene.h"
#include "io/gltf/animation/gltf_node_motion.h"

namespace penumbra {

class NodeVisibility {
public:
    // Reads every node's flag (a non-boolean `visible` is an error naming the node).
    NodeVisibility(const GltfContext& ctx, const NodeMotion& motion);

    // The node's visibility over the shutter, its ancestors' included.
    TimedVisibility over_shutter(int node) const;
    // Whether the node's visibility is true at animation time t.
    bool at(int node, double t) const;
    // Whether any node can be hidden (the file uses the extension).
    bool any_hidden() const { return m_any; }

private:
    const NodeMotion& m_motion;
    std::vector<signed char> m_static;                  // 1 visible, 0 hidden
    std::vector<const AnimationCurve*> m_curves;        // animated flags; may be null
    bool m_any = false;
};

}  // namespace penumbra
