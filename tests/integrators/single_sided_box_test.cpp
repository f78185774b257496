// The closed-box identity to 0.05%: inside a box whose walls are Lambertian of albedo a
// and emit Le from their inward (front) faces only, the radiance is Le / (1 - a) in every
// direction. Suite *Long: ctest label "long" (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <thread>
#include <utility>

#include "core/accel/embree_accel.h"
#include "core/sampling/warp.h"
#include "integrators/path_integrator.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

const float kLe = 1, kAlbedo = 0.5f;

// An emissive Lambertian material, single-sided.
int add_emitter(Scene& scene, float albedo) {
    const int m = test::add_lambertian(scene, Spectrum(albedo));
    scene.materials[size_t(m)].emissive = Spectrum(kLe);
    return m;
}

// The cube [-0.5, 0.5]^3 wound (and with normals) facing inwards.
uint32_t add_inward_cube(Scene& scene, int material) {
    const uint32_t cube = test::add_cube_object(scene, material);
    TriangleMesh& mesh = scene.meshes[scene.objects[cube].meshes[0]];
    for (size_t i = 0; i < mesh.indices.size(); i += 3)
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    for (Vec3& n : mesh.normals) n = -n;
    return cube;
}

struct Box {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    std::unique_ptr<LightSet> lights;
};

// The room: the box [-1, 1] x [-1.5, 1.5] x [-2, 2], walls facing in. With `inner`, a
// rotated block inside it also faces in, towards its own sealed interior: the room sees
// only its back faces, which reflect everything (albedo 1) and emit nothing, so the
// radiance in the room is still Le / (1 - a), while light samples on the block's 12
// triangles all come from behind. Two-sided emission would make the block's backs
// emit Le at albedo 1: unbounded radiance.
std::unique_ptr<Box> make_box(bool inner) {
    auto b = std::make_unique<Box>();
    const int walls = add_emitter(b->scene, kAlbedo);
    test::add_instance(b->scene, add_inward_cube(b->scene, walls), Transform::scale({2, 3, 4}));
    if (inner) {
        const int block = add_emitter(b->scene, 1);
        const Quat turn{0, std::sin(0.25f), 0, std::cos(0.25f)};  // half a radian about Y
        test::add_instance(b->scene, add_inward_cube(b->scene, block),
                           Transform::translate({0.2f, -0.3f, 0.5f}) * Transform::rotate(turn) *
                               Transform::scale({0.8f, 1.2f, 1.0f}));
    }
    b->accel = std::make_unique<EmbreeAccel>(b->scene);
    b->lights = std::make_unique<LightSet>(b->scene, nullptr);
    return b;
}

// Radiance along n rays from `origin` in uniform directions, on two threads; each
// sample is independent (its own pixel and index of the independent sampler).
test::Estimate measure(const Box& b, LightStrategy strategy, Vec3 origin, uint32_t n) {
    IntegratorOptions opt;
    opt.strategy = strategy;
    // 256 segments: the room's walls (albedo 1/2) take at least every other bounce, since
    // the block is convex, so the truncation bias is below 2^-128 of the answer. Russian
    // roulette alone would end paths without bias, but not a path that leaks into the
    // sealed block, where albedo 1 and emission Le make the radiance unbounded: a ray
    // through the block's convex edge, where entry and exit lie 1e-7 apart, may be
    // reported on the exit face first (Embree orders the two hits by t, rounded), and such
    // a path bounced 2e7 times before ending by a leak back out (one of 20M paths, mean
    // 3.01 +- 1.01). With the cap, a leak adds at most about 256 Le to one sample: 0.06
    // standard errors of this test.
    opt.max_depth = 256;
    const PathIntegrator integrator(opt);
    // Radiance along rays from inside the room, which meet the block's backs: not camera
    // rays, which would pass through them into the block.
    RenderContext ctx{b.scene, *b.accel, *b.lights};
    ctx.camera_culling = false;
    const int threads = 2;
    double sum[threads] = {}, sum2[threads] = {};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            auto sampler = make_sampler(SamplerType::Independent, 1, 17);
            for (uint32_t i = 0; i < n / threads; ++i) {
                sampler->start_pixel_sample({t, 0}, i);
                Ray r;
                r.o = origin;
                r.d = square_to_uniform_sphere(sampler->get_2d());
                const double x = integrator.Li(r, ctx, *sampler).y;
                sum[t] += x;
                sum2[t] += x * x;
            }
        });
    for (std::thread& t : pool) t.join();
    test::Estimate e;
    e.count = uint64_t(n / threads) * threads;
    double s = 0, s2 = 0;
    for (int t = 0; t < threads; ++t) {
        s += sum[t];
        s2 += sum2[t];
    }
    const double N = double(e.count);
    e.mean = s / N;
    e.std_error = std::sqrt((s2 / N - e.mean * e.mean) / (N - 1));
    return e;
}

// The estimate agrees with Le / (1 - a) within 5 standard errors, and one standard error
// is at most 1e-4 of it: a bias of 0.05% would lie 5 standard errors out.
void expect_closed_box_value(const test::Estimate& e, const char* what) {
    const double expected = kLe / (1 - kAlbedo);
    const double z = (e.mean - expected) / e.std_error;
    std::printf("%s: %.6f +- %.6f (%.4f%%), expected %.6f, z = %+.2f\n", what, e.mean, e.std_error,
                100 * e.std_error / expected, expected, z);
    EXPECT_LT(std::abs(z), 5) << what;
    EXPECT_LT(e.std_error, 1e-4 * expected) << what;
}

const Vec3 kEye(-0.7f, 1.0f, -1.6f);  // inside the room, outside the block

// One sample's standard deviation is about 0.75 (RR and light sampling), so 16M samples
// give a standard error of 1.9e-4 (0.0094%); about 22 s of CPU time.
TEST(SingleSidedBoxLong, RadianceInsideIsEmissionOverOneMinusAlbedo) {
    expect_closed_box_value(measure(*make_box(false), LightStrategy::Mis, kEye, 16000000),
                            "closed box, MIS");
}

// Measured with two-sided emission instead: 2.0873 +- 0.0005,
// z = +186. The standard deviation per sample is about 0.83: 20M samples.
TEST(SingleSidedBoxLong, BackFacesOfAnEmitterInsideEmitNothing) {
    expect_closed_box_value(measure(*make_box(true), LightStrategy::Mis, kEye, 20000000),
                            "closed box around an emitter seen from behind, MIS");
}

}  // namespace
}  // namespace penumbra
