#include "io/gltf/animation/gltf_animation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "io/gltf/gltf_accessor.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/gltf_parse.h"
#include "io/gltf/animation/gltf_pointer.h"
#include "core/math/portable_math.h"

namespace penumbra {

namespace {

// What a channel drives: a node's transform, morph weights or visibility (through
// KHR_animation_pointer), or another object's property (PropertyChannel).
enum class Path { Translation, Rotation, Scale, Weights, Visible, Property };

// Spherical linear interpolation along the shorter arc, glTF 2.0 Appendix C:
// a = acos(|q0.q1|), q = sin(a(1-s))/sin(a) q0 + sign(q0.q1) sin(a s)/sin(a) q1.
void slerp(const double* q0, const double* q1, double s, double* out) {
    double d = 0;
    for (int i = 0; i < 4; ++i) d += q0[i] * q1[i];
    const double sign = d < 0 ? -1.0 : 1.0;
    const double a = std::acos(std::min(1.0, std::abs(d)));
    double w0 = 1 - s, w1 = sign * s;
    // Nearly equal keys: sin(a) -> 0, and the weights tend to those of a lerp.
    if (portable_sin(a) > 1e-9) {
        w0 = portable_sin(a * (1 - s)) / portable_sin(a);
        w1 = sign * portable_sin(a * s) / portable_sin(a);
    }
    double len2 = 0;
    for (int i = 0; i < 4; ++i) {
        out[i] = w0 * q0[i] + w1 * q1[i];
        len2 += out[i] * out[i];
    }
    // Exact slerp of unit quaternions is unit; this removes the lerp fallback's error.
    const double inv = 1 / std::sqrt(len2);
    for (int i = 0; i < 4; ++i) out[i] *= inv;
}

void normalize4(double* q) {
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (len > 0)
        for (int i = 0; i < 4; ++i) q[i] /= len;
}

const char* path_name(Path p) {
    static const char* const names[] = {"translation", "rotation", "scale",
                                        "weights",     "visible",  "property"};
    return names[int(p)];
}

bool is_normalized_int(const tinygltf::Accessor& a) {
    return a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                            a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                            a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
                            a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
}

// The number of morph targets of the node's mesh (glTF requires every primitive of a
// mesh to have the same number).
size_t target_count(const GltfContext& ctx, const tinygltf::Node& node) {
    if (node.mesh < 0 || size_t(node.mesh) >= ctx.model.meshes.size()) return 0;
    const tinygltf::Mesh& mesh = ctx.model.meshes[size_t(node.mesh)];
    return mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
}

bool is_integer(const tinygltf::Accessor& a) {
    return a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_DOUBLE;
}

// Reads sampler `s` of animation `a` as a curve of `path` for `node` (for a Property,
// `width` numbers per key), checking the accessors against glTF 2.0, section 5.7
// (animation.sampler) and Appendix C, and KHR_animation_pointer's type rules.
AnimationCurve read_curve(const GltfContext& ctx, size_t a, int s, Path path, int node,
                          size_t width = 0) {
    const tinygltf::AnimationSampler& sampler = ctx.model.animations[a].samplers[size_t(s)];
    const std::string el = element("animations", a) + "." + element("samplers", size_t(s));
    AnimationCurve c;
    if (sampler.interpolation == "LINEAR")
        c.interpolation = Interpolation::Linear;
    else if (sampler.interpolation == "STEP")
        c.interpolation = Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
        c.interpolation = Interpolation::CubicSpline;
    else
        ctx.fail(el, "interpolation '" + sampler.interpolation +
                         "' is not LINEAR, STEP or CUBICSPLINE");

    const tinygltf::Accessor& in = get_accessor(ctx, el, "input", sampler.input);
    if (in.type != TINYGLTF_TYPE_SCALAR || in.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        ctx.fail(el, "input accessor " + std::to_string(sampler.input) + " is " +
                         describe_accessor(in) + "; expected SCALAR of float");
    if (in.count == 0) ctx.fail(el, "input accessor has 0 elements");
    for (float t : read_floats(ctx, sampler.input)) c.times.push_back(t);
    for (size_t k = 0; k < c.times.size(); ++k) {
        if (!std::isfinite(c.times[k]) || c.times[k] < 0)
            ctx.fail(el, "input time " + std::to_string(k) + " is not a finite number >= 0");
        if (k > 0 && !(c.times[k] > c.times[k - 1]))
            ctx.fail(el, "input times are not strictly increasing (key " + std::to_string(k) +
                             ")");
    }
    if (c.interpolation == Interpolation::CubicSpline && c.times.size() < 2)
        ctx.fail(el, "CUBICSPLINE needs at least 2 keys");

    const tinygltf::Accessor& out = get_accessor(ctx, el, "output", sampler.output);
    const bool is_float = out.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const std::string out_desc =
        "output accessor " + std::to_string(sampler.output) + " is " + describe_accessor(out);
    switch (path) {
    case Path::Translation:
    case Path::Scale:
        if (out.type != TINYGLTF_TYPE_VEC3 || !is_float)
            ctx.fail(el, out_desc + "; " + path_name(path) + " expects VEC3 of float");
        c.width = 3;
        break;
    case Path::Rotation:
        if (out.type != TINYGLTF_TYPE_VEC4 || !(is_float || is_normalized_int(out)))
            ctx.fail(el, out_desc +
                             "; rotation expects VEC4 of float or of normalized byte or short");
        c.width = 4;
        c.quaternion = true;
        break;
    case Path::Weights:
        if (out.type != TINYGLTF_TYPE_SCALAR || !(is_float || is_normalized_int(out)))
            ctx.fail(el, out_desc +
                             "; weights expects SCALAR of float or of normalized byte or short");
        c.width = target_count(ctx, ctx.model.nodes[size_t(node)]);
        break;
    case Path::Visible:
        // KHR_animation_pointer: a bool is SCALAR unsigned byte, 0 false, and only STEP.
        if (out.type != TINYGLTF_TYPE_SCALAR ||
            out.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || out.normalized)
            ctx.fail(el, out_desc + "; visible (a bool) expects SCALAR of unsigned byte");
        if (c.interpolation != Interpolation::Step)
            ctx.fail(el, "visible (a bool) must be animated with STEP interpolation");
        c.width = 1;
        break;
    case Path::Property: {
        // Floats come as float or as integers, normalized or not (converted as the
        // accessor says), the type holding `width` numbers.
        static const int types[] = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_SCALAR,
                                    TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
        const char* names[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
        if (out.type != types[width] || !(is_float || is_integer(out)))
            ctx.fail(el, out_desc + "; the property expects " + names[width] + " of numbers");
        c.width = width;
        break;
    }
    }
    const size_t per_key = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const size_t expected = c.times.size() * per_key * (path == Path::Weights ? c.width : 1);
    if (out.count != expected)
        ctx.fail(el, "output accessor has " + std::to_string(out.count) + " elements; " +
                         std::to_string(c.times.size()) + " " + sampler.interpolation +
                         " keys of " + path_name(path) + " need " + std::to_string(expected));
    for (float v : read_floats(ctx, sampler.output)) {
        if (!std::isfinite(v)) ctx.fail(el, "output values are not all finite");
        c.values.push_back(v);
    }
    if (c.quaternion) {
        // Key values must be unit quaternions; tangents (CUBICSPLINE) are not.
        for (size_t k = 0; k < c.times.size(); ++k) {
            double* q = &c.values[(k * per_key + (per_key == 3 ? 1 : 0)) * 4];
            if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0))
                ctx.fail(el, "rotation key " + std::to_string(k) + " is a zero quaternion");
            normalize4(q);
        }
    }
    return c;
}

}  // namespace

void AnimationCurve::sample(double t, double* out) const {
    const size_t n = times.size(), w = width;
    const bool cubic = interpolation == Interpolation::CubicSpline;
    const size_t stride = cubic ? 3 * w : w;
    // Key k's value; a CUBICSPLINE key stores (in-tangent, value, out-tangent).
    auto value = [&](size_t k) { return &values[k * stride + (cubic ? w : 0)]; };
    const double* v = nullptr;
    if (n == 1 || t <= times.front())
        v = value(0);
    else if (t >= times.back())
        v = value(n - 1);
    if (v) {
        std::copy(v, v + w, out);
        return;
    }
    // times[k] <= t < times[k + 1]
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double td = times[k + 1] - times[k];
    const double s = (t - times[k]) / td;
    switch (interpolation) {
    case Interpolation::Step:
        std::copy(value(k), value(k) + w, out);
        return;
    case Interpolation::Linear:
        if (quaternion) {
            slerp(value(k), value(k + 1), s, out);
        } else {
            for (size_t i = 0; i < w; ++i) out[i] = (1 - s) * value(k)[i] + s * value(k + 1)[i];
        }
        return;
    case Interpolation::CubicSpline: {
        // Hermite basis with the tangents scaled by the key interval (Appendix C):
        // p(s) = (2s^3 - 3s^2 + 1) v_k + td (s^3 - 2s^2 + s) b_k
        //      + (-2s^3 + 3s^2) v_k+1 + td (s^3 - s^2) a_k+1
        const double s2 = s * s, s3 = s2 * s;
        const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
        const double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
        const double* b0 = &values[k * stride + 2 * w];  // out-tangent of key k
        const double* a1 = &values[(k + 1) * stride];     // in-tangent of key k + 1
        for (size_t i = 0; i < w; ++i)
            out[i] = h00 * value(k)[i] + td * h10 * b0[i] + h01 * value(k + 1)[i] +
                     td * h11 * a1[i];
        if (quaternion) normalize4(out);
        return;
    }
    }
}

std::vector<double> AnimationCurve::sample(double t) const {
    std::vector<double> out(width);
    sample(t, out.data());
    return out;
}

Transform NodePose::transform() const {
    return Transform::trs(Vec3(float(t[0]), float(t[1]), float(t[2])),
                          Quat{float(r[0]), float(r[1]), float(r[2]), float(r[3])},
                          Vec3(float(s[0]), float(s[1]), float(s[2])));
}

namespace {

// One channel's target: a node path, or an object's property (Path::Property).
struct Target {
    PointerObject object = PointerObject::Node;
    int index = -1;
    Path path = Path::Property;
    std::string property;  // Path::Property: the pointer below the object
    size_t width = 0;
    size_t curve = 0, animation = 0;
    std::string channel;  // "animations[a].channels[c]"
};

Path node_path(const std::string& name) {
    if (name == "translation") return Path::Translation;
    if (name == "rotation") return Path::Rotation;
    if (name == "scale") return Path::Scale;
    if (name == "weights") return Path::Weights;
    return Path::Visible;  // "extensions/KHR_node_visibility/visible"
}

// Checks a KHR_animation_pointer target's index against its array.
void check_pointer_index(const GltfContext& ctx, const std::string& el, const Target& t) {
    const tinygltf::Model& m = ctx.model;
    switch (t.object) {
    case PointerObject::Node:
        return ctx.check_index(el, "pointer's node", t.index, m.nodes.size(), "nodes");
    case PointerObject::Material:
        return ctx.check_index(el, "pointer's material", t.index, m.materials.size(), "materials");
    case PointerObject::Light:
        return ctx.check_index(el, "pointer's light", t.index, m.lights.size(), "lights");
    case PointerObject::Camera:
        return ctx.check_index(el, "pointer's camera", t.index, m.cameras.size(), "cameras");
    }
}

// The target of channel c of animation a; empty (the pointer named in *ignored) for a
// KHR_animation_pointer channel on something that does not change pixels, and for a
// channel without a target node.
std::optional<Target> channel_target(const GltfContext& ctx, size_t a, size_t c,
                                     std::vector<std::string>& untargeted,
                                     std::vector<std::string>& ignored) {
    const tinygltf::AnimationChannel& ch = ctx.model.animations[a].channels[c];
    Target t;
    t.channel = element("animations", a) + "." + element("channels", c);
    t.animation = a;
    if (ch.target_path == "pointer") {
        const auto it = ch.target_extensions.find("KHR_animation_pointer");
        const tinygltf::Value ext = it != ch.target_extensions.end() ? it->second : tinygltf::Value();
        if (!ext.IsObject() || !ext.Get("pointer").IsString()) {
            untargeted.push_back(t.channel);  // no pointer: nothing to target
            return std::nullopt;
        }
        const std::string pointer = ext.Get("pointer").Get<std::string>();
        const std::optional<PointerTarget> p = resolve_pointer(pointer);
        if (!p) {
            ignored.push_back(t.channel + " '" + pointer + "'");
            return std::nullopt;
        }
        t.object = p->object;
        t.index = p->index;
        t.property = p->property;
        t.width = p->width;
        check_pointer_index(ctx, t.channel, t);
        if (t.object == PointerObject::Node) t.path = node_path(p->property);
        return t;
    }
    if (ch.target_node < 0) {
        untargeted.push_back(t.channel);
        return std::nullopt;
    }
    ctx.check_index(t.channel, "target node", ch.target_node, ctx.model.nodes.size(), "nodes");
    t.index = ch.target_node;
    if (ch.target_path != "translation" && ch.target_path != "rotation" &&
        ch.target_path != "scale" && ch.target_path != "weights")
        ctx.fail(t.channel, "target path '" + ch.target_path +
                                "' is not translation, rotation, scale, weights or pointer");
    t.path = node_path(ch.target_path);
    return t;
}

// A node channel's checks against the node it animates.
void check_node_target(const GltfContext& ctx, const Target& t) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(t.index)];
    const std::string name = element("nodes", size_t(t.index));
    if (t.path != Path::Weights && t.path != Path::Visible && !node.matrix.empty())
        ctx.fail(t.channel, "animates " + name + ", which has a matrix (animated nodes must use TRS)");
    if (t.path == Path::Weights && target_count(ctx, node) == 0)
        ctx.fail(t.channel, "animates the weights of " + name + ", whose mesh has no morph targets");
}

