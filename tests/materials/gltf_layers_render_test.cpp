// The glTF lobes through the path tracer: spheres in a uniform environment of radiance 1
// and no other light. A white sphere whose every interaction keeps energy (diffuse
// transmission split from a white base; unlit white, which emits 1 and reflects
// nothing) vanishes into the background; coats and sheen over white may only lose.
// GltfLayersPreview (disabled: a viewing aid) writes lit previews of each lobe to look at.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "core/lights/directional_light.h"
#include "integrators/render.h"
#include "io/image/image_writer.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

struct SphereStats {
    double mean = 0, se = 0;
};

Image render_sphere(const MaterialDesc& m, int res, int spp, Spectrum environment, bool sun) {
    Scene scene;
    scene.materials.push_back(m);
    const uint32_t sphere = test::add_sphere_object(scene, 0, 48, 96);
    test::add_instance(scene, sphere, Transform::scale(Vec3(1)));
    if (sun)
        scene.lights.push_back(std::make_unique<DirectionalLight>(
            normalize(Vec3(-0.6f, -0.5f, -0.6f)), Spectrum(3), 10.0f));
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(environment, 10.0f));
    RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({0, 0, 50}, {0, 0, 0}, {0, 1, 0}),
                                   2 * std::atan(1.2f / 50), res, res);
    IntegratorOptions iopt;
    iopt.max_depth = 64;
    const auto integrator = make_integrator(IntegratorType::Path, iopt);
    RenderOptions opt;
    opt.spp = spp;
    opt.progress = false;
    opt.filter = FilterType::Box;
    RenderStats stats;
    Image img = render(ctx, camera, *integrator, opt, &stats).resolve();
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    return img;
}

// Mean and standard error of G over the pixels well inside the sphere's disk.
SphereStats furnace(const MaterialDesc& m, int spp) {
    const int res = 24;
    const Image img = render_sphere(m, res, spp, Spectrum(1), false);
    double sum = 0, sum2 = 0;
    int count = 0;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float dx = x + 0.5f - res / 2.0f, dy = y + 0.5f - res / 2.0f;
            if (dx * dx + dy * dy > 0.6f * 0.6f * (res / 2.4f) * (res / 2.4f)) continue;
            const double v = img.at(x, y)[1];
            sum += v;
            sum2 += v * v;
            ++count;
        }
    SphereStats s;
    s.mean = sum / count;
    s.se = std::sqrt(std::max(0.0, sum2 / count - s.mean * s.mean) / count);
    return s;
}

MaterialDesc white_dielectric(float roughness) {
    MaterialDesc m;
    m.metallic = 0;
    m.roughness = roughness;
    return m;
}

// The specular albedo table's error (metal_rough_bsdf_test.cpp), per bounce.
constexpr double kTableTolerance = 2e-3;

TEST(GltfLayersFurnace, WhiteDiffuseTransmissionVanishes) {
    for (float factor : {0.5f, 1.0f}) {
        MaterialDesc m = white_dielectric(0.5f);
        m.diffuse_transmission = factor;
        const SphereStats s = furnace(m, 64);
        EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 4 * kTableTolerance)
            << "dt " << factor << " +- " << s.se;
        std::printf("diffuse transmission %.1f: furnace %.4f +- %.4f\n", factor, s.mean, s.se);
    }
}

TEST(GltfLayersFurnace, WhiteUnlitVanishes) {
    MaterialDesc m;
    m.unlit = true;
    const SphereStats s = furnace(m, 4);
    EXPECT_NEAR(s.mean, 1.0, 1e-5);
    EXPECT_LT(s.se, 1e-5);
}

TEST(GltfLayersFurnace, CoatsAndSheenOnlyLose) {
    for (int variant = 0; variant < 3; ++variant) {
        MaterialDesc m = white_dielectric(0.5f);
        if (variant != 1) m.clearcoat = 1, m.clearcoat_roughness = variant == 0 ? 0.0f : 0.4f;
        if (variant != 0) m.sheen_color = {1, 1, 1}, m.sheen_roughness = 0.5f;
        const SphereStats s = furnace(m, 16);
        EXPECT_LE(s.mean, 1 + 4 * s.se + kTableTolerance) << "variant " << variant;
        EXPECT_GT(s.mean, 0.8) << "variant " << variant;
        std::printf("variant %d (coat %.0f, sheen %.0f): furnace %.4f +- %.4f\n", variant,
                    m.clearcoat, m.sheen_color.x, s.mean, s.se);
    }
}

// A viewing aid, not a test (it checks nothing): run it with
// --gtest_also_run_disabled_tests --gtest_filter='GltfLayersPreview.*' and
// PENUMBRA_PREVIEW_DIR set, then look at the PNGs.
TEST(GltfLayersPreview, DISABLED_WritesLitSpheres) {
    const char* dir = std::getenv("PENUMBRA_PREVIEW_DIR");
    ASSERT_NE(dir, nullptr) << "set PENUMBRA_PREVIEW_DIR to write previews";
    struct Named {
        const char* name;
        MaterialDesc m;
    };
    std::vector<Named> list;
    MaterialDesc red = white_dielectric(0.6f);
    red.base_color = {0.6f, 0.05f, 0.05f, 1};
    list.push_back({"plain", red});
    MaterialDesc coat = red;
    coat.clearcoat = 1, coat.clearcoat_roughness = 0.03f;
    list.push_back({"clearcoat", coat});
    MaterialDesc sheen = red;
    sheen.base_color = {0.05f, 0.05f, 0.3f, 1};
    sheen.sheen_color = {1, 0.8f, 0.6f}, sheen.sheen_roughness = 0.4f;
    list.push_back({"sheen", sheen});
    MaterialDesc dt = white_dielectric(0.6f);
    dt.base_color = {0.2f, 0.6f, 0.2f, 1};
    dt.diffuse_transmission = 1, dt.diffuse_transmission_color = {1, 0.2f, 0.1f};
    list.push_back({"diffuse_transmission", dt});
    MaterialDesc sg;
    sg.specular_glossiness = true;
    sg.base_color = {0.1f, 0.1f, 0.1f, 1};
    sg.specular_color = {1, 0.8f, 0.3f}, sg.roughness = 0.25f;
    list.push_back({"specular_glossiness", sg});
    MaterialDesc unlit;
    unlit.unlit = true, unlit.base_color = {0.2f, 0.5f, 0.9f, 1};
    list.push_back({"unlit", unlit});
    for (const Named& n : list) {
        const Image img = render_sphere(n.m, 128, 64, Spectrum(0.15f), true);
        write_preview(std::string(dir) + "/" + n.name + ".png", img);
    }
}

}  // namespace
}  // namespace penumbra
