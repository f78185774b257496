// KHR_animation_pointer and KHR_node_visibility: pointers resolved and written, animated
// material, light and camera values at a still time (worked out from the keys), time
// steps over a shutter, hidden subtrees (static and animated), and the real files of
// ../shared/scenes/animation-pointer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "core/lights/stepped_light.h"
#include "io/gltf/animation/gltf_animation.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/animation/gltf_pointer.h"
#include "support/animated_scene.h"
#include "support/gltf_builder.h"
#include "support/material_gltf.h"
#include "support/paths.h"

namespace penumbra {
namespace {

TEST(GltfPointer, ResolvesTheObjectPropertyAndWidth) {
    auto t = resolve_pointer("/materials/3/pbrMetallicRoughness/baseColorFactor");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->object, PointerObject::Material);
    EXPECT_EQ(t->index, 3);
    EXPECT_EQ(t->property, "pbrMetallicRoughness/baseColorFactor");
    EXPECT_EQ(t->width, 4u);
    t = resolve_pointer("/extensions/KHR_lights_punctual/lights/1/spot/outerConeAngle");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->object, PointerObject::Light);
    EXPECT_EQ(t->index, 1);
    EXPECT_EQ(t->width, 1u);
    t = resolve_pointer("/nodes/5/extensions/KHR_node_visibility/visible");
    ASSERT_TRUE(t);
    EXPECT_TRUE(t->boolean);
    t = resolve_pointer(
        "/materials/0/extensions/KHR_materials_clearcoat/clearcoatTexture/extensions/"
        "KHR_texture_transform/offset");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->width, 2u);
    EXPECT_EQ(resolve_pointer("/cameras/0/perspective/yfov")->object, PointerObject::Camera);
    // Not pixels, or not pointers: left to the caller's warning.
    EXPECT_FALSE(resolve_pointer("/materials/0/extras/glow"));
    EXPECT_FALSE(resolve_pointer("/nodes/01/translation"));  // RFC 6901: no leading zero
    EXPECT_FALSE(resolve_pointer("nodes/0/translation"));
    EXPECT_FALSE(resolve_pointer("/meshes/0/weights"));
}

TEST(GltfPointer, WritesCoreAndExtensionPropertiesOfACopy) {
    tinygltf::Material m;
    m.pbrMetallicRoughness.baseColorTexture.index = 0;
    tinygltf::Value::Object transform;
    transform["offset"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.0), tinygltf::Value(0.0)});
    m.pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] =
        tinygltf::Value(transform);
    m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(tinygltf::Value::Object{});
    const double color[4] = {0.1, 0.2, 0.3, 0.4}, offset[2] = {0.5, 0.25}, strength = 7;
    EXPECT_TRUE(write_property(m, "pbrMetallicRoughness/baseColorFactor", color, 4));
    EXPECT_EQ(m.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
    EXPECT_TRUE(write_property(
        m, "pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset", offset, 2));
    const tinygltf::Value& off =
        m.pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"].Get("offset");
    ASSERT_TRUE(off.IsArray());
    EXPECT_EQ(off.Get(1).GetNumberAsDouble(), 0.25);
    EXPECT_TRUE(write_property(m, "extensions/KHR_materials_emissive_strength/emissiveStrength",
                               &strength, 1));
    EXPECT_EQ(m.extensions["KHR_materials_emissive_strength"].Get("emissiveStrength").GetNumberAsDouble(), 7);
    // A property whose enclosing object the asset lacks is not defined.
    EXPECT_FALSE(write_property(m, "extensions/KHR_materials_ior/ior", &strength, 1));
    EXPECT_FALSE(write_property(
        m, "normalTexture/extensions/KHR_texture_transform/rotation", &strength, 1));
    // The core textureInfos one level up (normalTexture), as PotOfCoalsAnimationPointer
    // animates its normal map's rotation.
    m.normalTexture.index = 1;
    m.normalTexture.extensions["KHR_texture_transform"] = tinygltf::Value(tinygltf::Value::Object{});
    EXPECT_TRUE(write_property(
        m, "normalTexture/extensions/KHR_texture_transform/rotation", &strength, 1));
    EXPECT_EQ(m.normalTexture.extensions["KHR_texture_transform"].Get("rotation").GetNumberAsDouble(), 7);
    tinygltf::Light point;
    point.type = "point";
    EXPECT_FALSE(write_property(point, "spot/outerConeAngle", &strength, 1));
    EXPECT_TRUE(write_property(point, "intensity", &strength, 1));
    EXPECT_EQ(point.intensity, 7);
}

