#include "io/gltf/animation/gltf_deform.h"

#include <cmath>
#include <map>

#include "io/gltf/gltf_accessor.h"
#include "io/gltf/animation/gltf_skin_weights.h"

namespace penumbra {

namespace {

Vec3 point(const Mat4& m, Vec3 p) {
    return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.z + m(0, 3),
            m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.z + m(1, 3),
            m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.z + m(2, 3)};
}

// The normal through m's linear part: the inverse transpose, up to a positive scale
// (the cofactor matrix times the determinant's sign), so no division by a small
// determinant and mirrored joints keep normals on the right side.
Vec3 normal(const Mat4& m, Vec3 n) {
    const Vec3 c0(m(0, 0), m(1, 0), m(2, 0)), c1(m(0, 1), m(1, 1), m(2, 1)),
        c2(m(0, 2), m(1, 2), m(2, 2));
    const Vec3 r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
    const float sign = dot(c0, r0) < 0 ? -1.0f : 1.0f;
    const Vec3 out = sign * (r0 * n.x + r1 * n.y + r2 * n.z);
    const float len = length(out);
    return len > 0 ? out / len : n;
}

std::vector<Vec3> to_vec3(const std::vector<float>& v) {
    std::vector<Vec3> out(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

// A morph target's POSITION or NORMAL displacements (VEC3; float or, with
// KHR_mesh_quantization, normalized integers); empty when the target lacks it.
std::vector<Vec3> read_target(const GltfContext& ctx, const std::string& el,
                              const std::map<std::string, int>& target, const char* name,
                              size_t vertices) {
    const auto it = target.find(name);
    if (it == target.end()) return {};
    const tinygltf::Accessor& a = get_accessor(ctx, el, name, it->second);
    if (a.type != TINYGLTF_TYPE_VEC3)
        ctx.fail(el, std::string(name) + " accessor " + std::to_string(it->second) + " is " +
                         describe_accessor(a) + "; expected VEC3");
    if (a.count != vertices)
        ctx.fail(el, std::string(name) + " accessor has " + std::to_string(a.count) +
                         " elements, POSITION has " + std::to_string(vertices));
    std::vector<Vec3> d = to_vec3(read_floats(ctx, it->second));
    for (size_t i = 0; i < d.size(); ++i)
        if (!is_finite(d[i]))
            ctx.fail(el, std::string(name) + " element " + std::to_string(i) + " is not finite");
    return d;
}

// One primitive's inputs to deformation, per file vertex.
struct PrimitiveDeformation {
    std::vector<std::vector<Vec3>> dp, dn;  // per target: POSITION and NORMAL offsets
    SkinWeights skin;                       // normalised; empty without a skin
    size_t vertices = 0;                    // in the file's primitive
};

PrimitiveDeformation read_primitive(const GltfContext& ctx, const MeshOrigin& origin,
                                    size_t joint_count) {
    const tinygltf::Primitive& prim =
        ctx.model.meshes[size_t(origin.mesh)].primitives[size_t(origin.primitive)];
    const std::string el = element("meshes", size_t(origin.mesh)) + "." +
                           element("primitives", size_t(origin.primitive));
    const size_t n = ctx.model.accessors[size_t(prim.attributes.at("POSITION"))].count;
    PrimitiveDeformation d;
    d.vertices = n;
    for (size_t t = 0; t < prim.targets.size(); ++t) {
        const std::string tel = el + "." + element("targets", t);
        d.dp.push_back(read_target(ctx, tel, prim.targets[t], "POSITION", n));
        d.dn.push_back(read_target(ctx, tel, prim.targets[t], "NORMAL", n));
    }
    if (joint_count > 0) d.skin = read_skin_weights(ctx, el, prim, n, joint_count);
    return d;
}

// The skin's joints and inverse bind matrices, validated.
struct Skin {
    std::vector<int> joints;
    std::vector<Mat4> inverse_bind;
};

Skin read_skin(const GltfContext& ctx, int index) {
    const tinygltf::Skin& s = ctx.model.skins[size_t(index)];
    const std::string el = element("skins", size_t(index));
    if (s.joints.empty()) ctx.fail(el, "has no joints");
    Skin skin;
    for (int j : s.joints) {
        ctx.check_index(el, "joint node", j, ctx.model.nodes.size(), "nodes");
        skin.joints.push_back(j);
    }
    skin.inverse_bind.assign(s.joints.size(), Mat4::identity());
    if (s.inverseBindMatrices >= 0) {
        const tinygltf::Accessor& a =
            get_accessor(ctx, el, "inverseBindMatrices", s.inverseBindMatrices);
        if (a.type != TINYGLTF_TYPE_MAT4 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            ctx.fail(el, "inverseBindMatrices accessor is " + describe_accessor(a) +
                             "; expected MAT4 of float");
        if (a.count < s.joints.size())
            ctx.fail(el, "inverseBindMatrices has " + std::to_string(a.count) +
                             " matrices for " + std::to_string(s.joints.size()) + " joints");
        const std::vector<float> m = read_floats(ctx, s.inverseBindMatrices);
        for (size_t j = 0; j < s.joints.size(); ++j) {
            double v[16];
            for (int k = 0; k < 16; ++k) {
                v[k] = m[16 * j + size_t(k)];
                if (!std::isfinite(v[k])) ctx.fail(el, "inverseBindMatrices are not all finite");
            }
            skin.inverse_bind[j] = Mat4::from_column_major(v);
        }
    }
    return skin;
}

// The morph weights of the node at time t: its animated weights, else node.weights,
// else mesh.weights, else zeros (glTF 2.0, section 3.7.2.2).
std::vector<double> weights_at(const GltfContext& ctx, const NodeMotion& motion, int node_index,
                               size_t targets, double t) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(node_index)];
    const tinygltf::Mesh& mesh = ctx.model.meshes[size_t(node.mesh)];
    const NodeChannels* nc = motion.animations().node(node_index);
    if (nc && nc->weights) return nc->weights->sample(t);
    const std::vector<double>& w = !node.weights.empty() ? node.weights : mesh.weights;
    if (w.empty()) return std::vector<double>(targets, 0.0);
    return w;
}

// The number of morph targets, the same in every primitive, and weights of that length.
size_t morph_target_count(const GltfContext& ctx, int node_index) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(node_index)];
    const tinygltf::Mesh& gm = ctx.model.meshes[size_t(node.mesh)];
    const std::string el = element("nodes", size_t(node_index));
    const size_t targets = gm.primitives.empty() ? 0 : gm.primitives[0].targets.size();
    for (size_t j = 0; j < gm.primitives.size(); ++j)
        if (gm.primitives[j].targets.size() != targets)
            ctx.fail(element("meshes", size_t(node.mesh)),
                     "primitives have different numbers of morph targets");
    for (const std::vector<double>* w : {&node.weights, &gm.weights})
        if (!w->empty() && w->size() != targets)
            ctx.fail(w == &node.weights ? el : element("meshes", size_t(node.mesh)),
                     "weights has " + std::to_string(w->size()) + " entries for " +
                         std::to_string(targets) + " morph targets");
    return targets;
}

