// glTF animations: samplers (key times and values) and the channels that drive node
// translation, rotation, scale and morph-target weights, and through KHR_animation_pointer
// node visibility and material, light and camera properties; validated at load and
// sampled at any time exactly as glTF 2.0, Appendix C specifies.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/math/transform.h"
#include "io/gltf/animation/gltf_pointer.h"

namespace penumbra {

struct GltfContext;

enum class Interpolation { Step, Linear, CubicSpline };

// One animation sampler as a curve over time. `values` holds `width` numbers per key;
// CUBICSPLINE keys hold three groups each (in-tangent, value, out-tangent), as the file
// stores them.
struct AnimationCurve {
    std::vector<double> times;  // seconds, strictly increasing, first >= 0
    std::vector<double> values;
    size_t width = 0;           // 3 (translation, scale), 4 (rotation), targets (weights)
    Interpolation interpolation = Interpolation::Linear;
    bool quaternion = false;    // rotation (x, y, z, w): slerp, and normalized results

    // The value at time t into out[0, width): the first key's before it, the last key's
    // after it (Appendix C clamps), else interpolated in the key interval holding t.
    void sample(double t, double* out) const;
    std::vector<double> sample(double t) const;
};

// The animated properties of one node; nullptr where a property is not animated.
struct NodeChannels {
    const AnimationCurve* translation = nullptr;
    const AnimationCurve* rotation = nullptr;
    const AnimationCurve* scale = nullptr;
    const AnimationCurve* weights = nullptr;
    const AnimationCurve* visible = nullptr;  // KHR_node_visibility: nonzero is visible

    bool animates_transform() const { return translation || rotation || scale; }
};

// A KHR_animation_pointer channel on a material, light or camera property: the pointer
// below the object (gltf_pointer.h) and the curve of its values.
struct PropertyChannel {
    std::string property;
    size_t width = 1;
    const AnimationCurve* curve = nullptr;
    std::string channel;  // "animations[a].channels[c]", for messages
};

// Translation, rotation (unit quaternion, glTF's x y z w) and scale, in double.
struct NodePose {
    double t[3] = {0, 0, 0};
    double r[4] = {0, 0, 0, 1};
    double s[3] = {1, 1, 1};

    Transform transform() const;  // T * R * S; throws std::invalid_argument for zero scale
};

// Every animation of a file, played together on one timeline starting at 0 s. A node
// property animated by two animations takes the first one's channel (one warning per file
// counts them).
class GltfAnimations {
public:
    GltfAnimations() = default;
    // Reads and validates ctx.model.animations; throws SceneError
    // "<file>: animations[i].samplers[j]: <problem>" (or .channels[j]).
    explicit GltfAnimations(const GltfContext& ctx);

    bool empty() const { return m_curves.empty(); }
    // The node's channels; nullptr when no channel targets it.
    const NodeChannels* node(int index) const;
    // The animated properties of material, light or camera `index` (not Node: node()).
    const std::vector<PropertyChannel>& properties(PointerObject object, int index) const;
    // The node's pose at time t: its translation/rotation/scale with the animated ones
    // replaced by their samples. `rest` is the node's own TRS.
    NodePose pose(int index, const NodePose& rest, double t) const;

    // Channels point into m_curves: moving keeps them valid, copying would not.
    GltfAnimations(GltfAnimations&&) = default;
    GltfAnimations& operator=(GltfAnimations&&) = default;
    GltfAnimations(const GltfAnimations&) = delete;
    GltfAnimations& operator=(const GltfAnimations&) = delete;

private:
    void add_property_channel(PointerObject object, int index, PropertyChannel ch,
                              size_t animation, std::map<const void*, size_t>& used,
                              std::vector<std::string>& overlapping);

    std::vector<AnimationCurve> m_curves;
    std::vector<NodeChannels> m_nodes;  // per glTF node; empty when nothing is animated
    // Per PointerObject (Node unused), per object index: its animated properties.
    std::vector<std::vector<PropertyChannel>> m_properties[4];
};

// Reads the animations of the glTF file at path (for tests and tools); throws SceneError.
GltfAnimations load_gltf_animations(const std::string& path);

}  // namespace penumbra