// The validator's positive case: two pointer channels on material 0. Its accessors have
// no bufferView, so every key time is 0: glTF requires strictly increasing times, and
// the error names the sampler after the pointers have been resolved.
TEST(GltfAnimationPointer, ValidatorFilesParse) {
    const std::string path =
        test::shared_path("scenes/animation-pointer/validator_KHR_animation_pointer_valid.gltf");
    try {
        load_gltf_animations(path);
        FAIL() << "all-zero key times must be refused";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("animations[0].samplers[0]: input times are not "
                                             "strictly increasing"),
                  std::string::npos)
            << e.what();
    }
    // Three mesh-less nodes flagged false, true and {}: nothing to draw, no error.
    const Scene s = load_gltf(
        test::shared_path("scenes/animation-pointer/validator_KHR_node_visibility_valid.gltf"));
    EXPECT_TRUE(s.instances.empty());
}

// BowShooting.glb: node 12 "Graphics" is hidden, and with it its descendants 13
// "Cylinder" and 15 "Cube" (under 14 "Head"), which carry no flag of their own.
TEST(GltfNodeVisibility, HiddenSubtreeOfARealFileIsLeftOut) {
    const Scene s = load_gltf(test::shared_path("scenes/animation-pointer/BowShooting.glb"));
    std::set<int> nodes;
    for (const Instance& inst : s.instances) nodes.insert(inst.node);
    EXPECT_FALSE(nodes.count(13));
    EXPECT_FALSE(nodes.count(15));
    EXPECT_GE(nodes.size(), 4u);  // the other meshes stay
    for (const Instance& inst : s.instances) EXPECT_TRUE(inst.visibility.constant());
    EXPECT_FALSE(s.timed_materials);
}

// WhackAMole.glb animates every node through pointers: loaded over a shutter in which the
// moles move, some instances get time steps, as node channels would give them.
TEST(GltfAnimationPointer, NodeTransformsThroughPointersMoveInstances) {
    const std::string path = test::shared_path("scenes/animation-pointer/WhackAMole.glb");
    const GltfAnimations a = load_gltf_animations(path);
    size_t animated = 0;
    for (int n = 0; n < 68; ++n)
        if (const NodeChannels* nc = a.node(n)) animated += nc->animates_transform();
    EXPECT_GT(animated, 0u);
    GltfLoadOptions options;
    options.shutter_open = 0;
    options.shutter_close = 2;
    const Scene s = load_gltf(path, options);
    size_t moving = 0;
    for (const Instance& inst : s.instances) moving += !inst.motion.empty();
    EXPECT_GT(moving, 0u);
}

Scene load_at(const std::string& path, double open, double close) {
    GltfLoadOptions options;
    options.shutter_open = open;
    options.shutter_close = close;
    return load_gltf(path, options);
}

bool has_node(const Scene& s, int node) {
    return std::any_of(s.instances.begin(), s.instances.end(),
                       [&](const Instance& i) { return i.node == node; });
}

TEST(GltfAnimationPointer, StillTimeTakesTheAnimatedValues) {
    const test::ScratchDir dir;
    const std::string path = test::animated_scene(dir);
    for (double t : {0.0, 0.25, 0.75, 1.0, 3.0}) {
        const Scene s = load_at(path, t, t);
        const double u = std::min(t, 1.0);
        const Vec4 c = s.materials[0].base_color;
        EXPECT_NEAR(c.x, 1 - u, 1e-6) << t;
        EXPECT_EQ(c.y, 0) << t;
        EXPECT_NEAR(c.z, u, 1e-6) << t;
        EXPECT_TRUE(s.material_steps.empty());
        // STEP: shown before 0.5 s, hidden from it (the key's own time included).
        EXPECT_EQ(has_node(s, 1), t < 0.5) << t;
        ASSERT_EQ(s.cameras.size(), 1u);
        EXPECT_NEAR(s.cameras[0].yfov, 0.5 + 0.5 * u, 1e-6) << t;
        EXPECT_TRUE(s.cameras[0].view_steps.empty());
        ASSERT_EQ(s.lights.size(), 1u);
        EXPECT_EQ(s.lights[0]->describe(), "point");
        // Power is 4 pi I: in proportion to the intensity, 10 + 20 u.
        const Scene s0 = load_at(path, 0, 0);
        EXPECT_NEAR(s.lights[0]->power() / s0.lights[0]->power(), (10 + 20 * u) / 10, 1e-5) << t;
    }
    const Scene hidden = load_at(path, 0.5, 0.5);
    EXPECT_FALSE(has_node(hidden, 1));
    EXPECT_FALSE(hidden.timed_materials);
}

