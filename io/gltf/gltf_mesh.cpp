// glTF meshes to Objects and TriangleMeshes: attribute validation, strips and fans to
// lists, and flat normals where the file gives none.
#include <cmath>
#include <numeric>

#include "io/gltf/gltf_accessor.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/gltf_mesh_checks.h"
#include "io/gltf/gltf_variants.h"

namespace penumbra {

namespace {

bool is_float(const tinygltf::Accessor& a) {
    return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
}
bool is_signed_8_16(const tinygltf::Accessor& a) {
    return a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
           a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT;
}
bool is_8_16(const tinygltf::Accessor& a) {
    return is_signed_8_16(a) || a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// The accessor types glTF 2.0 (section 3.7.2.1) allows for each attribute, widened by
// KHR_mesh_quantization to 8- and 16-bit integers.
struct AttributeRule {
    const char* expected;
    bool (*accepts)(const tinygltf::Accessor&);
};

const AttributeRule kPosition{
    "VEC3 of float, or of (normalized) byte or short (KHR_mesh_quantization)",
    [](const tinygltf::Accessor& a) {
        return a.type == TINYGLTF_TYPE_VEC3 && (is_float(a) || is_8_16(a));
    }};
const AttributeRule kNormal{
    "VEC3 of float, or of normalized signed byte or short", [](const tinygltf::Accessor& a) {
        return a.type == TINYGLTF_TYPE_VEC3 && (is_float(a) || (is_signed_8_16(a) && a.normalized));
    }};
const AttributeRule kTangent{
    "VEC4 of float, or of normalized signed byte or short", [](const tinygltf::Accessor& a) {
        return a.type == TINYGLTF_TYPE_VEC4 && (is_float(a) || (is_signed_8_16(a) && a.normalized));
    }};
const AttributeRule kTexcoord{
    "VEC2 of float, or of (normalized) byte or short", [](const tinygltf::Accessor& a) {
        return a.type == TINYGLTF_TYPE_VEC2 && (is_float(a) || is_8_16(a));
    }};
const AttributeRule kColor{
    "VEC3 or VEC4 of float, or of normalized unsigned byte or short",
    [](const tinygltf::Accessor& a) {
        const bool unorm =
            a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        return (a.type == TINYGLTF_TYPE_VEC3 || a.type == TINYGLTF_TYPE_VEC4) &&
               (is_float(a) || unorm);
    }};

class PrimitiveReader {
public:
    PrimitiveReader(const GltfContext& ctx, const tinygltf::Primitive& prim, std::string el)
        : m_ctx(ctx), m_prim(prim), m_el(std::move(el)) {}

    // The attribute's values (`components` floats per vertex) after checking its type
    // and element count; empty when the primitive lacks it.
    std::vector<float> read(const std::string& semantic, const AttributeRule& rule,
                            size_t vertex_count, int* components = nullptr) const {
        const auto it = m_prim.attributes.find(semantic);
        if (it == m_prim.attributes.end()) return {};
        const tinygltf::Accessor& a = get_accessor(m_ctx, m_el, semantic, it->second);
        if (!rule.accepts(a))
            m_ctx.fail(m_el, semantic + " accessor " + std::to_string(it->second) + " is " +
                                 describe_accessor(a) + "; expected " + rule.expected);
        if (vertex_count != 0 && a.count != vertex_count)
            m_ctx.fail(m_el, semantic + " accessor has " + std::to_string(a.count) +
                                 " elements, POSITION has " + std::to_string(vertex_count));
        if (components) *components = component_count(a.type);
        return read_floats(m_ctx, it->second);
    }

private:
    const GltfContext& m_ctx;
    const tinygltf::Primitive& m_prim;
    std::string m_el;
};

// in[indices[i]] for each i, with a spare element of capacity as to_vec3's.
template <typename V>
std::vector<V> gather(const std::vector<V>& in, const std::vector<uint32_t>& indices) {
    if (in.empty()) return {};
    std::vector<V> out;
    out.reserve(indices.size() + 1);
    out.resize(indices.size());
    for (size_t i = 0; i < indices.size(); ++i) out[i] = in[indices[i]];
    return out;
}

// glTF 2.0, section 3.7.2.1: without NORMAL, shading is flat. Each triangle gets its own
// three vertices carrying its face normal; provided tangents must then be ignored.
void make_flat(TriangleMesh& mesh) {
    mesh.positions = gather(mesh.positions, mesh.indices);
    mesh.uv0 = gather(mesh.uv0, mesh.indices);
    mesh.uv1 = gather(mesh.uv1, mesh.indices);
    mesh.colors = gather(mesh.colors, mesh.indices);
    mesh.tangents.clear();
    std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
    mesh.normals.resize(mesh.positions.size());
    for (size_t t = 0; t + 2 < mesh.positions.size(); t += 3) {
        const Vec3 n = cross(mesh.positions[t + 1] - mesh.positions[t],
                             mesh.positions[t + 2] - mesh.positions[t]);
        const float len = length(n);
        // Degenerate triangles are kept (they are never hit); any unit normal will do.
        const Vec3 unit = len > 0 && std::isfinite(len) ? n / len : Vec3(0, 0, 1);
        mesh.normals[t] = mesh.normals[t + 1] = mesh.normals[t + 2] = unit;
    }
}

// Index list of `mode` to a triangle list. Strips alternate the order of odd triangles
// so that all keep the first one's winding (glTF 2.0, section 3.7.2.1).
std::vector<uint32_t> to_triangle_list(MeshChecks& checks, const std::string& el, int mode,
                                       const std::vector<uint32_t>& in) {
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (in.size() % 3 != 0) checks.partial_triangle(el, in.size());
        out.assign(in.begin(), in.begin() + (in.size() / 3) * 3);
        return out;
    }
    for (size_t i = 0; i + 2 < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            out.insert(out.end(), {in[0], in[i + 1], in[i + 2]});
        else if (i % 2 == 0)
            out.insert(out.end(), {in[i], in[i + 1], in[i + 2]});
        else
            out.insert(out.end(), {in[i + 1], in[i], in[i + 2]});
    }
    return out;
}

const char* mode_name(int mode) {
    static const char* names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    return names[mode];
}

// With one spare element of capacity: Embree then reads positions in place instead of
// copying them (its 16-byte loads read past the last vertex; embree_accel.cpp).
std::vector<Vec3> to_vec3(const std::vector<float>& v) {
    std::vector<Vec3> out;
    out.reserve(v.size() / 3 + 1);
    out.resize(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

// A single-sided emitter emits from its front (counter-clockwise) face only, as glTF
// defines the front (docs/conventions.md); vertex normals pointing the other way on most
// of its triangles usually mean the file's winding is reversed, so say so, once.
void check_emitter_winding(const GltfContext& ctx, int material, const TriangleMesh& mesh) {
    if (material < 0 || mesh.normals.empty()) return;
    const tinygltf::Material& m = ctx.model.materials[size_t(material)];
    const std::vector<double>& e = m.emissiveFactor;
    if (m.doubleSided || e.size() < 3 || !(e[0] > 0 || e[1] > 0 || e[2] > 0)) return;
    size_t against = 0;
    const size_t triangles = mesh.indices.size() / 3;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        const Vec3 winding = cross(mesh.positions[i[1]] - mesh.positions[i[0]],
                                   mesh.positions[i[2]] - mesh.positions[i[0]]);
        if (dot(winding, mesh.normals[i[0]] + mesh.normals[i[1]] + mesh.normals[i[2]]) < 0)
            ++against;
    }
    if (2 * against > triangles)
        ctx.warn_once("meshes", "single-sided emitters whose normals point to their back "
                                "faces emit from the front (counter-clockwise) face only; "
                                "set doubleSided to emit from both");
}

// One triangle primitive; false when it has no triangles to render (skipped, with a
// warning).
bool build_primitive(const GltfContext& ctx, MeshChecks& checks, const tinygltf::Primitive& prim,
                     const std::string& el, TriangleMesh& mesh, MeshOrigin& origin) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
        ctx.fail(el, "mode " + std::to_string(mode) + " is not a glTF primitive mode");
    if (mode < TINYGLTF_MODE_TRIANGLES) {
        ctx.warn_once("meshes", std::string("skipping ") + mode_name(mode) +
                                    " primitives (only triangles are rendered)");
        return false;
    }
    if (prim.material >= 0 || prim.material < -1)
        ctx.check_index(el, "material", prim.material, ctx.model.materials.size(), "materials");
    mesh.material = primitive_material(ctx, prim, el);

    const PrimitiveReader reader(ctx, prim, el);
    if (!prim.attributes.count("POSITION")) ctx.fail(el, "has no POSITION attribute");
    const int pos_index = prim.attributes.at("POSITION");
    const size_t n = get_accessor(ctx, el, "POSITION", pos_index).count;
    if (n == 0) ctx.fail(el, "POSITION accessor has 0 elements");
    mesh.positions = to_vec3(reader.read("POSITION", kPosition, n));
    for (size_t i = 0; i < n; ++i)
        if (!is_finite(mesh.positions[i]))
            ctx.fail(el, "POSITION element " + std::to_string(i) + " is not finite");
    checks.check_position_bounds(pos_index, mesh.positions,
                                 prim.extensions.count("KHR_draco_mesh_compression") > 0);

    mesh.normals = to_vec3(reader.read("NORMAL", kNormal, n));
    for (size_t i = 0; i < mesh.normals.size(); ++i) {
        Vec3& nrm = mesh.normals[i];
        if (!is_finite(nrm)) ctx.fail(el, "NORMAL element " + std::to_string(i) + " is not finite");
        // Quantized normals are only approximately unit length.
        if (length_squared(nrm) > 0) nrm = normalize(nrm);
    }
    const std::vector<float> tangents = reader.read("TANGENT", kTangent, n);
    // Arrays sized once: growing them would leave up to half their capacity unused.
    mesh.tangents.reserve(tangents.size() / 4);
    for (size_t i = 0; i + 3 < tangents.size(); i += 4) {
        const Vec4 t(tangents[i], tangents[i + 1], tangents[i + 2], tangents[i + 3]);
        // A NaN would poison every normal-mapped frame it touches; zero-length ones are
        // harmless (the material then derives the tangent from the UVs).
        if (!(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w)))
            ctx.fail(el, "TANGENT element " + std::to_string(i / 4) + " is not finite");
        mesh.tangents.push_back(t);
    }
    const std::string uv_names[2] = {"TEXCOORD_0", "TEXCOORD_1"};
    std::vector<Vec2>* uv_out[2] = {&mesh.uv0, &mesh.uv1};
    for (int k = 0; k < 2; ++k) {
        const std::vector<float> uv = reader.read(uv_names[k], kTexcoord, n);
        uv_out[k]->reserve(uv.size() / 2);
        for (size_t i = 0; i + 1 < uv.size(); i += 2) uv_out[k]->push_back({uv[i], uv[i + 1]});
    }
    int color_components = 0;
    const std::vector<float> colors = reader.read("COLOR_0", kColor, n, &color_components);
    const size_t cc = size_t(color_components);
    if (cc > 0) mesh.colors.reserve(colors.size() / cc);
    for (size_t i = 0; cc > 0 && i + cc <= colors.size(); i += cc)
        mesh.colors.push_back(
            {colors[i], colors[i + 1], colors[i + 2], cc == 4 ? colors[i + 3] : 1.0f});

