// The chosen glTF scene's node tree to Instances, CameraDescs and KHR_lights_punctual
// lights, each with its flattened world transform (parent * local), and for those that
// move within the shutter, their world transforms at its time steps (gltf_node_motion.h).
// KHR_node_visibility leaves out what is hidden throughout the shutter and times what is
// hidden for part of it; lights and cameras take their KHR_animation_pointer values
// (gltf_property_animation.h). A light that changes or moves within the shutter is a
// SteppedLight.
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "core/lights/directional_light.h"
#include "core/lights/point_light.h"
#include "core/lights/spot_light.h"
#include "core/lights/stepped_light.h"
#include "core/camera/thin_lens_camera.h"
#include "io/gltf/gltf_context.h"
#include "io/gltf/animation/gltf_deform.h"
#include "io/gltf/gltf_instancing.h"
#include "io/gltf/animation/gltf_node_motion.h"
#include "io/gltf/animation/gltf_node_visibility.h"
#include "io/gltf/animation/gltf_property_animation.h"

namespace penumbra {

namespace {

// A light node found during traversal; lights are made after all instances are known,
// because a directional light needs the scene's radius.
struct LightNode {
    int light;
    int node;
    Transform to_world;  // at shutter open
    bool moves = false;  // within the shutter
};

bool all_finite(const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

// glTF 2.0, section 3.5.3: `matrix`, or T * R * S with identity defaults.
Transform local_transform(const GltfContext& ctx, const std::string& el, const tinygltf::Node& n) {
    if (!all_finite(n.matrix) || !all_finite(n.translation) || !all_finite(n.rotation) ||
        !all_finite(n.scale))
        ctx.fail(el, "transform is not finite");
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) ctx.fail(el, "matrix must have 16 numbers");
        return Transform(Mat4::from_column_major(n.matrix.data()));
    }
    Vec3 t(0, 0, 0), s(1, 1, 1);
    Quat r;
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) ctx.fail(el, "translation must have 3 numbers");
        t = {float(n.translation[0]), float(n.translation[1]), float(n.translation[2])};
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) ctx.fail(el, "rotation must have 4 numbers");
        r = {float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]),
             float(n.rotation[3])};
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) ctx.fail(el, "scale must have 3 numbers");
        s = {float(n.scale[0]), float(n.scale[1]), float(n.scale[2])};
    }
    return Transform::trs(t, r, s);
}

// The rigid part of a world transform: rotation orthonormalized (Gram-Schmidt from the
// -Z view axis, then +Y up) and translation kept. Cameras must not inherit scale.
Transform rigid(const Transform& t) {
    const Mat4& m = t.matrix();
    const Vec3 y_axis(m(0, 1), m(1, 1), m(2, 1));
    const Vec3 z_axis(m(0, 2), m(1, 2), m(2, 2));
    const Vec3 z = normalize(z_axis);
    const Vec3 y = normalize(y_axis - dot(y_axis, z) * z);
    const Vec3 x = cross(y, z);
    Mat4 r = Mat4::identity();
    for (int i = 0; i < 3; ++i) {
        r(i, 0) = x[i];
        r(i, 1) = y[i];
        r(i, 2) = z[i];
        r(i, 3) = m(i, 3);
    }
    return Transform(r);
}

// A number in a JSON object, if present; anything but a finite number is an error.
std::optional<float> lens_number(const GltfContext& ctx, const std::string& el,
                                 const tinygltf::Value& obj, const char* key) {
    if (!obj.IsObject() || !obj.Has(key)) return std::nullopt;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()) || v.GetNumberAsDouble() < 0)
        ctx.fail(el, std::string(key) + " must be a non-negative number");
    return float(v.GetNumberAsDouble());
}

