// The path tracer through refracting materials, under a uniform environment and no
// other light: a smooth, white, fully transmissive glTF sphere is lossless, so it must
// vanish into the background (radiance 1 everywhere: the 1/eta^2 on the way in and the
// eta^2 on the way out cancel, and Russian roulette must not mistake them for loss).
// Rough glass and Beckmann glTF spheres may only lose energy.
#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

struct SphereStats {
    double mean = 0, se = 0;
};

// Renders one unit sphere with material m filling the middle of the image and returns
// the mean and standard error over the pixels well inside its disk.
SphereStats render_sphere(const MaterialDesc& m, MicrofacetType type, int spp) {
    Scene scene;
    scene.materials.push_back(m);
    const uint32_t sphere = test::add_sphere_object(scene, 0, 48, 96);
    test::add_instance(scene, sphere, Transform::scale(Vec3(1)));
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(1), 10.0f));
    RenderContext ctx{scene, accel, lights};
    ctx.materials.gltf_distribution = type;
    const int res = 24;
    const PerspectiveCamera camera(Transform::look_at({0, 0, 50}, {0, 0, 0}, {0, 1, 0}),
                                   2 * std::atan(1.2f / 50), res, res);
    IntegratorOptions iopt;
    iopt.max_depth = 64;
    const auto integrator = make_integrator("path", iopt);
    RenderOptions opt;
    opt.spp = spp;
    opt.progress = false;
    opt.filter = "box";
    RenderStats stats;
    const Image img = render(ctx, camera, *integrator, opt, &stats).resolve();
    EXPECT_EQ(stats.nonfinite_samples, 0u);
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

MaterialDesc glass(float roughness) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = 1;
    return m;
}

TEST(TransmissionFurnace, SmoothGlassSphereVanishes) {
    const SphereStats s = render_sphere(glass(0), MicrofacetType::Ggx, 64);
    EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 2e-3) << "+- " << s.se;
}

TEST(TransmissionFurnace, RoughGlassAndBeckmannOnlyLoseEnergy) {
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        const SphereStats rough = render_sphere(glass(0.5f), type, 16);
        EXPECT_LE(rough.mean, 1 + 4 * rough.se) << "rough glass, type " << int(type);
        EXPECT_GT(rough.mean, 0.5);
        MaterialDesc metal;
        metal.base_color = {1, 1, 1, 1};
        metal.metallic = 1;
        metal.roughness = 0.3f;
        const SphereStats m = render_sphere(metal, type, 16);
        EXPECT_LE(m.mean, 1 + 4 * m.se) << "metal, type " << int(type);
    }
}

}  // namespace
}  // namespace penumbra
