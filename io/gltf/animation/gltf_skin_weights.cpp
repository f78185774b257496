#include "io/gltf/animation/gltf_skin_weights.h"

#include <cmath>
#include <set>

#include "io/gltf/gltf_accessor.h"

namespace penumbra {

void normalize_skin_weights(SkinWeights& w, size_t vertices) {
    const size_t per_set = 4 * vertices;
    for (size_t v = 0; v < vertices; ++v) {
        double sum = 0;
        size_t nonzero = 0;
        for (size_t set = 0; set < w.influences; ++set)
            for (size_t c = 0; c < 4; ++c) {
                const float x = w.weights[set * per_set + 4 * v + c];
                sum += std::abs(double(x));
                nonzero += x != 0;
            }
        if (!(std::abs(sum - 1.0) <= 2e-7 * double(nonzero))) {
            if (w.renormalized++ == 0) {
                w.example = v;
                w.example_sum = sum;
            }
        }
        const bool degenerate = !(sum > 0) || !std::isfinite(sum);
        for (size_t set = 0; set < w.influences; ++set)
            for (size_t c = 0; c < 4; ++c) {
                float& x = w.weights[set * per_set + 4 * v + c];
                x = degenerate ? float(set == 0 && c == 0) : float(double(x) / sum);
            }
    }
}

SkinWeights read_skin_weights(const GltfContext& ctx, const std::string& el,
                              const tinygltf::Primitive& prim, size_t vertices,
                              size_t joint_count) {
    SkinWeights d;
    for (int set = 0;; ++set) {
        const std::string js = "JOINTS_" + std::to_string(set),
                          ws = "WEIGHTS_" + std::to_string(set);
        const bool has_j = prim.attributes.count(js), has_w = prim.attributes.count(ws);
        if (!has_j && !has_w) break;
        if (has_j != has_w) ctx.fail(el, js + " and " + ws + " must come together");
        const tinygltf::Accessor& ja = get_accessor(ctx, el, js, prim.attributes.at(js));
        const tinygltf::Accessor& wa = get_accessor(ctx, el, ws, prim.attributes.at(ws));
        if (ja.type != TINYGLTF_TYPE_VEC4 || ja.normalized ||
            (ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
            ctx.fail(el, js + " accessor is " + describe_accessor(ja) +
                             "; expected VEC4 of unsigned byte or short");
        if (wa.type != TINYGLTF_TYPE_VEC4 ||
            !(wa.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || wa.normalized))
            ctx.fail(el, ws + " accessor is " + describe_accessor(wa) +
                             "; expected VEC4 of float or normalized unsigned byte or short");
        if (ja.count != vertices || wa.count != vertices)
            ctx.fail(el, js + "/" + ws + " accessors do not have one element per vertex (" +
                             std::to_string(vertices) + ")");
        const std::vector<float> j = read_floats(ctx, prim.attributes.at(js));
        const std::vector<float> w = read_floats(ctx, prim.attributes.at(ws));
        d.joints.insert(d.joints.end(), j.begin(), j.end());
        d.weights.insert(d.weights.end(), w.begin(), w.end());
        ++d.influences;
    }
    if (d.influences == 0) ctx.fail(el, "is skinned but has no JOINTS_0/WEIGHTS_0");
    // Non-finite weights are normalised like a zero sum, before the joints are checked:
    // the fallback gives JOINTS_0's first joint a weight.
    normalize_skin_weights(d, vertices);
    for (size_t i = 0; i < d.joints.size(); ++i)
        if (d.weights[i] != 0 && !(d.joints[i] < float(joint_count))) {
            const size_t set = i / (4 * vertices);
            ctx.fail(el, "JOINTS_" + std::to_string(set) + " element " +
                             std::to_string(i % (4 * vertices) / 4) + " names joint " +
                             std::to_string(int(d.joints[i])) + " of a skin with " +
                             std::to_string(joint_count) + " joints");
        }
    return d;
}

void warn_unnormalized_skin_weights(const GltfContext& ctx, const Scene& scene,
                                    const std::vector<MeshOrigin>& origins) {
    std::set<int> meshes;  // each mesh a skinned node draws, checked once
    for (const Instance& inst : scene.instances) {
        if (inst.node < 0) continue;
        const tinygltf::Node& node = ctx.model.nodes[size_t(inst.node)];
        if (node.skin >= 0 && node.mesh >= 0) meshes.insert(node.mesh);
    }
    size_t vertices = 0;
    std::vector<std::string> names;
    std::string example;
    for (int m : meshes) {
        const tinygltf::Mesh& mesh = ctx.model.meshes[size_t(m)];
        size_t in_mesh = 0;
        // Skinning read these primitives without error; the joint count is not rechecked.
        for (uint32_t index : scene.objects[size_t(m)].meshes) {
            const MeshOrigin& origin = origins[index];
            const tinygltf::Primitive& prim = mesh.primitives[size_t(origin.primitive)];
            const std::string el = element("meshes", size_t(m)) + "." +
                                   element("primitives", size_t(origin.primitive));
            const size_t n = ctx.model.accessors[size_t(prim.attributes.at("POSITION"))].count;
            const SkinWeights w = read_skin_weights(ctx, el, prim, n, size_t(-1));
            if (w.renormalized > 0 && example.empty())
                example = el + " vertex " + std::to_string(w.example) + " sums to " +
                          std::to_string(w.example_sum);
            in_mesh += w.renormalized;
        }
        if (in_mesh == 0) continue;
        vertices += in_mesh;
        names.push_back(element("meshes", size_t(m)) +
                        (mesh.name.empty() ? "" : " '" + mesh.name + "'"));
    }
    // glTF 2.0, section 3.7.3.3: the weights of a vertex sum to one (a validator error).
    if (vertices > 0)
        ctx.warn("skins", "the skin weights of " + std::to_string(vertices) +
                              " vertices do not sum to 1, in " + std::to_string(names.size()) +
                              " mesh(es)" + examples(names) + "; first: " + example +
                              "; each vertex's weights are scaled to sum to 1, as three.js "
                              "and Blender do");
}

}  // namespace penumbra