// Depth of field. glTF core has no lens; we read, in order of precedence, the
// EXT_cameras_sensor extension (sensorHeight in mm, fStop, focusDistance in metres) and
// the camera's extras (aperture_radius in metres, or fstop; focus_distance; blades;
// sensor_height_mm). See docs/conventions.md.
void read_lens(const GltfContext& ctx, const std::string& el, const tinygltf::Camera& gc,
               CameraDesc& c) {
    float fstop = 0;
    const tinygltf::Value& x = gc.extras;
    if (auto v = lens_number(ctx, el + ".extras", x, "sensor_height_mm")) c.sensor_height_mm = *v;
    if (auto v = lens_number(ctx, el + ".extras", x, "fstop")) fstop = *v;
    if (auto v = lens_number(ctx, el + ".extras", x, "aperture_radius")) c.aperture_radius = *v;
    if (auto v = lens_number(ctx, el + ".extras", x, "focus_distance")) c.focus_distance = *v;
    if (auto v = lens_number(ctx, el + ".extras", x, "blades")) c.aperture_blades = int(*v);
    const auto it = gc.extensions.find("EXT_cameras_sensor");
    if (it != gc.extensions.end()) {
        const std::string ext = el + ".extensions.EXT_cameras_sensor";
        if (auto v = lens_number(ctx, ext, it->second, "sensorHeight")) c.sensor_height_mm = *v;
        if (auto v = lens_number(ctx, ext, it->second, "fStop")) fstop = *v;
        if (auto v = lens_number(ctx, ext, it->second, "focusDistance")) c.focus_distance = *v;
    }
    if (fstop > 0 && c.aperture_radius == 0 && c.type == ProjectionType::Perspective)
        c.aperture_radius = aperture_radius_from_fstop(fstop, c.yfov, c.sensor_height_mm);
}

// Camera `index` as `gc` describes it (the file's, or a copy with animated values).
CameraDesc make_camera(const GltfContext& ctx, int index, const tinygltf::Camera& gc,
                       const tinygltf::Node& node, const Transform& world) {
    const std::string el = element("cameras", size_t(index));
    CameraDesc c;
    c.name = !gc.name.empty() ? gc.name : !node.name.empty() ? node.name : el;
    if (gc.type == "perspective") {
        const auto& p = gc.perspective;
        if (!(p.yfov > 0 && p.yfov < kPi))
            ctx.fail(el, "perspective.yfov " + std::to_string(p.yfov) + " not in (0, pi)");
        if (!(p.aspectRatio >= 0)) ctx.fail(el, "perspective.aspectRatio must be > 0");
        if (!(p.znear > 0)) ctx.fail(el, "perspective.znear must be > 0");
        c.type = ProjectionType::Perspective;
        c.yfov = float(p.yfov);
        c.aspect_ratio = float(p.aspectRatio);
        c.znear = float(p.znear);
        c.zfar = float(p.zfar);
    } else if (gc.type == "orthographic") {
        const auto& o = gc.orthographic;
        if (!(o.xmag != 0 && o.ymag != 0 && std::isfinite(o.xmag) && std::isfinite(o.ymag)))
            ctx.fail(el, "orthographic.xmag and ymag must be nonzero");
        c.type = ProjectionType::Orthographic;
        c.xmag = float(std::abs(o.xmag));
        c.ymag = float(std::abs(o.ymag));
        c.znear = float(o.znear);
        c.zfar = float(o.zfar);
    } else {
        ctx.fail(el, "type '" + gc.type + "' is not perspective or orthographic");
    }
    c.to_world = rigid(world);
    read_lens(ctx, el, gc, c);
    return c;
}

// The KHR_lights_punctual light a node references, or -1.
int node_light(const GltfContext& ctx, const std::string& el, const tinygltf::Node& node) {
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return -1;
    const tinygltf::Value& ext = it->second;
    if (!ext.IsObject() || !ext.Get("light").IsNumber())
        ctx.fail(el, "extensions.KHR_lights_punctual.light must be an index");
    const int index = ext.Get("light").GetNumberAsInt();
    ctx.check_index(el, "KHR_lights_punctual light", index, ctx.model.lights.size(), "lights");
    return index;
}

// KHR_lights_punctual: intensity in candela (point, spot) or lux (directional), times
// colour, to W/sr or W/m^2 as ctx.light_units says (core/lights/light_units.h). `range`
// is ignored: we keep the physical inverse-square falloff everywhere.
std::unique_ptr<Light> make_light(const GltfContext& ctx, const tinygltf::Light& gl,
                                  const LightNode& ln, float scene_radius) {
    const std::string el = "extensions.KHR_lights_punctual." + element("lights", size_t(ln.light));
    Spectrum color(1, 1, 1);
    if (!gl.color.empty()) {
        if (gl.color.size() != 3) ctx.fail(el, "color must have 3 numbers");
        color = {float(gl.color[0]), float(gl.color[1]), float(gl.color[2])};
    }
    if (!(gl.intensity >= 0) || !std::isfinite(gl.intensity))
        ctx.fail(el, "intensity must be a finite number >= 0");
    const Spectrum I =
        ctx.rec709_to_working * color * float(gl.intensity * radiometric_scale(ctx.light_units));
    const Vec3 position = ln.to_world.point(Vec3(0, 0, 0));
    const Vec3 axis = ln.to_world.vector(Vec3(0, 0, -1));
    if (gl.type == "point") return std::make_unique<PointLight>(position, I);
    if (!(length_squared(axis) > 0))
        ctx.fail(element("nodes", size_t(ln.node)), "light direction is degenerate");
    if (gl.type == "directional")
        return std::make_unique<DirectionalLight>(normalize(axis), I, scene_radius);
    if (gl.type == "spot") {
        const double inner = gl.spot.innerConeAngle, outer = gl.spot.outerConeAngle;
        if (!(inner >= 0 && inner <= outer && outer <= kPi / 2 + 1e-6))
            ctx.fail(el,
                     "spot cone angles must satisfy 0 <= innerConeAngle <= "
                     "outerConeAngle <= pi/2");
        return std::make_unique<SpotLight>(position, normalize(axis), I, float(inner),
                                           float(outer));
    }
    ctx.fail(el, "type '" + gl.type + "' is not point, spot or directional");
}

