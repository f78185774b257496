// Internal to io/: node transforms over the shutter. Knows every node's parent, rest
// pose and animation channels, evaluates local and world matrices at any time, and
// chooses how many time steps a moving node needs (the rule is in docs/conventions.md).
#pragma once

#include <vector>

#include "core/math/transform.h"
#include "io/gltf/animation/gltf_animation.h"
#include "io/gltf/gltf_context.h"

namespace penumbra {

// The exposure interval in animation seconds; open == close is a still.
struct Shutter {
    double open = 0, close = 0;
    bool still() const { return !(close > open); }
    // Animation time of step k of `steps` (normalized shutter time k / (steps - 1)).
    double time(int k, int steps) const {
        return steps < 2 ? open : open + (close - open) * double(k) / double(steps - 1);
    }
};

// Most time steps given to one instance, camera or deforming mesh (64 intervals).
constexpr int kMaxTimeSteps = 65;
// At most this much rotation (radians, 10 degrees) between two time steps: between
// steps, positions are interpolated linearly, so a point orbiting a moved pivot cuts its
// arc's chord (sagitta r (1 - cos 5deg) = 0.4% of the radius).
constexpr double kMaxStepRotation = 0.17453292519943295;

class NodeMotion {
public:
    // Validates the node graph's parent links (a node reachable from itself fails).
    NodeMotion(const GltfContext& ctx, const GltfAnimations& animations, Shutter shutter);

    const Shutter& shutter() const { return m_shutter; }
    const GltfAnimations& animations() const { return m_animations; }
    // True when the node or one of its ancestors has translation/rotation/scale channels.
    bool moves(int node) const { return m_chain_animated[size_t(node)]; }
    int parent(int node) const { return m_parent[size_t(node)]; }

    // The node's local matrix at time t: its animated pose, else its matrix or TRS.
    Mat4 local(int node, double t) const;
    // Product of the local matrices from the root down to the node (may be singular).
    Mat4 world(int node, double t) const;

    // Time steps for curves that drive one moving thing: 1 (no motion) for a still
    // shutter or when none of them changes inside it, else 2 .. kMaxTimeSteps.
    int steps(const std::vector<const AnimationCurve*>& curves) const;
    // The transform curves of the node and its ancestors.
    std::vector<const AnimationCurve*> chain_curves(int node) const;
    // World transforms of the node at the chosen time steps; empty when the node does not
    // move within the shutter. Throws std::invalid_argument when one is singular.
    std::vector<Transform> world_motion(int node) const;

private:
    const GltfContext& m_ctx;
    const GltfAnimations& m_animations;
    Shutter m_shutter;
    std::vector<int> m_parent;
    std::vector<bool> m_chain_animated;
    std::vector<NodePose> m_rest;
};

// The node's own translation, rotation and scale (identity where absent).
NodePose rest_pose(const tinygltf::Node& node);

}  // namespace penumbra