const char* object_array(PointerObject o) {
    static const char* const names[] = {"nodes", "materials", "lights", "cameras"};
    return names[int(o)];
}

}  // namespace

GltfAnimations::GltfAnimations(const GltfContext& ctx) {
    const tinygltf::Model& m = ctx.model;
    // Out-of-spec but renderable: one summary warning per kind, with a count and the
    // first examples (as the glTF validator reports), not one line per channel.
    std::vector<std::string> untargeted, ignored, overlapping, overlapping_properties;
    std::vector<Target> targets;
    for (size_t a = 0; a < m.animations.size(); ++a) {
        const tinygltf::Animation& anim = m.animations[a];
        // (object, index, property) within this animation.
        std::set<std::tuple<int, int, std::string>> seen;
        for (size_t c = 0; c < anim.channels.size(); ++c) {
            const tinygltf::AnimationChannel& ch = anim.channels[c];
            ctx.check_index(element("animations", a) + "." + element("channels", c), "sampler",
                            ch.sampler, anim.samplers.size(), "samplers");
            std::optional<Target> t = channel_target(ctx, a, c, untargeted, ignored);
            if (!t) continue;
            if (t->object == PointerObject::Node) check_node_target(ctx, *t);
            const std::string what =
                t->object == PointerObject::Node ? path_name(t->path) : t->property;
            if (!seen.insert({int(t->object), t->index, what}).second)
                ctx.fail(t->channel, "targets " + element(object_array(t->object), size_t(t->index)) +
                                         " " + what + " again in the same animation");
            m_curves.push_back(read_curve(ctx, a, ch.sampler, t->path, t->index, t->width));
            t->curve = m_curves.size() - 1;
            targets.push_back(std::move(*t));
        }
    }
    if (!untargeted.empty())
        ctx.warn("animations", std::to_string(untargeted.size()) +
                                   " channel(s) without a target node ignored" +
                                   examples(untargeted));
    if (!ignored.empty())
        ctx.warn("animations", std::to_string(ignored.size()) +
                                   " KHR_animation_pointer channel(s) animate properties that do "
                                   "not change the render, ignored" +
                                   examples(ignored));
    if (m_curves.empty()) return;
    // Pointers are taken once m_curves has stopped growing.
    m_nodes.resize(m.nodes.size());
    std::map<const void*, size_t> used;  // the animation each slot came from
    for (const Target& t : targets) {
        const AnimationCurve* curve = &m_curves[t.curve];
        if (t.object != PointerObject::Node) {
            add_property_channel(t.object, t.index, {t.property, t.width, curve, t.channel},
                                 t.animation, used, overlapping_properties);
            continue;
        }
        NodeChannels& nc = m_nodes[size_t(t.index)];
        const AnimationCurve** slot = t.path == Path::Translation ? &nc.translation
                                      : t.path == Path::Rotation  ? &nc.rotation
                                      : t.path == Path::Scale     ? &nc.scale
                                      : t.path == Path::Weights   ? &nc.weights
                                                                  : &nc.visible;
        if (*slot) {
            overlapping.push_back(element("nodes", size_t(t.index)) + " " + path_name(t.path) +
                                  " by " + element("animations", used[slot]) + " and " +
                                  element("animations", t.animation));
            continue;
        }
        *slot = curve;
        used[slot] = t.animation;
    }
    // All animations play on one timeline, so a property driven by two has two values.
    if (!overlapping.empty())
        ctx.warn("animations", std::to_string(overlapping.size()) +
                                   " node properties animated by several animations; the "
                                   "first animation's channel is used" +
                                   examples(overlapping));
    if (!overlapping_properties.empty())
        ctx.warn("animations", std::to_string(overlapping_properties.size()) +
                                   " material, light or camera properties animated by several "
                                   "animations; the first animation's channel is used" +
                                   examples(overlapping_properties));
}