// Morph weights and joint matrices (joint world times inverse bind) at each of some times:
// the shutter's steps, or a motion vector's neighbouring frames.
struct StepInputs {
    std::vector<std::vector<double>> weights;
    std::vector<std::vector<Mat4>> joint_matrices;  // empty per step without a skin
};

StepInputs sample_times(const GltfContext& ctx, const NodeMotion& motion, int node_index,
                        size_t targets, const std::optional<Skin>& skin,
                        const std::vector<double>& times) {
    StepInputs in;
    in.joint_matrices.resize(times.size());
    in.weights.resize(times.size());
    for (size_t k = 0; k < times.size(); ++k) {
        const double t = times[k];
        in.weights[k] = weights_at(ctx, motion, node_index, targets, t);
        if (skin)
            for (size_t j = 0; j < skin->joints.size(); ++j)
                in.joint_matrices[k].push_back(motion.world(skin->joints[j], t) *
                                               skin->inverse_bind[j]);
    }
    return in;
}

StepInputs sample_steps(const GltfContext& ctx, const NodeMotion& motion, int node_index,
                        size_t targets, const std::optional<Skin>& skin, int steps) {
    std::vector<double> times;
    for (int k = 0; k < steps; ++k) times.push_back(motion.shutter().time(k, steps));
    return sample_times(ctx, motion, node_index, targets, skin, times);
}

