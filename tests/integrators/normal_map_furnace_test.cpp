// A normal-mapped white furnace: a white Lambertian plane whose normal map leans every
// normal by kTilt, under a uniform environment of radiance 1. A flat plane reflects
// exactly 1. The mapped one may only lose what the bump shadowing term (direct_lighting.h)
// and the surface's horizon take from its hemisphere:
//   A(phi) = integral over wi above the plane of (cos_b / pi) bump_shadowing(n, n_b, wi),
// cos_b = max(0, wi.n_b), n_b leaning by phi. The shading normal is the mapped one, or
// one bent back towards the plane's normal (materials/normal_map.h), so its lean phi is
// at most kTilt, and the plane may not come out darker than the least A over [0, kTilt]
// from any view. Views from the side the map leans away from put wo below the mapped
// normal: where every BSDF is 0, those were black. A white mirror with the same map
// reflects exactly 1 from every view: its mirror direction stays above the plane, where
// the sky is, and the shadowing term is the diffuse lobes' alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/camera/orthographic_camera.h"
#include "integrators/direct_lighting.h"
#include "support/statistics/quadrature.h"
#include "support/render_scene.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

constexpr float kTilt = 40 * kPi / 180;
constexpr int kRes = 8;

// The plane y = 0, its UVs' u along +x; with a normal map, every normal leans by kTilt
// towards +x. White Lambertian, or a white mirror (metal of roughness 0).
Scene furnace_plane(bool mapped, bool mirror = false) {
    Scene scene;
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = mirror ? 1 : 0;
    m.roughness = mirror ? 0 : 1;
    m.specular = mirror ? 1 : 0;  // else exactly Lambertian (KHR_materials_specular 0)
    if (mapped) {
        const Vec3 local(std::sin(kTilt), 0, std::cos(kTilt));
        Image img(1, 1, 4);
        for (int c = 0; c < 3; ++c) img.at(0, 0)[c] = (local[c] + 1) / 2;
        img.at(0, 0)[3] = 1;
        scene.images.push_back(TextureImage(img));
        Texture tex;
        tex.image = 0;
        tex.nearest = true;
        scene.textures.push_back(tex);
        m.normal_texture.texture = 0;
    }
    scene.materials.push_back(m);
    const float r = 1000;
    const uint32_t quad =
        test::add_quad_object(scene, {-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r}, 0);
    test::add_instance(scene, quad, Transform());
    return scene;
}

struct Measured {
    double mean = 0, se = 0;
};

// The plane's radiance towards wo: the mean of kRes^2 pixels around the origin, and its
// standard error from their spread.
Measured furnace_radiance(const Scene& scene, Vec3 wo) {
    const OrthographicCamera camera(Transform::look_at(wo * 10.0f, {0, 0, 0}, {0, 1, 0}), 0.05f,
                                    0.05f, kRes, kRes);
    const test::SceneRender r = test::render_scene(
        scene, camera, "path", 64, 3, 5, std::make_unique<EnvironmentLight>(Spectrum(1), 10.0f));
    EXPECT_EQ(r.nonfinite_samples, 0u);
    double sum = 0, sum2 = 0;
    for (int y = 0; y < kRes; ++y)
        for (int x = 0; x < kRes; ++x) {
            const double v = test::pixel_mean(r.image, x, y);
            sum += v;
            sum2 += v * v;
        }
    const int n = kRes * kRes;
    Measured m;
    m.mean = sum / n;
    m.se = std::sqrt(std::max(0.0, sum2 / n - m.mean * m.mean) / (n - 1));
    return m;
}

// A(phi) above, over (cos theta, phi) of wi about the plane's normal (+z here).
double shadowed_albedo(float lean) {
    const Vec3 n(0, 0, 1), nb(std::sin(lean), 0, std::cos(lean));
    return test::integrate_2d(
        [&](double mu, double phi) {
            const float s = float(std::sqrt(std::max(0.0, 1 - mu * mu)));
            const Vec3 wi(s * float(std::cos(phi)), s * float(std::sin(phi)), float(mu));
            const float cos_b = dot(wi, nb);
            if (!(cos_b > 0)) return 0.0;
            return double(cos_b * bump_shadowing(n, nb, wi) / kPi);
        },
        0, 1, 0, 2 * kPi, 1e-5);
}

TEST(NormalMapFurnace, FlatPlaneReflectsTheWholeEnvironment) {
    const Scene flat = furnace_plane(false);
    for (const float deg : {5.0f, 30.0f}) {
        const float e = deg * kPi / 180;
        const Measured m = furnace_radiance(flat, {std::cos(e), std::sin(e), 0});
        EXPECT_NEAR(m.mean, 1, 4 * m.se + 1e-3) << deg;
    }
}

TEST(NormalMapFurnace, MappedPlaneLosesNoMoreThanShadowingFromAnyView) {
    double bound = 1;
    for (int i = 0; i <= 8; ++i) bound = std::min(bound, shadowed_albedo(kTilt * i / 8));
    // The term's own loss at this lean: about 23% (over the 12% the horizon alone takes,
    // (1 - cos kTilt) / 2), so darker than this is a rim, not shadowing.
    ASSERT_GT(bound, 0.7);
    ASSERT_LT(bound, 0.8);
    const Scene mapped = furnace_plane(true);
    for (const float az : {0.0f, 90.0f, 180.0f})
        for (const float deg : {5.0f, 15.0f, 30.0f, 60.0f}) {
            const float e = deg * kPi / 180, a = az * kPi / 180;
            const Vec3 wo(std::cos(a) * std::cos(e), std::sin(e), std::sin(a) * std::cos(e));
            const Measured m = furnace_radiance(mapped, wo);
            const double tol = 4 * m.se + 2e-3;
            EXPECT_GE(m.mean, bound - tol) << "azimuth " << az << ", elevation " << deg;
            EXPECT_LE(m.mean, 1 + tol) << "azimuth " << az << ", elevation " << deg;
        }
}

TEST(NormalMapFurnace, MappedMirrorReflectsTheWholeEnvironmentFromAnyView) {
    const Scene mirror = furnace_plane(true, true);
    for (const float az : {0.0f, 90.0f, 180.0f})
        for (const float deg : {5.0f, 15.0f, 30.0f, 60.0f, 85.0f}) {
            const float e = deg * kPi / 180, a = az * kPi / 180;
            const Vec3 wo(std::cos(a) * std::cos(e), std::sin(e), std::sin(a) * std::cos(e));
            const Measured m = furnace_radiance(mirror, wo);
            EXPECT_NEAR(m.mean, 1, 4 * m.se + 1e-3) << "azimuth " << az << ", elevation " << deg;
        }
}

}  // namespace
}  // namespace penumbra