// The instances of node `index`'s mesh: one, or EXT_mesh_gpu_instancing's, or a skinned
// copy in world space; shown for part of the shutter where `vis` flips.
void add_node_mesh(const GltfContext& ctx, const NodeMotion& motion, int index,
                   const Transform& world, const std::vector<Transform>& steps,
                   const TimedVisibility& vis, const std::vector<MeshOrigin>& origins,
                   Scene& scene, std::vector<std::string>& instanced_skinned) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(index)];
    const std::string el = element("nodes", size_t(index));
    ctx.check_index(el, "mesh", node.mesh, ctx.model.meshes.size(), "meshes");
    const size_t first = scene.instances.size();
    const std::optional<DeformedObject> deformed =
        scene.objects[size_t(node.mesh)].meshes.empty()
            ? std::nullopt
            : add_deformed_object(ctx, motion, index, origins, scene);
    // A skinned mesh is already in world space; its node's transform and motion are
    // ignored. EXT_mesh_gpu_instancing defines no instance transform for it.
    const bool world_space = deformed && deformed->world_space;
    if (world_space && node.extensions.count("EXT_mesh_gpu_instancing"))
        instanced_skinned.push_back(el);
    const uint32_t object = deformed ? deformed->object : uint32_t(node.mesh);
    if (!scene.objects[size_t(node.mesh)].meshes.empty() &&
        (world_space || !add_gpu_instances(ctx, el, node, index, object, world, steps, scene))) {
        Instance inst;
        inst.object = object;
        inst.to_world = world_space ? Transform() : world;
        if (!world_space) inst.motion = steps;
        inst.node = index;
        inst.name = node.name.empty() ? el : node.name;
        scene.instances.push_back(std::move(inst));
    }
    if (vis.constant() || scene.instances.size() == first) return;
    for (size_t i = first; i < scene.instances.size(); ++i) scene.instances[i].visibility = vis;
    if (scene.hidden_material < 0) {
        MaterialDesc hidden;
        hidden.name = "hidden (KHR_node_visibility)";
        hidden.alpha_mode = AlphaMode::Mask;
        hidden.alpha_cutoff = INFINITY;
        scene.hidden_material = int(scene.materials.size());
        scene.materials.push_back(hidden);
    }
    scene.timed_materials = true;
}

// The light of `ln` over the shutter: its animated values and visibility at shutter
// open, or a SteppedLight where they change or the node moves within the shutter; nullptr
// when it is hidden throughout.
std::unique_ptr<Light> make_scene_light(const GltfContext& ctx, const NodeMotion& motion,
                                        const NodeVisibility& visibility, const LightNode& ln,
                                        float scene_radius) {
    const tinygltf::Light& file = ctx.model.lights[size_t(ln.light)];
    const std::vector<PropertyChannel> channels =
        usable_channels(ctx, "extensions/KHR_lights_punctual/" + element("lights", size_t(ln.light)),
                        file, motion.animations().properties(PointerObject::Light, ln.light));
    const Shutter& s = motion.shutter();
    const TimedVisibility vis = visibility.over_shutter(ln.node);
    if (!changes_within(channels, s) && vis.constant() && !ln.moves)
        return vis.at_open ? make_light(ctx, animated(file, channels, s.open), ln, scene_radius)
                           : nullptr;
    std::vector<std::unique_ptr<Light>> steps;
    bool any = false;
    for (int k = 0; k < kPropertySteps; ++k) {
        const double t = s.time(k, kPropertySteps);
        if (!vis.at(float(k) / float(kPropertySteps - 1))) {
            steps.push_back(nullptr);
            continue;
        }
        LightNode step = ln;
        if (ln.moves) step.to_world = Transform(motion.world(ln.node, t));
        steps.push_back(make_light(ctx, animated(file, channels, t), step, scene_radius));
        any = true;
    }
    return any ? std::make_unique<SteppedLight>(std::move(steps)) : nullptr;
}

