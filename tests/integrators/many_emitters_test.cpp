// A Lambertian floor under 144 small emitters of varied radiance in one plane (single-sided
// ones facing down or up, double-sided ones), through the path and direct integrators: the
// floor's radiance is albedo / pi times the sum of Lambert's formula over the emitters
// that face it, for every light selection and triangle strategy. With the BVH the MIS
// weights of BSDF-found emitters need the pmf at the previous vertex: a wrong one shows.
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/scene/emission.h"
#include "integrators/integrator.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"
#include "support/option_names.h"

namespace penumbra {
namespace {

const float kAlbedo = 0.5f;

// Irradiance at p (normal n) from a triangle of unit radiance above its horizon (Arvo
// 1995, "Applications of irradiance tensors", eq. 10).
double lambert_irradiance(const Vec3 v[3], Vec3 p, Vec3 n) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = normalize(v[k] - p), b = normalize(v[(k + 1) % 3] - p);
        const Vec3 c = cross(a, b);
        sum += std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)) * dot(n, c) / length(c);
    }
    return 0.5 * std::abs(sum);
}

struct Setup {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    double expected = 0;  // floor radiance at the origin (green)
};

std::unique_ptr<Setup> floor_under_emitters() {
    auto s = std::make_unique<Setup>();
    Scene& scene = s->scene;
    const int floor = test::add_lambertian(scene, Spectrum(kAlbedo));
    test::add_instance(
        scene,
        test::add_quad_object(scene, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}, {-20, 0, -20}, floor),
        Transform());
    int emitters[4];
    for (int k = 0; k < 4; ++k) {
        emitters[k] = test::add_lambertian(scene, Spectrum(0));
        scene.materials[emitters[k]].emissive = Spectrum(k % 2 ? 6.0f : 0.4f);
        scene.materials[emitters[k]].double_sided = k >= 2;
    }
    Rng rng(21);
    const int n = 12;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            // A random triangle inside its grid cell of the plane y = 1: no emitter
            // shadows another, so the floor sees the sum of their irradiances.
            const float x0 = -3 + 6.0f * i / n, z0 = -3 + 6.0f * j / n, w = 6.0f / n;
            Vec3 v[3];
            for (Vec3& p : v)
                p = {x0 + w * (0.05f + 0.9f * rng.next_float()), 1,
                     z0 + w * (0.05f + 0.9f * rng.next_float())};
            // Front face (counter-clockwise) down for even cells, up for odd ones.
            const bool down = (i + j) % 2 == 0;
            if ((cross(v[1] - v[0], v[2] - v[0]).y < 0) != down) std::swap(v[1], v[2]);
            TriangleMesh mesh;
            mesh.positions = {v[0], v[1], v[2]};
            const Vec3 nrm = normalize(cross(v[1] - v[0], v[2] - v[0]));
            mesh.normals = {nrm, nrm, nrm};
            mesh.indices = {0, 1, 2};
            mesh.material = emitters[rng.next_below(4)];
            const MaterialDesc& m = scene.materials[mesh.material];
            if (emits_towards(m, nrm, Vec3(0) - v[0]))
                s->expected +=
                    kAlbedo / kPi * m.emissive.y * lambert_irradiance(v, Vec3(0), {0, 1, 0});
            test::add_instance(scene, test::add_mesh_object(scene, std::move(mesh), "tri"),
                               Transform());
        }
    s->accel = std::make_unique<EmbreeAccel>(scene);
    return s;
}

test::Estimate floor_radiance(const Setup& s, const LightSet& lights, const std::string& name,
                              const IntegratorOptions& o, uint64_t n) {
    const auto integrator = make_integrator(test::integrator_named(name), o);
    auto sampler = make_sampler(SamplerType::Independent, 1, 5);
    const RenderContext ctx{s.scene, *s.accel, lights};
    return test::estimate(n, [&](uint64_t i) {
        sampler->start_pixel_sample({int(i), 0}, 0);
        Ray r;
        r.o = {0, 0.5f, 0};
        r.d = {0, -1, 0};
        return integrator->Li(r, ctx, *sampler).y;
    });
}

TEST(ManyEmitters, FloorRadianceIsTheSumOfLambertsFormulaForEverySampler) {
    const auto s = floor_under_emitters();
    ASSERT_GT(s->expected, 0);
    IntegratorOptions mis, light_only, direct;
    light_only.strategy = LightStrategy::LightOnly;
    direct.light_samples = 4;
    for (LightSamplerType type :
         {LightSamplerType::Uniform, LightSamplerType::Power, LightSamplerType::Bvh})
        for (TriangleSampling ts : {TriangleSampling::Area, TriangleSampling::SolidAngle}) {
            const LightSet lights(s->scene, nullptr, {type, ts});
            for (const auto& [name, integrator, o] : {std::tuple{"path mis", "path", mis},
                                                      {"path light", "path", light_only},
                                                      {"direct 4+1", "direct", direct}}) {
                const test::Estimate e = floor_radiance(*s, lights, integrator, o, 120000);
                EXPECT_TRUE(test::within(e, s->expected))
                    << int(type) << " " << int(ts) << " " << name << ": " << e.mean << " +- "
                    << e.std_error << ", expected " << s->expected;
                // Power: 4 standard errors are at most 6% of the answer.
                EXPECT_LT(e.std_error, 0.015 * s->expected) << int(type) << " " << name;
            }
        }
}

}  // namespace
}  // namespace penumbra
