#include "io/gltf/gltf_variants.h"

#include "io/gltf/material/gltf_material_json.h"

namespace penumbra {

namespace {

const char* const kName = "KHR_materials_variants";
const std::string kRootEl = std::string("extensions.") + kName;

// The root's variants array (an empty Value when the file has none).
const tinygltf::Value& root_variants(const GltfContext& ctx) {
    static const tinygltf::Value none;
    const auto it = ctx.model.extensions.find(kName);
    if (it == ctx.model.extensions.end()) return none;
    const tinygltf::Value& root = it->second;
    if (!root.IsObject() || !root.Has("variants") || !root.Get("variants").IsArray())
        ctx.fail(kRootEl, "variants must be an array");
    return root.Get("variants");
}

size_t variant_count(const GltfContext& ctx) {
    const tinygltf::Value& v = root_variants(ctx);
    return v.IsArray() ? v.ArrayLen() : 0;
}

}  // namespace

int find_variant(const GltfContext& ctx, const std::string& name) {
    if (name.empty()) return -1;
    const tinygltf::Value& variants = root_variants(ctx);
    const size_t n = variants.IsArray() ? variants.ArrayLen() : 0;
    std::string list;
    for (size_t i = 0; i < n; ++i) {
        const tinygltf::Value& v = variants.Get(int(i));
        const std::string vel = kRootEl + "." + element("variants", i);
        if (!v.IsObject() || !v.Has("name") || !v.Get("name").IsString())
            ctx.fail(vel, "must be an object with a string name");
        const std::string& vname = v.Get("name").Get<std::string>();
        if (vname == name) return int(i);
        list += (list.empty() ? "'" : ", '") + vname + "'";
    }
    ctx.fail(kRootEl, "no material variant '" + name + "' (" +
                          (n == 0 ? std::string("the file defines none") : "the file has " + list) +
                          ")");
}

int primitive_material(const GltfContext& ctx, const tinygltf::Primitive& prim,
                       const std::string& el) {
    const std::string xel = el + ".extensions." + kName;
    const tinygltf::Value& ext = extension_object(prim.extensions, kName);
    if (!ext.IsObject()) return prim.material;
    if (!ext.Has("mappings") || !ext.Get("mappings").IsArray())
        ctx.fail(xel, "mappings must be an array");
    const tinygltf::Value& mappings = ext.Get("mappings");
    const size_t variants = variant_count(ctx);
    int chosen = -1;
    for (size_t i = 0; i < mappings.ArrayLen(); ++i) {
        const tinygltf::Value& m = mappings.Get(int(i));
        const std::string mel = xel + "." + element("mappings", i);
        if (!m.IsObject() || !m.Has("material") || !m.Get("material").IsInt() ||
            !m.Has("variants") || !m.Get("variants").IsArray())
            ctx.fail(mel, "must have an integer material and an array of variants");
        const int material = m.Get("material").GetNumberAsInt();
        ctx.check_index(mel, "material", material, ctx.model.materials.size(), "materials");
        const tinygltf::Value& list = m.Get("variants");
        for (size_t k = 0; k < list.ArrayLen(); ++k) {
            if (!list.Get(int(k)).IsInt()) ctx.fail(mel, "variants must hold integers");
            const int variant = list.Get(int(k)).GetNumberAsInt();
            ctx.check_index(mel, "variant", variant, variants, "variants");
            if (variant != ctx.variant) continue;
            // A variant names one material per primitive; a file that maps it twice is
            // ambiguous and renders with the first, the lookup order of the draft spec.
            if (chosen >= 0 && chosen != material)
                ctx.warn_once("meshes",
                              "a material variant is mapped to several materials of "
                              "one primitive; using the first mapping");
            else
                chosen = material;
        }
    }
    return chosen >= 0 ? chosen : prim.material;
}

}  // namespace penumbra