// The camera of node `index` with its animated values at shutter open, and its field of
// view per time step where that changes within the shutter.
CameraDesc make_scene_camera(const GltfContext& ctx, const NodeMotion& motion, int index,
                             const Transform& world, const std::vector<Transform>& steps) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(index)];
    const tinygltf::Camera& file = ctx.model.cameras[size_t(node.camera)];
    const std::vector<PropertyChannel> channels =
        usable_channels(ctx, element("cameras", size_t(node.camera)), file,
                        motion.animations().properties(PointerObject::Camera, node.camera));
    const Shutter& s = motion.shutter();
    CameraDesc c = make_camera(ctx, node.camera, animated(file, channels, s.open), node, world);
    if (changes_within(channels, s))
        for (int k = 0; k < kPropertySteps; ++k) {
            const CameraDesc at = make_camera(
                ctx, node.camera, animated(file, channels, s.time(k, kPropertySteps)), node, world);
            c.view_steps.push_back(c.type == ProjectionType::Orthographic ? at.ymag : at.yfov);
        }
    for (const Transform& step : steps) c.motion.push_back(rigid(step));
    c.node = index;
    return c;
}

// Motion vectors: the camera of node `index` at the neighbouring frames, placed and with
// its field of view then (Scene::frame_neighbours). `world`: the node's still transform.
void add_neighbour_cameras(const GltfContext& ctx, const NodeMotion& motion, int index,
                           const Transform& world, FrameNeighbours& neighbours) {
    const tinygltf::Node& node = ctx.model.nodes[size_t(index)];
    const tinygltf::Camera& file = ctx.model.cameras[size_t(node.camera)];
    const std::vector<PropertyChannel> channels =
        usable_channels(ctx, element("cameras", size_t(node.camera)), file,
                        motion.animations().properties(PointerObject::Camera, node.camera));
    for (NeighbourFrame* f : {&neighbours.previous, &neighbours.next}) {
        // A camera scaled to zero then keeps its pose at the frame: it has no view to give.
        Transform at = world;
        if (motion.moves(index)) {
            try {
                at = Transform(motion.world(index, f->time));
            } catch (const std::invalid_argument&) {
            }
        }
        CameraDesc c = make_camera(ctx, node.camera, animated(file, channels, f->time), node, at);
        c.node = index;
        f->cameras.push_back(std::move(c));
    }
}

// glTF 2.0, section 3.7.3.1: a skin's joints and skeleton root belong to the scene that
// draws it (the validator's NODE_SKIN_NO_SCENE). Outside it their pose is undefined:
// three.js draws such a skin collapsed, and we pose those nodes from their own transforms
// and parents. One warning names each such skin and its nodes outside the scene.
void warn_skins_outside_scene(const GltfContext& ctx, int scene_index,
                              const std::vector<bool>& visited) {
    const tinygltf::Model& m = ctx.model;
    std::set<int> skins;  // drawn in this scene
    for (size_t i = 0; i < m.nodes.size(); ++i)
        if (visited[i] && m.nodes[i].mesh >= 0 && m.nodes[i].skin >= 0 &&
            size_t(m.nodes[i].skin) < m.skins.size())
            skins.insert(m.nodes[i].skin);
    if (skins.empty()) return;
    // The scene's tree, including subtrees the traversal skipped under a zero scale (the
    // tree has been checked: indices in range, no node reached twice).
    std::vector<bool> reached(m.nodes.size(), false);
    std::vector<int> stack = m.scenes[size_t(scene_index)].nodes;
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (reached[size_t(n)]) continue;
        reached[size_t(n)] = true;
        for (int c : m.nodes[size_t(n)].children)
            if (c >= 0 && size_t(c) < m.nodes.size()) stack.push_back(c);
    }
    auto outside = [&](int n) {
        return n >= 0 && size_t(n) < m.nodes.size() && !reached[size_t(n)];
    };
    auto node_name = [&](int n) {
        const std::string& name = m.nodes[size_t(n)].name;
        return element("nodes", size_t(n)) + (name.empty() ? "" : " '" + name + "'");
    };
    std::vector<std::string> items;
    for (int s : skins) {
        const tinygltf::Skin& skin = m.skins[size_t(s)];
        std::vector<std::string> joints;
        for (int j : skin.joints)
            if (outside(j)) joints.push_back(node_name(j));
        const bool root = outside(skin.skeleton);
        if (joints.empty() && !root) continue;
        std::string item =
            element("skins", size_t(s)) + (skin.name.empty() ? "" : " '" + skin.name + "'") + ": ";
        if (root)
            item += "its skeleton root " + node_name(skin.skeleton) +
                    (joints.empty() ? "" : " and ");
        if (!joints.empty())
            item += std::to_string(joints.size()) + " of its " +
                    std::to_string(skin.joints.size()) + " joints" + examples(joints);
        items.push_back(item);
    }
    if (items.empty()) return;
    std::string list;
    for (const std::string& item : items) list += (list.empty() ? "" : "; ") + item;
    ctx.warn("skins", std::to_string(items.size()) + " skin(s) drawn in " +
                          element("scenes", size_t(scene_index)) +
                          " have nodes outside it, so their pose is undefined (" + list +
                          "); those nodes are posed from their own transforms and parents");
}

}  // namespace