void GltfAnimations::add_property_channel(PointerObject object, int index, PropertyChannel ch,
                                          size_t animation, std::map<const void*, size_t>& used,
                                          std::vector<std::string>& overlapping) {
    std::vector<std::vector<PropertyChannel>>& lists = m_properties[size_t(object)];
    if (lists.size() <= size_t(index)) lists.resize(size_t(index) + 1);
    std::vector<PropertyChannel>& list = lists[size_t(index)];
    for (const PropertyChannel& other : list)
        if (other.property == ch.property) {
            overlapping.push_back(element(object_array(object), size_t(index)) + " " +
                                  ch.property + " by " +
                                  element("animations", used[other.curve]) + " and " +
                                  element("animations", animation));
            return;
        }
    used[ch.curve] = animation;
    list.push_back(std::move(ch));
}

const std::vector<PropertyChannel>& GltfAnimations::properties(PointerObject object,
                                                               int index) const {
    static const std::vector<PropertyChannel> none;
    const auto& lists = m_properties[size_t(object)];
    return index >= 0 && size_t(index) < lists.size() ? lists[size_t(index)] : none;
}

const NodeChannels* GltfAnimations::node(int index) const {
    if (index < 0 || size_t(index) >= m_nodes.size()) return nullptr;
    const NodeChannels& nc = m_nodes[size_t(index)];
    return nc.animates_transform() || nc.weights || nc.visible ? &nc : nullptr;
}

NodePose GltfAnimations::pose(int index, const NodePose& rest, double t) const {
    NodePose p = rest;
    const NodeChannels* nc = node(index);
    if (!nc) return p;
    if (nc->translation) nc->translation->sample(t, p.t);
    if (nc->rotation) nc->rotation->sample(t, p.r);
    if (nc->scale) nc->scale->sample(t, p.s);
    return p;
}

GltfAnimations load_gltf_animations(const std::string& path) {
    const tinygltf::Model model = parse_gltf(path, false);
    const GltfContext ctx{model, path};
    return GltfAnimations(ctx);
}

}  // namespace penumbra