// Linear blend skinning: sum of weight * joint world * inverse bind, for file vertex v.
Mat4 skin_matrix(const PrimitiveDeformation& d, size_t v, const std::vector<Mat4>& joints) {
    Mat4 m;
    const SkinWeights& sw = d.skin;
    for (size_t set = 0; set < sw.influences; ++set)
        for (int c = 0; c < 4; ++c) {
            const size_t at = set * 4 * d.vertices + 4 * v + size_t(c);
            const float w = sw.weights[at];
            if (w == 0) continue;
            const Mat4& jm = joints[size_t(sw.joints[at])];
            for (int r = 0; r < 4; ++r)
                for (int q = 0; q < 4; ++q) m(r, q) += w * jm(r, q);
        }
    return m;
}

// Flat shading: each triangle's own three vertices carry its face normal.
void set_face_normals(const std::vector<Vec3>& p, std::vector<Vec3>& n) {
    for (size_t t = 0; t + 2 < p.size(); t += 3) {
        const Vec3 f = cross(p[t + 1] - p[t], p[t + 2] - p[t]);
        const float len = length(f);
        const Vec3 u = len > 0 && std::isfinite(len) ? f / len : Vec3(0, 0, 1);
        n[t] = n[t + 1] = n[t + 2] = u;
    }
}

// Morphs, then skins (when `joints` is given), the base mesh's positions and normals at one
// step.
void deform_step(const TriangleMesh& base, const MeshOrigin& origin, const PrimitiveDeformation& d,
                 const std::vector<double>& weights, size_t targets,
                 const std::vector<Mat4>* joints, std::vector<Vec3>& p, std::vector<Vec3>& n) {
    const bool flat = !origin.source_vertex.empty();
    p = base.positions;
    n = base.normals;
    for (size_t i = 0; i < p.size(); ++i) {
        const size_t v = flat ? size_t(origin.source_vertex[i]) : i;
        for (size_t t = 0; t < targets; ++t) {
            const float w = float(weights[t]);
            if (w == 0) continue;
            if (!d.dp[t].empty()) p[i] += w * d.dp[t][v];
            if (!d.dn[t].empty() && !flat) n[i] += w * d.dn[t][v];
        }
        if (joints) {
            const Mat4 m = skin_matrix(d, v, *joints);
            p[i] = point(m, p[i]);
            if (!flat) n[i] = normal(m, n[i]);
        } else if (!flat && length_squared(n[i]) > 0) {
            n[i] = normalize(n[i]);
        }
    }
    if (flat) set_face_normals(p, n);
}

// A copy of `base` carrying one deformed position and normal set per step; the motion sets
// are dropped again when no step moves a vertex.
TriangleMesh deform_mesh(const GltfContext& ctx, const std::string& el, const TriangleMesh& base,
                         const MeshOrigin& origin, const PrimitiveDeformation& d,
                         const StepInputs& in, size_t targets, bool skinned) {
    TriangleMesh mesh = base;
    bool changes = false;
    for (size_t k = 0; k < in.weights.size(); ++k) {
        std::vector<Vec3> p, n;
        deform_step(base, origin, d, in.weights[k], targets,
                    skinned ? &in.joint_matrices[k] : nullptr, p, n);
        if (k > 0) changes = changes || p != mesh.motion_positions[0];
        mesh.motion_positions.push_back(std::move(p));
        mesh.motion_normals.push_back(std::move(n));
    }
    for (const auto& p : mesh.motion_positions)
        for (const Vec3& x : p)
            if (!is_finite(x)) ctx.fail(el, "deformed vertices are not finite");
    mesh.positions = mesh.motion_positions[0];
    mesh.normals = mesh.motion_normals[0];
    mesh.bounds = Bounds3();
    for (const auto& p : mesh.motion_positions)
        for (const Vec3& x : p) mesh.bounds.expand(x);
    if (!changes) {
        mesh.motion_positions.clear();
        mesh.motion_normals.clear();
    }
    return mesh;
}