void load_nodes(const GltfContext& ctx, int scene_index, const NodeMotion& motion,
                const std::vector<MeshOrigin>& origins, Scene& scene) {
    const tinygltf::Model& m = ctx.model;
    const std::string sel = element("scenes", size_t(scene_index));
    const NodeVisibility visibility(ctx, motion);
    std::vector<bool> visited(m.nodes.size(), false);
    std::vector<LightNode> lights;
    // Renderable but surprising: one summary warning per kind, after the tree.
    std::vector<std::string> singular, instanced_skinned;
    // Depth-first with an explicit stack, so that deep hierarchies cannot overflow the
    // call stack; each entry is a node and its parent's world transform.
    std::vector<std::pair<int, Transform>> stack;
    const std::vector<int>& roots = m.scenes[size_t(scene_index)].nodes;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        ctx.check_index(sel, "node", *it, m.nodes.size(), "nodes");
        stack.emplace_back(*it, Transform());
    }
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const std::string el = element("nodes", size_t(index));
        if (visited[size_t(index)])
            ctx.fail(el, "reached twice in the node tree (a cycle, or a node with two parents)");
        visited[size_t(index)] = true;
        const tinygltf::Node& node = m.nodes[size_t(index)];
        Transform world;
        // World transforms at the shutter's time steps; empty: still within the shutter.
        std::vector<Transform> steps;
        try {
            const Transform local = local_transform(ctx, el, node);
            if (motion.moves(index)) {
                // Animated (or under an animated parent): the pose at shutter open.
                steps = motion.world_motion(index);
                world = steps.empty() ? Transform(motion.world(index, motion.shutter().open))
                                      : steps.front();
            } else {
                world = parent * local;
            }
        } catch (const std::invalid_argument&) {
            // Zero scale is valid glTF (it hides a subtree); nothing below can be seen.
            singular.push_back(el);
            continue;
        }
        const TimedVisibility vis = visibility.over_shutter(index);
        const bool shown = vis.at_open || !vis.constant();
        if (node.mesh != -1 && shown)
            add_node_mesh(ctx, motion, index, world, steps, vis, origins, scene, instanced_skinned);
        if (node.camera != -1) {
            ctx.check_index(el, "camera", node.camera, m.cameras.size(), "cameras");
            scene.cameras.push_back(make_scene_camera(ctx, motion, index, world, steps));
            if (scene.frame_neighbours)
                add_neighbour_cameras(ctx, motion, index, world, *scene.frame_neighbours);
        }
        const int light = node_light(ctx, el, node);
        if (light >= 0 && shown) lights.push_back({light, index, world, !steps.empty()});
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
            ctx.check_index(el, "child node", *it, m.nodes.size(), "nodes");
            stack.emplace_back(*it, world);
        }
    }

    warn_skins_outside_scene(ctx, scene_index, visited);
    if (!singular.empty())
        ctx.warn("nodes", std::to_string(singular.size()) +
                              " node(s) have a singular transform (zero scale?) at a time "
                              "step; their subtrees are skipped" +
                              examples(singular));
    if (!instanced_skinned.empty())
        ctx.warn("nodes", std::to_string(instanced_skinned.size()) +
                              " node(s) use EXT_mesh_gpu_instancing on a skinned mesh, which "
                              "has no instance transform: one skinned copy is drawn" +
                              examples(instanced_skinned));

    const Bounds3 bounds = scene.bounds();
    const float radius = bounds.empty() ? 1.0f : std::max(1.0f, 0.5f * length(bounds.diagonal()));
    for (const LightNode& ln : lights)
        if (std::unique_ptr<Light> light = make_scene_light(ctx, motion, visibility, ln, radius))
            scene.lights.push_back(std::move(light));
}

}  // namespace penumbra
