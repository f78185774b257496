// Motion blur traversal: incoherent rays at random shutter times through moving
// instances and a deforming mesh, Embree (time steps, quaternion instances) against our
// BVH and grid (keyframes interpolated per ray), and the same scenes held still. One
// thread. Figures and commands: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>

#include "core/accel/accel.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"

namespace penumbra {
namespace {

TriangleMesh unit_sphere(int slices, int stacks) {
    TriangleMesh m;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            const float theta = kPi * i / stacks, phi = 2 * kPi * j / slices;
            m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                   std::sin(theta) * std::sin(phi)});
        }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = i * (slices + 1) + j, b = a + slices + 1;
            m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    for (const Vec3& p : m.positions) m.bounds.expand(p);
    return m;
}

Quat axis_angle(Vec3 axis, float angle) {
    const Vec3 a = normalize(axis) * std::sin(0.5f * angle);
    return {a.x, a.y, a.z, std::cos(0.5f * angle)};
}

// 1000 instances of a 4.8k-triangle sphere in a box of side 20; moving: each translates
// by up to 1, turns by up to 90 degrees and scales, over 2 time steps.
Scene instances_scene(bool moving) {
    Scene scene;
    scene.meshes.push_back(unit_sphere(60, 40));
    scene.objects.push_back({"sphere", {0}, scene.meshes[0].bounds});
    Rng rng(8);
    auto u = [&] { return rng.next_float(); };
    for (int i = 0; i < 1000; ++i) {
        Instance inst;
        const Vec3 t(20 * u() - 10, 20 * u() - 10, 20 * u() - 10);
        const Vec3 s(0.3f + 0.5f * u(), 0.3f + 0.5f * u(), 0.3f + 0.5f * u());
        inst.to_world = Transform::trs(t, axis_angle(Vec3(u(), u(), u() + 0.1f), 6 * u()), s);
        const Vec3 move(u() - 0.5f, u() - 0.5f, u() - 0.5f);
        if (moving)
            inst.motion = {inst.to_world,
                           Transform::translate(move * 2.0f) *
                               Transform::rotate(axis_angle(Vec3(u(), u() + 0.1f, u()), 1.57f * u())) *
                               inst.to_world * Transform::scale(Vec3(1.2f, 1, 1))};
        scene.instances.push_back(inst);
    }
    return scene;
}

// One 100k-triangle sphere whose vertices ripple over 3 time steps.
Scene deforming_scene(bool moving) {
    Scene scene;
    TriangleMesh m = unit_sphere(250, 200);
    if (moving) {
        for (int k = 0; k < 3; ++k) {
            std::vector<Vec3> p = m.positions;
            for (Vec3& v : p) v = v * (1 + 0.1f * k * std::sin(9 * v.x + k));
            for (const Vec3& v : p) m.bounds.expand(v);
            m.motion_positions.push_back(std::move(p));
        }
        m.motion_positions[0] = m.positions;
    }
    scene.meshes.push_back(std::move(m));
    scene.objects.push_back({"sphere", {0}, scene.meshes[0].bounds});
    scene.instances.push_back(Instance());
    return scene;
}

enum class Which { Instances, Deforming };

const Scene& scene_for(Which w, bool moving) {
    static std::map<std::pair<Which, bool>, Scene> scenes;
    const auto key = std::make_pair(w, moving);
    auto it = scenes.find(key);
    if (it != scenes.end()) return it->second;
    Scene s = w == Which::Instances ? instances_scene(moving) : deforming_scene(moving);
    return scenes.emplace(key, std::move(s)).first->second;
}

void BM_MotionIncoherent(benchmark::State& state, Which which, bool moving, AccelType type) {
    const Scene& scene = scene_for(which, moving);
    const std::unique_ptr<Accel> accel = make_accel(type, scene);
    const Bounds3 b = scene.bounds();
    Rng rng(4);
    std::vector<Ray> rays(1 << 20);
    for (Ray& r : rays) {
        r.o = b.lo + b.diagonal() * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
        r.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        r.time = rng.next_float();
    }
    size_t i = 0, hits = 0;
    for (auto _ : state) {
        hits += accel->intersect(rays[i]).has_value();
        i = (i + 1) & (rays.size() - 1);
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations());
}

#define MOTION_BENCH(scene, moving, type, label) \
    BENCHMARK_CAPTURE(BM_MotionIncoherent, label, Which::scene, moving, AccelType::type)
MOTION_BENCH(Instances, false, Embree, instances_still_embree);
MOTION_BENCH(Instances, true, Embree, instances_moving_embree);
MOTION_BENCH(Instances, false, BvhSah, instances_still_bvh_sah);
MOTION_BENCH(Instances, true, BvhSah, instances_moving_bvh_sah);
MOTION_BENCH(Instances, false, Grid, instances_still_grid);
MOTION_BENCH(Instances, true, Grid, instances_moving_grid);
MOTION_BENCH(Deforming, false, Embree, deforming_still_embree);
MOTION_BENCH(Deforming, true, Embree, deforming_moving_embree);
MOTION_BENCH(Deforming, false, BvhSah, deforming_still_bvh_sah);
MOTION_BENCH(Deforming, true, BvhSah, deforming_moving_bvh_sah);
MOTION_BENCH(Deforming, false, Grid, deforming_still_grid);
MOTION_BENCH(Deforming, true, Grid, deforming_moving_grid);

}  // namespace
}  // namespace penumbra
