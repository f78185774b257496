// Nested volumes refract by the ratio of the IORs on the two sides of each boundary, as
// the path's medium stack gives them (path_media.h): glass into liquid at 1.33 / 1.5, an
// inner face between two volumes of the same IOR not at all. Checked on the relative IOR
// itself and on the transmittance of nested smooth slabs at normal incidence, where
// incoherent multiple reflection has a closed form (a t-test on 0/1 samples).
#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "integrators/path_media.h"
#include "materials/lobes/fresnel.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

MaterialDesc clear_volume(float ior) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = 0;
    m.ior = ior;
    m.transmission = 1;
    m.thickness = 1;
    return m;
}

TEST(NestedDielectric, BoundariesRefractByTheRatioOfTheirSides) {
    Scene scene;
    scene.materials = {clear_volume(1.5f), clear_volume(1.33f), clear_volume(1.5f)};
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    PathMedia media;
    // Into glass from outside, then into the liquid inside it, out of the liquid, out.
    EXPECT_EQ(path_volume(ctx, media, 0, true).eta, 1.5f);
    media.stack.enter(0);
    EXPECT_FLOAT_EQ(path_volume(ctx, media, 1, true).eta, 1.33f / 1.5f);
    media.stack.enter(1);
    EXPECT_FLOAT_EQ(path_volume(ctx, media, 1, false).eta, 1.5f / 1.33f);
    media.stack.leave(1);
    EXPECT_EQ(path_volume(ctx, media, 0, false).eta, 1 / 1.5f);
    // Overlap: in glass 0 and then glass 2 (entered last, current); leaving 0 there
    // crosses no interface.
    media.stack.enter(2);
    EXPECT_EQ(path_volume(ctx, media, 0, false).eta, 1.0f);
    // Leaving a volume the path is not in: the material against IOR 1, as without media.
    EXPECT_EQ(path_volume(ctx, PathMedia{}, 1, false).eta, 0.0f);
    // Thin-walled materials take no ratio.
    scene.materials[1].thickness = 0;
    const RenderContext thin{scene, accel, lights};
    EXPECT_EQ(path_volume(thin, PathMedia{}, 1, true).eta, 0.0f);
}

// Incoherent stack of smooth interfaces with reflectances R (from either side): the
// transmittance T of the whole by adding one interface at a time.
double stack_transmittance(const std::vector<double>& R) {
    double t = 1, r = 0;
    for (double ri : R) {
        const double ti = 1 - ri, d = 1 - r * ri;
        const double t_new = t * ti / d;
        r = r + t * t * ri / d;
        t = t_new;
    }
    return t;
}

double slab_estimate(const std::vector<MaterialDesc>& volumes, double* se) {
    // Boxes nested along z: the first [-2, 2]^2 x [-1, 1], each next 0.5 thinner in z and
    // smaller in x, y; an emitter of 1 behind them facing +z; black elsewhere.
    Scene scene;
    for (size_t i = 0; i < volumes.size(); ++i) {
        scene.materials.push_back(volumes[i]);
        const float h = 1 - 0.25f * i, w = 2 - 0.25f * i;
        const uint32_t cube = test::add_cube_object(scene, int(i));
        test::add_instance(scene, cube, Transform::scale({2 * w, 2 * w, 2 * h}));
    }
    MaterialDesc emitter;
    emitter.base_color = {0, 0, 0, 1};
    emitter.metallic = 0;
    emitter.specular = 0;
    emitter.emissive = Spectrum(1);
    emitter.double_sided = true;
    scene.materials.push_back(emitter);
    const uint32_t quad = test::add_quad_object(scene, {-10, -10, -3}, {10, -10, -3},
                                                {10, 10, -3}, {-10, 10, -3},
                                                int(scene.materials.size()) - 1);
    test::add_instance(scene, quad, Transform::scale(Vec3(1)));
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    IntegratorOptions opt;
    opt.max_depth = 64;
    opt.rr_depth = 1000;
    const auto integrator = make_integrator(IntegratorType::Path, opt);
    IndependentSampler sampler(1, 7);
    const test::Estimate e = test::estimate(20000, [&](uint64_t i) {
        sampler.start_pixel_sample({0, 0}, uint32_t(i));
        Ray r;
        r.o = {0.01f, 0.02f, 5};
        r.d = {0, 0, -1};
        return double(integrator->Li(r, ctx, sampler).y);
    });
    *se = e.std_error;
    return e.mean;
}

TEST(NestedDielectric, NestedSlabsTransmitAsTheirInterfacesSay) {
    const double F_glass = fresnel_dielectric(1, 1.5f);
    double se = 0;
    // Glass in glass: the inner faces are no interface; one slab of two faces.
    const double same = slab_estimate({clear_volume(1.5f), clear_volume(1.5f)}, &se);
    EXPECT_NEAR(same, stack_transmittance({F_glass, F_glass}), 4 * se) << "+- " << se;
    // Liquid in glass: four faces, the inner two at 1.33 / 1.5 (0.0036, where IOR 1.33
    // against 1 would reflect 0.020 and lower T by ~0.03, ~15 standard errors).
    const double F_inner = fresnel_dielectric(1, 1.33f / 1.5f);
    const double nested = slab_estimate({clear_volume(1.5f), clear_volume(1.33f)}, &se);
    EXPECT_NEAR(nested, stack_transmittance({F_glass, F_inner, F_inner, F_glass}), 4 * se)
        << "+- " << se;
}

}  // namespace
}  // namespace penumbra