// Motion vectors: the deformed mesh's positions at the neighbouring frames
// (Scene::frame_neighbours), kept only where they differ from its positions at the frame.
void add_neighbour_positions(const TriangleMesh& base, const TriangleMesh& deformed,
                             uint32_t mesh_index, const MeshOrigin& origin,
                             const PrimitiveDeformation& d, const StepInputs& in,
                             size_t targets, bool skinned, FrameNeighbours& neighbours) {
    NeighbourFrame* frames[2] = {&neighbours.previous, &neighbours.next};
    for (size_t k = 0; k < 2; ++k) {
        std::vector<Vec3> p, n;
        deform_step(base, origin, d, in.weights[k], targets,
                    skinned ? &in.joint_matrices[k] : nullptr, p, n);
        if (p == deformed.positions) continue;
        std::vector<std::vector<Vec3>>& positions = frames[k]->positions;
        if (positions.size() <= mesh_index) positions.resize(size_t(mesh_index) + 1);
        positions[mesh_index] = std::move(p);
    }
}

}  // namespace

std::optional<DeformedObject> add_deformed_object(const GltfContext& ctx, const NodeMotion& motion,
                                                  int node_index,
                                                  const std::vector<MeshOrigin>& origins,
                                                  Scene& scene) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(node_index)];
    const std::string el = element("nodes", size_t(node_index));
    const size_t targets = morph_target_count(ctx, node_index);

    std::vector<const AnimationCurve*> curves;
    const NodeChannels* nc = motion.animations().node(node_index);
    if (nc && nc->weights) curves.push_back(nc->weights);
    std::optional<Skin> skin;
    if (node.skin >= 0) {
        ctx.check_index(el, "skin", node.skin, ctx.model.skins.size(), "skins");
        skin = read_skin(ctx, node.skin);
        for (int j : skin->joints)
            for (const AnimationCurve* c : motion.chain_curves(j)) curves.push_back(c);
    }
    bool morphed = false;
    for (double w : weights_at(ctx, motion, node_index, targets, motion.shutter().open))
        morphed = morphed || w != 0;
    const int steps = motion.steps(curves);
    // Motion vectors see the frames around this one: animated weights may deform the
    // mesh there while it rests at the frame itself.
    const bool neighbours = scene.frame_neighbours.has_value();
    const bool animated_weights = nc && nc->weights;
    if (!skin && !morphed && steps < 2 && !(neighbours && animated_weights)) return std::nullopt;
    const StepInputs in = sample_steps(ctx, motion, node_index, targets, skin, steps);
    StepInputs around;
    if (neighbours)
        around = sample_times(ctx, motion, node_index, targets, skin,
                              {scene.frame_neighbours->previous.time,
                               scene.frame_neighbours->next.time});

    Object object;
    object.name = scene.objects[size_t(node.mesh)].name + " (" + el + ")";
    for (uint32_t mesh_index : scene.objects[size_t(node.mesh)].meshes) {
        const MeshOrigin& origin = origins[mesh_index];
        const PrimitiveDeformation d = read_primitive(ctx, origin, skin ? skin->joints.size() : 0);
        TriangleMesh mesh = deform_mesh(ctx, el, scene.meshes[mesh_index], origin, d, in, targets,
                                        skin.has_value());
        if (neighbours)
            add_neighbour_positions(scene.meshes[mesh_index], mesh, uint32_t(scene.meshes.size()),
                                    origin, d, around, targets, skin.has_value(),
                                    *scene.frame_neighbours);
        object.bounds.expand(mesh.bounds);
        object.meshes.push_back(uint32_t(scene.meshes.size()));
        scene.meshes.push_back(std::move(mesh));
    }
    scene.objects.push_back(std::move(object));
    return DeformedObject{uint32_t(scene.objects.size() - 1), skin.has_value()};
}

}  // namespace penumbra