TEST(GltfAnimationPointer, ShutterGivesTimeSteps) {
    const test::ScratchDir dir;
    const Scene s = load_at(test::animated_scene(dir), 0.25, 0.75);
    // The material at open, then 65 steps across [0.25, 0.75] s.
    EXPECT_NEAR(s.materials[0].base_color.x, 0.75, 1e-6);
    ASSERT_GE(s.material_steps.size(), 1u);
    const std::vector<int>& steps = s.material_steps[0];
    ASSERT_EQ(steps.size(), 65u);
    for (size_t k = 0; k < steps.size(); ++k) {
        const double t = 0.25 + 0.5 * double(k) / 64;
        EXPECT_NEAR(s.materials[size_t(steps[k])].base_color.z, t, 1e-6) << k;
    }
    EXPECT_TRUE(s.timed_materials);
    // Nearest step: normalized time 0.5 is step 32, 0.49 rounds to 31.
    uint32_t back = 0, front = 0;
    for (uint32_t i = 0; i < s.instances.size(); ++i) (s.instances[i].node == 0 ? back : front) = i;
    EXPECT_EQ(s.material_at(back, 0, 0.5f), steps[32]);
    EXPECT_EQ(s.material_at(back, 0, 0.49f), steps[31]);
    // The green quad is shown until 0.5 s: normalized 0.5 of [0.25, 0.75].
    ASSERT_TRUE(has_node(s, 1));
    const TimedVisibility& v = s.instances[front].visibility;
    EXPECT_TRUE(v.at_open);
    ASSERT_EQ(v.flips.size(), 1u);
    EXPECT_FLOAT_EQ(v.flips[0], 0.5f);
    EXPECT_EQ(s.material_at(front, 1, 0.4999f), 1);
    EXPECT_EQ(s.material_at(front, 1, 0.5f), s.hidden_material);
    EXPECT_EQ(s.material(s.hidden_material).alpha_mode, AlphaMode::Mask);
    // The camera zooms: 65 fields of view from 0.625 to 0.875 rad.
    ASSERT_EQ(s.cameras[0].view_steps.size(), 65u);
    EXPECT_NEAR(s.cameras[0].view_steps.front(), 0.625, 1e-6);
    EXPECT_NEAR(s.cameras[0].view_steps[32], 0.75, 1e-6);
    EXPECT_NEAR(s.cameras[0].view_steps.back(), 0.875, 1e-6);
    // The light: stepped, its intensity 15 cd at open and 25 cd at close; radiance at a
    // point 2 m below it in proportion.
    const auto* light = dynamic_cast<const SteppedLight*>(s.lights[0].get());
    ASSERT_NE(light, nullptr);
    const ShadingPoint ref{Vec3(0, 0, 0), Vec3(0, 0, 1)};
    const auto at_open = light->sample_Li(ref, Vec2(0.5f, 0.5f), 0.0f);
    const auto at_close = light->sample_Li(ref, Vec2(0.5f, 0.5f), 1.0f);
    const auto mid = light->sample_Li(ref, Vec2(0.5f, 0.5f), 0.5f);
    ASSERT_TRUE(at_open && at_close && mid);
    EXPECT_NEAR(at_close->Li.x / at_open->Li.x, 25.0 / 15.0, 1e-5);
    EXPECT_NEAR(mid->Li.x / at_open->Li.x, 20.0 / 15.0, 1e-5);
}

TEST(GltfAnimationPointer, BadBoolAnimationIsANamedError) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    const int times = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int values = b.add<float>({1, 0}, test::kFloat, "SCALAR");
    const std::string members =
        "\"extensionsUsed\":[\"KHR_animation_pointer\"],\"nodes\":[{}],\"scenes\":[{\"nodes\":[0]}],\"animations\":[{\"samplers\":[{\"input\":" +
        std::to_string(times) + ",\"output\":" + std::to_string(values) +
        ",\"interpolation\":\"STEP\"}],\"channels\":[{\"sampler\":0,\"target\":{\"path\":"
        "\"pointer\",\"extensions\":{\"KHR_animation_pointer\":{\"pointer\":"
        "\"/nodes/0/extensions/KHR_node_visibility/visible\"}}}}]}]";
    const std::string path = b.write(dir, "bad.gltf", members, test::BufferStorage::DataUri);
    try {
        load_gltf(path);
        FAIL() << "a float visibility animation must be refused";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("animations[0].samplers[0]"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("unsigned byte"), std::string::npos) << e.what();
    }
}

