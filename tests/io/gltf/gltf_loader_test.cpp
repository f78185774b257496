// load_gltf on the Khronos sample models (exact counts read from their JSON, transforms
// checked against hand-computed values) and on small written scenes: the scene
// structure, cameras and KHR_lights_punctual.
#include "io/gltf/gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

void expect_near(Vec3 a, Vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

struct Counts {
    size_t objects, instances, meshes, triangles, cameras, materials, textures, images;
};

void expect_counts(const Scene& s, const Counts& c) {
    EXPECT_EQ(s.objects.size(), c.objects);
    EXPECT_EQ(s.instances.size(), c.instances);
    EXPECT_EQ(s.meshes.size(), c.meshes);
    EXPECT_EQ(s.triangle_count(), c.triangles);
    EXPECT_EQ(s.cameras.size(), c.cameras);
    EXPECT_EQ(s.materials.size(), c.materials);
    EXPECT_EQ(s.textures.size(), c.textures);
    EXPECT_EQ(s.images.size(), c.images);
    EXPECT_TRUE(s.lights.empty());
}

std::string khronos(const char* name) {
    return test::shared_path(std::string("scenes/khronos/") + name + ".gltf");
}

TEST(GltfLoader, Box) {
    const Scene s = load_gltf(khronos("Box"));
    expect_counts(s, {1, 1, 1, 12, 0, 1, 0, 0});
    EXPECT_EQ(s.source, khronos("Box"));
    const TriangleMesh& m = s.meshes[0];
    EXPECT_EQ(m.positions.size(), 24u);
    EXPECT_EQ(m.normals.size(), 24u);
    EXPECT_EQ(m.material, 0);
    EXPECT_FLOAT_EQ(s.materials[0].base_color.x, 0.8f);
    EXPECT_FLOAT_EQ(s.materials[0].metallic, 1.0f);  // omitted: the spec's default
    expect_near(m.bounds.lo, Vec3(-0.5f));
    expect_near(m.bounds.hi, Vec3(0.5f));
    // The root's matrix maps (x, y, z) to (x, z, -y): vertex 2 is (-0.5, 0.5, 0.5).
    expect_near(m.positions[2], {-0.5f, 0.5f, 0.5f});
    EXPECT_EQ(s.instances[0].node, 1);
    expect_near(s.instances[0].to_world.point(m.positions[2]), {-0.5f, 0.5f, -0.5f});
}

TEST(GltfLoader, BoxTexturedDecodesItsSrgbTexture) {
    const Scene s = load_gltf(khronos("BoxTextured"));
    expect_counts(s, {1, 1, 1, 12, 0, 1, 1, 1});
    const MaterialDesc& mat = s.materials[0];
    ASSERT_TRUE(mat.base_color_texture.valid());
    EXPECT_EQ(mat.base_color_texture.texcoord, 0);
    const Texture& tex = s.textures[size_t(mat.base_color_texture.texture)];
    EXPECT_EQ(tex.wrap_s, WrapMode::Repeat);
    EXPECT_FALSE(tex.nearest);
    const Image img = s.images[tex.image].to_image();
    EXPECT_EQ(img.width, 211);
    EXPECT_EQ(img.height, 211);
    EXPECT_EQ(s.meshes[0].uv0.size(), 24u);
}

TEST(GltfLoader, SimpleMeshesInstancesOneObjectTwice) {
    const Scene s = load_gltf(khronos("SimpleMeshes"));
    expect_counts(s, {1, 2, 1, 2, 0, 0, 0, 0});
    EXPECT_EQ(s.instances[0].object, 0u);
    EXPECT_EQ(s.instances[1].object, 0u);
    EXPECT_EQ(s.meshes[0].material, -1);
    const Vec3 p = s.meshes[0].positions[1];  // (1, 0, 0)
    expect_near(s.instances[0].to_world.point(p), {1, 0, 0});
    expect_near(s.instances[1].to_world.point(p), {2, 0, 0});
    EXPECT_EQ(s.instances[1].name, "nodes[1]");
}

TEST(GltfLoader, BoxAnimatedHierarchy) {
    const Scene s = load_gltf(khronos("BoxAnimated"));
    expect_counts(s, {2, 2, 2, 62 + 192, 0, 2, 0, 0});
    EXPECT_EQ(s.materials[0].name, "inner");
    EXPECT_FLOAT_EQ(s.materials[1].metallic, 0.0f);
    // Scene roots are [3, 0]; node 2 (inner box) sits under 0 -> 1 -> 2.
    EXPECT_EQ(s.instances[0].node, 3);
    EXPECT_EQ(s.instances[1].node, 2);
    EXPECT_EQ(s.objects[s.instances[1].object].name, "inner_box");
}

TEST(GltfLoader, CamerasModel) {
    const Scene s = load_gltf(khronos("Cameras"));
    expect_counts(s, {1, 1, 1, 2, 2, 0, 0, 0});
    const CameraDesc& p = s.cameras[0];
    EXPECT_EQ(p.type, ProjectionType::Perspective);
    EXPECT_FLOAT_EQ(p.yfov, 0.7f);
    EXPECT_FLOAT_EQ(p.aspect_ratio, 1.0f);
    EXPECT_FLOAT_EQ(p.znear, 0.01f);
    EXPECT_FLOAT_EQ(p.zfar, 100.0f);
    EXPECT_EQ(p.node, 1);
    EXPECT_EQ(p.name, "cameras[0]");
    expect_near(p.to_world.point({0, 0, 0}), {0.5f, 0.5f, 3.0f});
    const CameraDesc& o = s.cameras[1];
    EXPECT_EQ(o.type, ProjectionType::Orthographic);
    EXPECT_FLOAT_EQ(o.xmag, 1.0f);
    EXPECT_FLOAT_EQ(o.ymag, 1.0f);
    // The quad is rotated by -45 degrees about X: its vertex (1, 1, 0) lands at
    // (1, cos 45, -sin 45).
    // Without NORMAL the vertices are un-indexed: triangle (1, 3, 2) starts at 3.
    const Vec3 v = s.instances[0].to_world.point(s.meshes[0].positions[4]);
    expect_near(v, {1.0f, 0.70711f, -0.70711f}, 2e-3f);
    // No NORMAL attribute: flat normals, one set of vertices per triangle.
    EXPECT_EQ(s.meshes[0].positions.size(), 6u);
    expect_near(s.meshes[0].normals[0], {0, 0, 1});
}

// Three nodes using mesh 0 (one of them a child, with scale), a camera under a scaled
// parent, and one light of each KHR_lights_punctual type.
TEST(GltfLoader, NodesCamerasAndLights) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members = R"(
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}, {"primitives": []}],
      "cameras": [{"type": "perspective", "name": "cam",
                   "perspective": {"yfov": 0.5, "znear": 0.1}}],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": [1, 0.5, 0.25], "intensity": 5464},
        {"type": "spot", "intensity": 1366, "spot": {"outerConeAngle": 0.5}},
        {"type": "directional", "range": 3}]}},
      "nodes": [
        {"mesh": 0, "children": [1], "translation": [10, 0, 0]},
        {"mesh": 0, "scale": [2, 2, 2], "translation": [0, 1, 0]},
        {"mesh": 0, "name": "third"},
        {"scale": [3, 3, 3], "children": [4]},
        {"camera": 0, "translation": [0, 0, 5]},
        {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [1, 2, 3]},
        {"extensions": {"KHR_lights_punctual": {"light": 1}},
         "rotation": [-0.70710678, 0, 0, 0.70710678]},
        {"extensions": {"KHR_lights_punctual": {"light": 2}}},
        {"mesh": 1}],
      "scenes": [{"nodes": [0, 2, 3, 5, 6, 7, 8]}])";
    const Scene s = load_gltf(b.write(dir, "scene.gltf", members, BufferStorage::DataUri));
    EXPECT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 3u);  // mesh 1 has no triangles: no instance
    expect_near(s.instances[1].to_world.point({1, 0, 0}), {12, 1, 0});  // parent * local
    EXPECT_EQ(s.instances[2].name, "third");

    ASSERT_EQ(s.cameras.size(), 1u);
    const CameraDesc& c = s.cameras[0];
    EXPECT_EQ(c.name, "cam");
    EXPECT_EQ(c.aspect_ratio, 0.0f);
    EXPECT_EQ(c.zfar, 0.0f);
    expect_near(c.to_world.point({0, 0, 0}), {0, 0, 15});
    expect_near(c.to_world.vector({0, 0, -1}), {0, 0, -1});  // scale removed

    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0]->describe(), "point");
    EXPECT_EQ(s.lights[1]->describe(), "spot");
    EXPECT_EQ(s.lights[2]->describe(), "directional");
    // The point light's intensity is colour * intensity / 683 lm/W (5464 cd = 8 W/sr):
    // check through sample_Li at a receiver 1 unit away from (1, 2, 3).
    const auto ls = s.lights[0]->sample_Li({{1, 2, 4}, {0, 0, -1}}, {0.5f, 0.5f}, 0);
    ASSERT_TRUE(ls.has_value());
    expect_near(ls->Li, {8, 4, 2}, 1e-4f);
    expect_near(ls->wi, {0, 0, -1});
    // The spot node is rotated -90 degrees about X, so its -Z axis points down (-Y).
    const auto below = s.lights[1]->sample_Li({{0, -2, 0}, {0, 1, 0}}, {0.5f, 0.5f}, 0);
    ASSERT_TRUE(below.has_value());
    expect_near(below->Li, Spectrum(2.0f / 4.0f), 1e-4f);
    const auto above = s.lights[1]->sample_Li({{0, 2, 0}, {0, -1, 0}}, {0.5f, 0.5f}, 0);
    EXPECT_TRUE(!above.has_value() || is_black(above->Li));
    // Directional: travels along -Z, white, the spec's default intensity of 1 lux.
    const auto sun = s.lights[2]->sample_Li({{0, 0, 0}, {0, 0, 1}}, {0.5f, 0.5f}, 0);
    ASSERT_TRUE(sun.has_value());
    expect_near(sun->wi, {0, 0, 1});
    EXPECT_FLOAT_EQ(sun->Li.x, float(1.0 / 683.0));
    EXPECT_EQ(sun->Li.x, sun->Li.y);
    EXPECT_EQ(sun->Li.x, sun->Li.z);
}

