// The --default-light rule (core/lights/default_lights.h) on scenes built in code: a
// helmet-like object (big diffuse body, tiny or texture-darkened emission) gets the default
// lighting, emitter-lit rooms (a Cornell box, the bundled emitter scenes) keep their own,
// and on/off, punctual lights and an environment override the emitters' verdict.
#include "core/lights/default_lights.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/lights/point_light.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

int add_emitter(Scene& scene, Spectrum radiance, int texture = -1) {
    MaterialDesc m;
    m.base_color = Vec4(0, 0, 0, 1);
    m.emissive = radiance;
    m.emissive_texture.texture = texture;
    scene.materials.push_back(m);
    return int(scene.materials.size() - 1);
}

// A unit quad in the plane y = 0 centred at the origin, facing +y.
uint32_t add_unit_quad(Scene& scene, int material) {
    return test::add_quad_object(scene, {-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0.5f, 0, -0.5f},
                                 {-0.5f, 0, -0.5f}, material);
}

// A diffuse body 2 m across (bounding radius sqrt(3)) with an emissive square of side
// `side` and radiance Le on top of it.
Scene helmet_like(float side, Spectrum Le) {
    Scene s;
    const uint32_t body = test::add_cube_object(s, test::add_lambertian(s, Spectrum(0.5f)));
    test::add_instance(s, body, Transform::scale({2, 2, 2}));
    const uint32_t patch = add_unit_quad(s, add_emitter(s, Le));
    test::add_instance(s, patch,
                       Transform::translate({0, 1.001f, 0}) * Transform::scale({side, 1, side}));
    return s;
}

// The Cornell box's proportions: the room [-1, 1]^3, a 0.5 x 0.4 m ceiling panel of
// radiance 30.
Scene cornell_like() {
    Scene s;
    const uint32_t room = test::add_cube_object(s, test::add_lambertian(s, Spectrum(0.75f)));
    test::add_instance(s, room, Transform::scale({2, 2, 2}));
    const uint32_t panel = add_unit_quad(s, add_emitter(s, Spectrum(30)));
    test::add_instance(s, panel,
                       Transform::translate({0, 0.999f, 0}) * Transform::scale({0.5f, 1, 0.4f}));
    return s;
}