// Texture transforms on a core textureInfo and on one inside a material extension, and an
// extension factor, all LINEAR over [0, 1] s; and a pointer into KHR_materials_ior, which
// the material does not have: ignored with a warning, the default IOR kept.
TEST(GltfAnimationPointer, TextureTransformsAndExtensionFactorsAnimate) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const int times = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int offsets = b.add<float>({0, 0, 1, 0.5f}, test::kFloat, "VEC2");
    const int angles = b.add<float>({0, 2}, test::kFloat, "SCALAR");
    const int strengths = b.add<float>({1, 5}, test::kFloat, "SCALAR");
    const int iors = b.add<float>({1.2f, 1.8f}, test::kFloat, "SCALAR");
    auto channel = [](int s, const std::string& pointer) {
        return "{\"sampler\":" + std::to_string(s) +
               ",\"target\":{\"path\":\"pointer\",\"extensions\":{\"KHR_animation_pointer\":"
               "{\"pointer\":\"/materials/0/" + pointer + "\"}}}}";
    };
    auto sampler = [&](int out) {
        return "{\"input\":" + std::to_string(times) + ",\"output\":" + std::to_string(out) + "}";
    };
    const std::string transform =
        "\"extensions\":{\"KHR_texture_transform\":{\"offset\":[0,0],\"rotation\":0}}";
    const std::string members =
        "\"extensionsUsed\":[\"KHR_animation_pointer\",\"KHR_texture_transform\","
        "\"KHR_materials_clearcoat\",\"KHR_materials_emissive_strength\"],"
        "\"images\":[{\"uri\":\"" + test::png_uri(dir) + "\"}],\"textures\":[{\"source\":0}],"
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0," +
        transform + "}},\"emissiveFactor\":[1,1,1],\"extensions\":{"
        "\"KHR_materials_clearcoat\":{\"clearcoatFactor\":1,\"clearcoatTexture\":{\"index\":0," +
        transform + "}},\"KHR_materials_emissive_strength\":{}}}],"
        "\"animations\":[{\"samplers\":[" + sampler(offsets) + "," + sampler(angles) + "," +
        sampler(offsets) + "," + sampler(strengths) + "," + sampler(iors) + "],\"channels\":[" +
        channel(0, "pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset") +
        "," + channel(1, "pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/rotation") +
        "," + channel(2, "extensions/KHR_materials_clearcoat/clearcoatTexture/extensions/"
                         "KHR_texture_transform/offset") +
        "," + channel(3, "extensions/KHR_materials_emissive_strength/emissiveStrength") + "," +
        channel(4, "extensions/KHR_materials_ior/ior") + "]}]," +
        test::one_mesh_scene(R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0})");
    const std::string path = b.write(dir, "uv.gltf", members, test::BufferStorage::DataUri);
    const Scene s = load_at(path, 0.25, 0.25);
    const MaterialDesc& m = s.materials[0];
    EXPECT_NEAR(m.base_color_texture.offset.x, 0.25, 1e-6);
    EXPECT_NEAR(m.base_color_texture.offset.y, 0.125, 1e-6);
    EXPECT_NEAR(m.base_color_texture.rotation, 0.5, 1e-6);
    EXPECT_NEAR(m.clearcoat_texture.offset.x, 0.25, 1e-6);
    EXPECT_NEAR(m.emissive_strength, 2, 1e-6);
    EXPECT_EQ(m.ior, 1.5f);
    // Under --strict the undefined pointer is the error, naming the channel.
    GltfLoadOptions strict;
    strict.strict = true;
    try {
        load_gltf(path, strict);
        FAIL() << "a pointer to an undefined property must be reported";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("animations[0].channels[4]"), std::string::npos) << e.what();
    }
}

// A hidden node in a cycle: the traversal's error, not an endless walk up the parents.
TEST(GltfNodeVisibility, CycleUnderAHiddenNodeIsTheTraversalsError) {
    const test::ScratchDir dir;
    const std::string path = dir.write(
        "cycle.gltf",
        R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_node_visibility"],
            "nodes":[{"children":[1],"extensions":{"KHR_node_visibility":{"visible":false}}},
                     {"children":[0]}],"scenes":[{"nodes":[0]}]})");
    try {
        load_gltf(path);
        FAIL() << "a cycle must be refused";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("reached twice"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace penumbra