    std::vector<uint32_t> indices;
    if (prim.indices >= 0 || prim.indices < -1) {
        const tinygltf::Accessor& a = get_accessor(ctx, el, "indices", prim.indices);
        if (a.type != TINYGLTF_TYPE_SCALAR || a.normalized ||
            (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            ctx.fail(el, "indices accessor " + std::to_string(prim.indices) + " is " +
                             describe_accessor(a) +
                             "; expected SCALAR of unsigned byte, short or int");
        indices = read_uints(ctx, prim.indices);
        for (uint32_t i : indices)
            if (i >= n)
                ctx.fail(el, "index " + std::to_string(i) + " out of range (" + std::to_string(n) +
                                 " vertices)");
    } else {
        indices.resize(n);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    mesh.indices = to_triangle_list(checks, el, mode, indices);
    if (mesh.indices.empty()) {
        checks.no_triangles(el);
        return false;
    }
    check_emitter_winding(ctx, prim.material, mesh);
    if (mesh.normals.empty()) {
        // Skins and morph targets address the file's vertices, which make_flat splits.
        if (!prim.targets.empty() || prim.attributes.count("JOINTS_0"))
            origin.source_vertex = mesh.indices;
        make_flat(mesh);
    }
    for (const Vec3& p : mesh.positions) mesh.bounds.expand(p);
    return true;
}

}  // namespace

void load_meshes(const GltfContext& ctx, Scene& scene, std::vector<MeshOrigin>& origins,
                 MeshChecks& checks) {
    const tinygltf::Model& m = ctx.model;
    for (size_t i = 0; i < m.meshes.size(); ++i) {
        const tinygltf::Mesh& gm = m.meshes[i];
        Object object;
        object.name = gm.name.empty() ? element("meshes", i) : gm.name;
        for (size_t j = 0; j < gm.primitives.size(); ++j) {
            const std::string el = element("meshes", i) + "." + element("primitives", j);
            const tinygltf::Primitive& prim = gm.primitives[j];
            TriangleMesh mesh;
            MeshOrigin origin{int(i), int(j), {}};
            if (!build_primitive(ctx, checks, prim, el, mesh, origin)) continue;
            if (gm.name.empty())
                mesh.name = el;
            else if (gm.primitives.size() == 1)
                mesh.name = gm.name;
            else
                mesh.name = gm.name + "." + element("primitives", j);
            object.bounds.expand(mesh.bounds);
            object.meshes.push_back(uint32_t(scene.meshes.size()));
            scene.meshes.push_back(std::move(mesh));
            origins.push_back(std::move(origin));
        }
        scene.objects.push_back(std::move(object));
    }
}

}  // namespace penumbra