TEST(DefaultLights, EmitterPowerIsWorldAreaTimesPiTimesMeanRadiance) {
    // Scaled instance: area 0.3 x 0.2 = 0.06 m^2; radiance (luminance) 10.
    Scene s;
    const uint32_t q = add_unit_quad(s, add_emitter(s, Spectrum(10)));
    test::add_instance(s, q, Transform::scale({0.3f, 1, 0.2f}));
    test::add_instance(s, q, Transform::translate({0, 2, 0}) * Transform::scale({0.3f, 1, 0.2f}));
    const EmitterSummary e = summarize_emitters(s);
    EXPECT_NEAR(e.area, 0.12, 1e-6);
    EXPECT_NEAR(e.power, kPi * 0.12 * 10, 1e-5);
    EXPECT_NEAR(e.mean_radiance(), 10, 1e-5);
    // An emission texture scales by its mean: a 2 x 2 image with one texel of 1, three of 0.
    Image img(2, 2, 3);
    img.pixels = {1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    s.images.push_back(TextureImage(img));
    s.textures.push_back(Texture{0});
    s.materials.back().emissive_texture.texture = 0;
    EXPECT_NEAR(summarize_emitters(s).mean_radiance(), 2.5, 1e-5);
}

TEST(DefaultLights, HelmetLikeScenesGetTheDefaultLighting) {
    // A 2 cm square of radiance 5 on a 2 m body: bright, but a speck (6 mW; the default
    // lights deliver 29 W to the body's bounding sphere).
    const LightingChoice tiny =
        choose_lighting(DefaultLightMode::Auto, helmet_like(0.02f, Spectrum(5)), false);
    EXPECT_TRUE(tiny.add_defaults) << tiny.reason;
    EXPECT_NE(tiny.reason.find("too small"), std::string::npos) << tiny.reason;
    // The whole top emissive through a mostly black texture (mean 0.04 of a factor of 1):
    // enough power (0.5 W, 1.7%), but a glowing decal, not a light.
    Scene decal = helmet_like(2.0f, Spectrum(1));
    Image img(5, 5, 3);
    img.pixels.assign(img.pixels.size(), 0.0f);
    img.at(2, 2)[0] = img.at(2, 2)[1] = img.at(2, 2)[2] = 1.0f;
    decal.images.push_back(TextureImage(img));
    decal.textures.push_back(Texture{0});
    decal.materials.back().emissive_texture.texture = 0;
    const LightingChoice dim = choose_lighting(DefaultLightMode::Auto, decal, false);
    EXPECT_TRUE(dim.add_defaults) << dim.reason;
    EXPECT_NE(dim.reason.find("too dim"), std::string::npos) << dim.reason;
}

TEST(DefaultLights, EmitterLitRoomsKeepTheirOwnLight) {
    const LightingChoice cornell = choose_lighting(DefaultLightMode::Auto, cornell_like(), false);
    EXPECT_FALSE(cornell.add_defaults) << cornell.reason;
    // The bundled emitter-lit scenes. soft-shadows.gltf is the closest call: three panels
    // of 3 W/pi each on a 16 m floor, 2.2% of the default lights' power (threshold 1%).
    for (const char* name :
         {"scenes/cornell-box.gltf", "scenes/soft-shadows.gltf", "scenes/glossy.gltf"}) {
        const Scene s = load_gltf(test::source_path(name));
        const LightingChoice c = choose_lighting(DefaultLightMode::Auto, s, false);
        EXPECT_FALSE(c.add_defaults) << name << ": " << c.reason;
    }
}

TEST(DefaultLights, ThresholdsSitWhereDocumented) {
    // Mean radiance threshold (2.5 + 0.6) / pi = 0.987: a panel as large as the Cornell
    // box's, 1% below and above it.
    const float limit = (kDefaultKeyIrradiance + kDefaultFillIrradiance) / kPi;
    EXPECT_TRUE(
        choose_lighting(DefaultLightMode::Auto, helmet_like(1.0f, Spectrum(0.99f * limit)), false)
            .add_defaults);
    EXPECT_FALSE(
        choose_lighting(DefaultLightMode::Auto, helmet_like(1.0f, Spectrum(1.01f * limit)), false)
            .add_defaults);
    // Power threshold: 1% of 3.1 pi R^2 with R = sqrt(3) (the body's bounding sphere; the
    // patch on top stays inside it), for a patch of radiance 100: side^2 = 0.01 x 3.1 x 3 /
    // 100.
    const float side = std::sqrt(0.01f * 3.1f * 3.0f / 100.0f);
    EXPECT_TRUE(
        choose_lighting(DefaultLightMode::Auto, helmet_like(0.99f * side, Spectrum(100)), false)
            .add_defaults);
    EXPECT_FALSE(
        choose_lighting(DefaultLightMode::Auto, helmet_like(1.01f * side, Spectrum(100)), false)
            .add_defaults);
}

TEST(DefaultLights, ModesLightsAndEnvironmentDecideBeforeTheEmitters) {
    Scene dark = helmet_like(0.02f, Spectrum(5));
    EXPECT_FALSE(choose_lighting(DefaultLightMode::Off, dark, false).add_defaults);
    EXPECT_FALSE(choose_lighting(DefaultLightMode::Auto, dark, true).add_defaults);  // --env
    EXPECT_TRUE(choose_lighting(DefaultLightMode::On, cornell_like(), false).add_defaults);
    Scene bare;
    test::add_instance(bare, test::add_cube_object(bare, test::add_lambertian(bare, Spectrum(1))),
                       Transform());
    EXPECT_TRUE(choose_lighting(DefaultLightMode::Auto, bare, false).add_defaults);
    bare.lights.push_back(std::make_unique<PointLight>(Vec3(0, 3, 0), Spectrum(1)));
    EXPECT_FALSE(choose_lighting(DefaultLightMode::Auto, bare, false).add_defaults);
}

TEST(DefaultLights, KeyAndFillComeFromTheCameraSide) {
    Scene s = helmet_like(0.02f, Spectrum(5));
    CameraDesc cam;
    cam.to_world = Transform::translate({0, 0, 5});  // looking down -Z at the body
    const std::unique_ptr<EnvironmentLight> env = add_default_lights(s, cam);
    ASSERT_EQ(s.lights.size(), 2u);
    ASSERT_TRUE(env);
    // Both light the side facing the camera (+Z) and the key the top too.
    for (const auto& light : s.lights) {
        const auto ls = light->sample_Li({{0, 0, 1}, {0, 0, 1}}, {0.5f, 0.5f}, 0);
        ASSERT_TRUE(ls);
        EXPECT_GT(ls->wi.z, 0.5f);
    }
    const auto key = s.lights[0]->sample_Li({{0, 1, 0}, {0, 1, 0}}, {0.5f, 0.5f}, 0);
    ASSERT_TRUE(key);
    EXPECT_GT(key->wi.y, 0.3f);
    EXPECT_FLOAT_EQ(key->Li.x, kDefaultKeyIrradiance);
}

}  // namespace
}  // namespace penumbra