// KHR_lights_punctual intensities are candela and lux; --light-units radiometric reads the
// same numbers as W/sr and W/m^2, exactly 683 times brighter, for every light type.
TEST(GltfLoader, LightUnitsPhotometricByDefaultRadiometricOnRequest) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members = R"(
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "point", "intensity": 1000},
        {"type": "spot", "intensity": 683, "spot": {"outerConeAngle": 0.5}},
        {"type": "directional", "intensity": 100000}]}},
      "nodes": [{"mesh": 0},
        {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 2]},
        {"extensions": {"KHR_lights_punctual": {"light": 1}}, "translation": [0, 0, 2]},
        {"extensions": {"KHR_lights_punctual": {"light": 2}}}],
      "scenes": [{"nodes": [0, 1, 2, 3]}])";
    const std::string path = b.write(dir, "units.gltf", members, BufferStorage::DataUri);
    const Scene photometric = load_gltf(path);
    GltfLoadOptions lo;
    lo.light_units = LightUnits::Radiometric;
    const Scene radiometric = load_gltf(path, lo);
    ASSERT_EQ(photometric.lights.size(), 3u);
    ASSERT_EQ(radiometric.lights.size(), 3u);
    // The receiver at the origin faces +Z: 2 m below the point and the spot (which looks
    // down -Z onto it), and lit by the sun along its direction.
    const ShadingPoint at{{0, 0, 0}, {0, 0, 1}};
    const float expected[3] = {1000.0f / 683 / 4, 1.0f / 4, 100000.0f / 683};
    for (size_t i = 0; i < 3; ++i) {
        const auto p = photometric.lights[i]->sample_Li(at, {0.5f, 0.5f}, 0);
        const auto r = radiometric.lights[i]->sample_Li(at, {0.5f, 0.5f}, 0);
        ASSERT_TRUE(p && r) << i;
        EXPECT_NEAR(p->Li.y, expected[i], 1e-6f * expected[i]) << i;
        EXPECT_NEAR(r->Li.y / p->Li.y, 683.0f, 683.0f * 1e-6f) << i;
    }
}

TEST(GltfLoader, ChoosesTheRequestedScene) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members = R"(
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [{"mesh": 0}, {"mesh": 0}, {"mesh": 0}],
      "scenes": [{"nodes": [0]}, {"nodes": [1, 2]}], "scene": 1)";
    const std::string path = b.write(dir, "scenes.gltf", members, BufferStorage::DataUri);
    EXPECT_EQ(load_gltf(path).instances.size(), 2u);
    EXPECT_EQ(load_gltf(path, {0}).instances.size(), 1u);
    EXPECT_THROW(load_gltf(path, {2}), SceneError);
}

TEST(GltfLoader, OptionalUnknownExtensionOnlyWarns) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members = R"("extensionsUsed": ["KHR_texture_transform", "EXT_unknown"],)" +
                                test::one_mesh_scene(R"({"attributes": {"POSITION": 0}})");
    const LogLevel level = log_level();
    set_log_level(LogLevel::Error);
    const Scene s = load_gltf(b.write(dir, "optional.gltf", members, BufferStorage::DataUri));
    set_log_level(level);
    EXPECT_EQ(s.instances.size(), 1u);
}

}  // namespace
}  // namespace penumbra
