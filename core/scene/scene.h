// The renderable scene as plain data: triangle meshes, the objects (glTF meshes) that
// group them, instances placing objects in the world, materials, textures, cameras and
// lights. io/ builds it; accelerators, cameras and integrators read it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/lights/light.h"
#include "core/math/bounds.h"
#include "core/math/transform.h"
#include "core/scene/material_desc.h"
#include "core/texture.h"

namespace penumbra {

// One glTF primitive: an indexed triangle list with one material, in object space.
struct TriangleMesh {
    std::string name;             // "meshes[i].primitives[j]" or the mesh name
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;    // per vertex; generated when the file has none
    std::vector<Vec2> uv0, uv1;   // TEXCOORD_0/1; empty when absent
    std::vector<Vec4> tangents;   // xyz, w = bitangent sign; empty when absent
    std::vector<Vec4> colors;     // COLOR_0 as linear RGBA; empty when absent
    std::vector<uint32_t> indices;  // 3 per triangle
    int material = -1;              // index into Scene::materials; -1: glTF default
    Bounds3 bounds;                 // with motion: of every time step
    // Deformation motion (skins, morph targets): empty for a mesh that does not deform
    // within the shutter. Otherwise K >= 2 time steps at normalized shutter times
    // k / (K - 1), as Embree's time-sampled geometry; step 0 equals positions/normals.
    // Positions and normals between steps are interpolated linearly (Embree's rule).
    std::vector<std::vector<Vec3>> motion_positions;
    std::vector<std::vector<Vec3>> motion_normals;

    size_t triangle_count() const { return indices.size() / 3; }
};

// One glTF mesh: the meshes it is made of. Built once per accelerator, shared by all
// instances that place it.
struct Object {
    std::string name;
    std::vector<uint32_t> meshes;  // indices into Scene::meshes
    Bounds3 bounds;                // object space
};

// KHR_node_visibility over the shutter: visible at shutter open or not, and the
// normalized shutter times at which that flips (a STEP curve's keys), increasing.
struct TimedVisibility {
    bool at_open = true;
    std::vector<float> flips;

