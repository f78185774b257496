// The path tracer through refracting materials, under a uniform environment and no
// other light: a smooth, white, fully transmissive glTF sphere with a clear volume
// (KHR_materials_volume, infinite attenuation distance) is lossless, so it must vanish
// into the background (radiance 1 everywhere: the 1/eta^2 on the way in and the eta^2
// on the way out cancel, and Russian roulette must not mistake them for loss); so must a
// thin-walled one (no volume: sheets that do not bend). Rough glass and Beckmann glTF
// spheres may only lose energy, and so may absorbing glass.
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
    const auto integrator = make_integrator(IntegratorType::Path, iopt);
    RenderOptions opt;
    opt.spp = spp;
    opt.progress = false;
    opt.filter = FilterType::Box;
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

// A solid glass sphere: a closed volume whose medium is clear unless attenuated.
MaterialDesc glass(float roughness, bool volume = true) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = 1;
    m.thickness = volume ? 1.0f : 0.0f;
    return m;
}

TEST(TransmissionFurnace, SmoothGlassSphereVanishes) {
    const SphereStats s = render_sphere(glass(0), MicrofacetType::Ggx, 64);
    EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 2e-3) << "+- " << s.se;
}

TEST(TransmissionFurnace, SmoothThinWalledSphereVanishes) {
    const SphereStats s = render_sphere(glass(0, false), MicrofacetType::Ggx, 64);
    EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 2e-3) << "+- " << s.se;
}

TEST(TransmissionFurnace, AbsorbingGlassLosesEnergyAndInfiniteDistanceLosesNone) {
    MaterialDesc tinted = glass(0);
    tinted.attenuation_color = {0.5f, 0.5f, 0.5f};
    // The spec's default distance: the colour does nothing.
    const SphereStats clear = render_sphere(tinted, MicrofacetType::Ggx, 16);
    const SphereStats plain = render_sphere(glass(0), MicrofacetType::Ggx, 16);
    EXPECT_EQ(clear.mean, plain.mean);
    EXPECT_EQ(clear.se, plain.se);
    // Half the light left per unit radius: the central chord (2) keeps a quarter, and
    // paths that reflect inside lose more; the Fresnel-reflected rim keeps most.
    tinted.attenuation_distance = 1;
    const SphereStats absorbing = render_sphere(tinted, MicrofacetType::Ggx, 16);
    EXPECT_LT(absorbing.mean, 0.6);
    EXPECT_GT(absorbing.mean, 0.2);
}

TEST(TransmissionFurnace, RoughGlassAndBeckmannOnlyLoseEnergy) {
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
        const SphereStats rough = render_sphere(glass(0.5f), type, 16);
        EXPECT_LE(rough.mean, 1 + 4 * rough.se) << "rough glass, type " << int(type);
        EXPECT_GT(rough.mean, 0.5);
        const SphereStats thin = render_sphere(glass(0.5f, false), type, 16);
        EXPECT_LE(thin.mean, 1 + 4 * thin.se) << "rough thin-walled, type " << int(type);
        EXPECT_GT(thin.mean, 0.5);
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
