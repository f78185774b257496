#include "io/gltf/gltf_instancing.h"

#include <cmath>
#include <optional>
#include <vector>

#include "io/gltf/gltf_accessor.h"

namespace penumbra {

namespace {

// The attribute's values, checked for type and count; empty when absent.
std::optional<std::vector<float>> attribute(const GltfContext& ctx, const std::string& el,
                                            const tinygltf::Value& attrs, const char* name,
                                            int type, size_t* count) {
    if (!attrs.Has(name)) return std::nullopt;
    const tinygltf::Value& v = attrs.Get(name);
    if (!v.IsNumber()) ctx.fail(el, std::string(name) + " must be an accessor index");
    const int index = v.GetNumberAsInt();
    const tinygltf::Accessor& a = get_accessor(ctx, el, name, index);
    if (a.type != type)
        ctx.fail(el, std::string(name) + " accessor " + std::to_string(index) + " is " +
                         describe_accessor(a) + "; expected " +
                         (type == TINYGLTF_TYPE_VEC4 ? "VEC4" : "VEC3"));
    if (*count == 0) *count = a.count;
    if (a.count != *count)
        ctx.fail(el, std::string(name) + " accessor has " + std::to_string(a.count) +
                         " elements, another attribute has " + std::to_string(*count));
    std::vector<float> values = read_floats(ctx, index);
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            ctx.fail(el, std::string(name) + " element " +
                             std::to_string(i / size_t(component_count(type))) + " is not finite");
    return values;
}

}  // namespace

bool add_gpu_instances(const GltfContext& ctx, const std::string& node_el,
                       const tinygltf::Node& node, int node_index, uint32_t object,
                       const Transform& world,
                       const std::vector<Transform>& motion, Scene& scene) {
    const auto it = node.extensions.find("EXT_mesh_gpu_instancing");
    if (it == node.extensions.end()) return false;
    const std::string el = node_el + ".extensions.EXT_mesh_gpu_instancing";
    const tinygltf::Value& ext = it->second;
    if (!ext.IsObject() || !ext.Get("attributes").IsObject())
        ctx.fail(el, "attributes must be an object");
    const tinygltf::Value& attrs = ext.Get("attributes");
    size_t count = 0;
    const auto t = attribute(ctx, el, attrs, "TRANSLATION", TINYGLTF_TYPE_VEC3, &count);
    const auto r = attribute(ctx, el, attrs, "ROTATION", TINYGLTF_TYPE_VEC4, &count);
    const auto s = attribute(ctx, el, attrs, "SCALE", TINYGLTF_TYPE_VEC3, &count);
    if (!t && !r && !s) ctx.fail(el, "no TRANSLATION, ROTATION or SCALE attribute");

    scene.instances.reserve(scene.instances.size() + count);
    for (size_t i = 0; i < count; ++i) {
        const Vec3 ti = t ? Vec3((*t)[3 * i], (*t)[3 * i + 1], (*t)[3 * i + 2]) : Vec3(0);
        const Quat ri = r ? Quat{(*r)[4 * i], (*r)[4 * i + 1], (*r)[4 * i + 2], (*r)[4 * i + 3]}
                          : Quat{};
        const Vec3 si = s ? Vec3((*s)[3 * i], (*s)[3 * i + 1], (*s)[3 * i + 2]) : Vec3(1);
        Transform local;
        try {
            local = Transform::trs(ti, ri, si);
        } catch (const std::invalid_argument& e) {
            // A zero scale hides an instance; a zero quaternion is an error.
            if (si.x == 0 || si.y == 0 || si.z == 0) continue;
            ctx.fail(el, "instance " + std::to_string(i) + ": " + e.what());
        }
        // Instances are unnamed: a million copies of the node name would cost more than
        // the instances themselves. Their node index identifies them.
        Instance inst;
        inst.object = object;
        inst.to_world = world * local;
        for (const Transform& step : motion) inst.motion.push_back(step * local);
        inst.node = node_index;
        scene.instances.push_back(std::move(inst));
    }
    return true;
}

}  // namespace penumbra
