#include "io/gltf/animation/gltf_pointer.h"

#include <cstdlib>
#include <map>
#include <vector>

namespace penumbra {

namespace {

// RFC 6901 reference tokens: split at '/', then "~1" is '/' and "~0" is '~'.
std::vector<std::string> tokens(const std::string& pointer) {
    std::vector<std::string> out;
    if (pointer.empty() || pointer[0] != '/') return out;
    std::string token;
    for (size_t i = 1; i <= pointer.size(); ++i) {
        if (i == pointer.size() || pointer[i] == '/') {
            out.push_back(token);
            token.clear();
        } else if (pointer[i] == '~' && i + 1 < pointer.size() &&
                   (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
            token += pointer[++i] == '0' ? '~' : '/';
        } else {
            token += pointer[i];
        }
    }
    return out;
}

// A glTF array index: decimal digits without a leading zero (RFC 6901's rule).
int array_index(const std::string& s) {
    if (s.empty() || s.size() > 9 || (s.size() > 1 && s[0] == '0')) return -1;
    for (char c : s)
        if (c < '0' || c > '9') return -1;
    return std::atoi(s.c_str());
}

std::string join(const std::vector<std::string>& t, size_t from) {
    std::string s;
    for (size_t i = from; i < t.size(); ++i) s += (i > from ? "/" : "") + t[i];
    return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The Asset Object Model's mutable material properties that the renderer reads, with
// their widths: glTF 2.0 core and the ratified KHR_materials_* extensions.
const std::map<std::string, size_t>& material_properties() {
    static const std::map<std::string, size_t> table = {
        {"alphaCutoff", 1},
        {"emissiveFactor", 3},
        {"normalTexture/scale", 1},
        {"occlusionTexture/strength", 1},
        {"pbrMetallicRoughness/baseColorFactor", 4},
        {"pbrMetallicRoughness/metallicFactor", 1},
        {"pbrMetallicRoughness/roughnessFactor", 1},
        {"extensions/KHR_materials_anisotropy/anisotropyStrength", 1},
        {"extensions/KHR_materials_anisotropy/anisotropyRotation", 1},
        {"extensions/KHR_materials_clearcoat/clearcoatFactor", 1},
        {"extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor", 1},
        {"extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale", 1},
        {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionFactor", 1},
        {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor", 3},
        {"extensions/KHR_materials_dispersion/dispersion", 1},
        {"extensions/KHR_materials_emissive_strength/emissiveStrength", 1},
        {"extensions/KHR_materials_ior/ior", 1},
        {"extensions/KHR_materials_iridescence/iridescenceFactor", 1},
        {"extensions/KHR_materials_iridescence/iridescenceIor", 1},
        {"extensions/KHR_materials_iridescence/iridescenceThicknessMinimum", 1},
        {"extensions/KHR_materials_iridescence/iridescenceThicknessMaximum", 1},
        {"extensions/KHR_materials_sheen/sheenColorFactor", 3},
        {"extensions/KHR_materials_sheen/sheenRoughnessFactor", 1},
        {"extensions/KHR_materials_specular/specularFactor", 1},
        {"extensions/KHR_materials_specular/specularColorFactor", 3},
        {"extensions/KHR_materials_transmission/transmissionFactor", 1},
        {"extensions/KHR_materials_volume/thicknessFactor", 1},
        {"extensions/KHR_materials_volume/attenuationDistance", 1},
        {"extensions/KHR_materials_volume/attenuationColor", 3},
    };
    return table;
}

// KHR_texture_transform on any textureInfo of a material ("...Texture/extensions/
// KHR_texture_transform/offset"): its width, or 0 for anything else.
size_t texture_transform_width(const std::string& property) {
    static const std::string ext = "Texture/extensions/KHR_texture_transform/";
    for (const auto& [key, width] : {std::pair<const char*, size_t>{"offset", 2},
                                     {"rotation", 1},
                                     {"scale", 2}})
        if (ends_with(property, ext + key)) return width;
    return 0;
}

std::optional<size_t> property_width(PointerObject object, const std::string& p) {
    switch (object) {
    case PointerObject::Node:
        if (p == "translation" || p == "scale") return 3;
        if (p == "rotation") return 4;
        if (p == "weights") return 0;  // the mesh's morph target count
        if (p == "extensions/KHR_node_visibility/visible") return 1;
        return std::nullopt;
    case PointerObject::Material: {
        const auto it = material_properties().find(p);
        if (it != material_properties().end()) return it->second;
        if (const size_t w = texture_transform_width(p)) return w;
        return std::nullopt;
    }
    case PointerObject::Light:
        if (p == "color") return 3;
        if (p == "intensity" || p == "range" || p == "spot/innerConeAngle" ||
            p == "spot/outerConeAngle")
            return 1;
        return std::nullopt;
    case PointerObject::Camera:
        for (const char* q : {"perspective/aspectRatio", "perspective/yfov", "perspective/zfar",
                              "perspective/znear", "orthographic/xmag", "orthographic/ymag",
                              "orthographic/zfar", "orthographic/znear"})
            if (p == q) return 1;
        return std::nullopt;
    }
    return std::nullopt;
}

tinygltf::Value number_value(const double* v, size_t width) {
    if (width == 1) return tinygltf::Value(v[0]);
    tinygltf::Value::Array a;
    for (size_t i = 0; i < width; ++i) a.emplace_back(v[i]);
    return tinygltf::Value(std::move(a));
}

// Writes the value at path t[from..] inside a JSON object: every object on the way must
// exist; the last token is set (present or defaulted).
bool write_json(tinygltf::Value& obj, const std::vector<std::string>& t, size_t from,
                const double* v, size_t width) {
    tinygltf::Value* cur = &obj;
    for (size_t i = from; i < t.size(); ++i) {
        if (!cur->IsObject()) return false;
        tinygltf::Value::Object& o = cur->Get<tinygltf::Value::Object>();
        if (i + 1 == t.size()) {
            o[t[i]] = number_value(v, width);
            return true;
        }
        const auto it = o.find(t[i]);
        if (it == o.end()) return false;
        cur = &it->second;
    }
    return false;
}

// Writes into an extension map ("extensions/NAME/..." starting at t[from]).
bool write_extension(tinygltf::ExtensionMap& extensions, const std::vector<std::string>& t,
                     size_t from, const double* v, size_t width) {
    if (t.size() < from + 3 || t[from] != "extensions") return false;
    const auto it = extensions.find(t[from + 1]);
    return it != extensions.end() && write_json(it->second, t, from + 2, v, width);
}

template <typename Info>
bool write_texture_info(Info& info, const std::vector<std::string>& t, const double* v,
                        size_t width) {
    return info.index >= 0 && write_extension(info.extensions, t, 2, v, width);
}

}  // namespace

std::optional<PointerTarget> resolve_pointer(const std::string& pointer) {
    const std::vector<std::string> t = tokens(pointer);
    PointerTarget target;
    size_t first = 2;  // the property's first token
    if (t.size() >= 3 && t[0] == "nodes") {
        target.object = PointerObject::Node;
    } else if (t.size() >= 3 && t[0] == "materials") {
        target.object = PointerObject::Material;
    } else if (t.size() >= 3 && t[0] == "cameras") {
        target.object = PointerObject::Camera;
    } else if (t.size() >= 5 && t[0] == "extensions" && t[1] == "KHR_lights_punctual" &&
               t[2] == "lights") {
        target.object = PointerObject::Light;
        first = 4;
    } else {
        return std::nullopt;
    }
    target.index = array_index(t[first - 1]);
    if (target.index < 0) return std::nullopt;
    target.property = join(t, first);
    const std::optional<size_t> width = property_width(target.object, target.property);
    if (!width) return std::nullopt;
    target.width = *width;
    target.boolean = target.property == "extensions/KHR_node_visibility/visible";
    return target;
}

bool write_property(tinygltf::Material& m, const std::string& property, const double* v,
                    size_t width) {
    const std::vector<std::string> t = tokens("/" + property);
    auto vec = [&](std::vector<double>& out) {
        out.assign(v, v + width);
        return true;
    };
    if (property == "alphaCutoff") return (m.alphaCutoff = v[0], true);
    if (property == "emissiveFactor") return vec(m.emissiveFactor);
    if (property == "normalTexture/scale") return (m.normalTexture.scale = v[0], true);
    if (property == "occlusionTexture/strength") return (m.occlusionTexture.strength = v[0], true);
    tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    if (property == "pbrMetallicRoughness/baseColorFactor") return vec(pbr.baseColorFactor);
    if (property == "pbrMetallicRoughness/metallicFactor") return (pbr.metallicFactor = v[0], true);
    if (property == "pbrMetallicRoughness/roughnessFactor") return (pbr.roughnessFactor = v[0], true);
    if (t.size() >= 2 && t[0] == "pbrMetallicRoughness") {
        // Texture transforms of the core textureInfos (t[2] is "extensions").
        if (t[1] == "baseColorTexture") return write_texture_info(pbr.baseColorTexture, t, v, width);
        if (t[1] == "metallicRoughnessTexture")
            return write_texture_info(pbr.metallicRoughnessTexture, t, v, width);
        return false;
    }
    std::vector<std::string> shifted(t);  // core textures sit one level higher
    shifted.insert(shifted.begin(), "");
    if (t[0] == "normalTexture") return write_texture_info(m.normalTexture, shifted, v, width);
    if (t[0] == "occlusionTexture") return write_texture_info(m.occlusionTexture, shifted, v, width);
    if (t[0] == "emissiveTexture") return write_texture_info(m.emissiveTexture, shifted, v, width);
    return write_extension(m.extensions, t, 0, v, width);
}

bool write_property(tinygltf::Light& l, const std::string& property, const double* v,
                    size_t width) {
    if (property == "color") return (l.color.assign(v, v + width), true);
    if (property == "intensity") return (l.intensity = v[0], true);
    if (property == "range") return (l.range = v[0], true);
    if (l.type != "spot") return false;
    if (property == "spot/innerConeAngle") return (l.spot.innerConeAngle = v[0], true);
    if (property == "spot/outerConeAngle") return (l.spot.outerConeAngle = v[0], true);
    return false;
}

bool write_property(tinygltf::Camera& c, const std::string& property, const double* v,
                    size_t) {
    const bool persp = c.type == "perspective", ortho = c.type == "orthographic";
    if (persp && property == "perspective/aspectRatio") return (c.perspective.aspectRatio = v[0], true);
    if (persp && property == "perspective/yfov") return (c.perspective.yfov = v[0], true);
    if (persp && property == "perspective/zfar") return (c.perspective.zfar = v[0], true);
    if (persp && property == "perspective/znear") return (c.perspective.znear = v[0], true);
    if (ortho && property == "orthographic/xmag") return (c.orthographic.xmag = v[0], true);
    if (ortho && property == "orthographic/ymag") return (c.orthographic.ymag = v[0], true);
    if (ortho && property == "orthographic/zfar") return (c.orthographic.zfar = v[0], true);
    if (ortho && property == "orthographic/znear") return (c.orthographic.znear = v[0], true);
    return false;
}

}  // namespace penumbra