    bool constant() const { return flips.empty(); }
    bool at(float time) const {
        bool v = at_open;
        for (float f : flips) {
            if (time < f) break;
            v = !v;
        }
        return v;
    }
};

// A node that references an object, with its flattened world transform.
struct Instance {
    uint32_t object = 0;
    Transform to_world;  // with motion: the transform at shutter open (= motion[0])
    int node = -1;  // glTF node index, for messages and AOVs
    std::string name;
    // Transform motion: empty for an instance that does not move within the shutter.
    // Otherwise K >= 2 world transforms at normalized shutter times k / (K - 1), the
    // time steps Embree receives (as quaternion decompositions, so rotations do not
    // shrink objects). core/scene/motion.h interpolates them at a ray's time.
    std::vector<Transform> motion;
    // Shown for part of the shutter only (an instance hidden throughout is not made).
    TimedVisibility visibility;
};

enum class ProjectionType { Perspective, Orthographic };

// A camera as the file describes it. The image size is chosen at render time.
struct CameraDesc {
    std::string name;
    ProjectionType type = ProjectionType::Perspective;
    float yfov = 0.8f;        // perspective: vertical field of view, radians
    float aspect_ratio = 0;   // perspective: width / height; 0 when the file gives none
    float xmag = 1, ymag = 1; // orthographic: half the view's width and height
    float znear = 0.01f;
    float zfar = 0;           // 0: infinite
    Transform to_world;       // camera looks down its local -Z, +Y up (glTF)
    // Camera motion, as Instance::motion: empty when the camera does not move within
    // the shutter.
    std::vector<Transform> motion;
    // A field of view animated within the shutter (KHR_animation_pointer): yfov
    // (perspective) or ymag (orthographic) at K >= 2 normalized shutter times
    // k / (K - 1), the nearest taken per sample; empty otherwise.
    std::vector<float> view_steps;
    int node = -1;
    // Thin lens (perspective only). aperture_radius 0 is a pinhole. From the file's
    // EXT_cameras_sensor / camera extras when present, else overridden on the command line.
    float aperture_radius = 0;     // world units
    float focus_distance = 0;      // along the view axis, world units; 0: unset
    int aperture_blades = 0;       // 0: circular aperture; >= 3: regular polygon
    float blade_rotation = 0;      // radians
    float sensor_height_mm = 24;   // for f-stop to aperture conversion (full frame)
};

// The scene one frame before and one frame after the rendered frame (its shutter_open),
// as far as motion vectors (Aov::Vector) need it: where each instance, each deforming
// mesh's vertices and each camera are then. Loaded only when the Vector AOV is asked for.
struct NeighbourFrame {
    double time = 0;  // animation seconds
    // Scene::instances[i]'s object-to-world matrix at `time` (a matrix, not a Transform:
    // a node scaled to zero then is no error, and only points are mapped); empty where no
    // instance moves (each is at its to_world then too).
    std::vector<Mat4> instances;
    // Scene::meshes[m]'s vertex positions at `time` (object space), for m below size();
    // empty, or missing past the end, for a mesh whose vertices are its positions then too
    // (every mesh that does not deform).
    std::vector<std::vector<Vec3>> positions;
    // Scene::cameras[c] at `time`: placed, and with its field of view then.
    std::vector<CameraDesc> cameras;
};

struct FrameNeighbours {
    NeighbourFrame previous, next;
};

struct Scene {
    std::string source;  // file the scene came from
    std::string generator;  // the tool that wrote it (glTF asset.generator), for messages
    std::vector<TriangleMesh> meshes;
    std::vector<Object> objects;
    std::vector<Instance> instances;
    std::vector<MaterialDesc> materials;
    std::vector<TextureImage> images;  // the textures' images, at their own precision
    std::vector<Texture> textures;
    std::vector<CameraDesc> cameras;
    std::vector<std::unique_ptr<Light>> lights;
    // The exposure interval in the glTF animation's seconds: a ray's normalized time
    // u in [0, 1] is the instant shutter_open + u * (shutter_close - shutter_open).
    // Equal for a still (the default: both 0, the scene as its nodes place it).
    double shutter_open = 0, shutter_close = 0;
    // Materials that change within the shutter (KHR_animation_pointer): material_steps[m]
    // lists K >= 2 material indices, material m at normalized shutter times k / (K - 1),
    // and a hit at time u takes the nearest (the composite trapezoid rule over the
    // shutter). Empty, or empty for m, where nothing changes.
    std::vector<std::vector<int>> material_steps;
    // The material of an instance's hits while it is hidden: no coverage (MASK with an
    // infinite cutoff), so rays pass through as through a cut-out; -1 when unused.
    int hidden_material = -1;
    // Whether a hit's material depends on its time (either of the above).
    bool timed_materials = false;
    // Motion vectors' other frames; empty unless the loader was asked for them
    // (GltfLoadOptions::neighbour_frame_offset).
    std::optional<FrameNeighbours> frame_neighbours;

    // World-space bounds of all instances, over the whole shutter for moving ones.
    Bounds3 bounds() const;
    // Whether any instance, mesh or camera has time steps (motion.h).
    bool has_motion() const;
    size_t triangle_count() const;  // counting each instance's triangles
    // Inline: every hit looks its material up.
    const MaterialDesc& material(int index) const {
        return index >= 0 ? materials[size_t(index)] : default_material();
    }
    static const MaterialDesc& default_material();  // glTF's, for primitives without one
    // The material index a hit on `instance` with mesh material `material` uses at
    // normalized shutter time `time`; `material` itself unless timed_materials.
    int material_at(uint32_t instance, int material, float time) const {
        return timed_materials ? timed_material(instance, material, time) : material;
    }
    int timed_material(uint32_t instance, int material, float time) const;
    // Whether `material` emits at some time in the shutter.
    bool may_emit(int material) const;
    // Whether material_at can give `material` another index on `instance`.
    bool material_varies(uint32_t instance, int material) const;
};

}  // namespace penumbra
