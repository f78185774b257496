// Accelerator benchmarks: closest-hit throughput on incoherent rays (Embree against our
// BVH with each split and the grid, one thread), Embree's packets and streams against
// single rays on the Cornell box's camera and shadow rays, and build time of a
// 1M-triangle mesh on one core. Figures and commands: docs/performance.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <memory>

#include "core/accel/accel.h"
#include "core/accel/embree_accel.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "io/gltf/gltf_loader.h"

namespace penumbra {
namespace {

// A closed UV sphere of 2 * slices * (stacks - 1) triangles, as a one-instance scene.
Scene sphere_scene(int slices, int stacks) {
    Scene scene;
    TriangleMesh m;
    m.positions.push_back({0, 1, 0});
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const float theta = kPi * i / stacks, phi = 2 * kPi * j / slices;
            m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                   std::sin(theta) * std::sin(phi)});
        }
    m.positions.push_back({0, -1, 0});
    const uint32_t south = static_cast<uint32_t>(m.positions.size() - 1);
    auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) {
        m.indices.insert(m.indices.end(), {0u, ring(1, j + 1), ring(1, j)});
        m.indices.insert(m.indices.end(), {south, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    }
    for (int i = 1; i < stacks - 1; ++i)
        for (int j = 0; j < slices; ++j)
            m.indices.insert(m.indices.end(), {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1),
                                               ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    for (const Vec3& p : m.positions) m.bounds.expand(p);
    scene.meshes.push_back(std::move(m));
    scene.objects.push_back({"sphere", {0}, scene.meshes[0].bounds});
    Instance inst;
    scene.instances.push_back(inst);
    return scene;
}

// 100k small random triangles filling a unit cube: deep, incoherent, no large faces.
Scene soup_scene() {
    Scene scene;
    TriangleMesh m;
    Rng rng(12);
    for (int i = 0; i < 100000; ++i) {
        const Vec3 c(rng.next_float(), rng.next_float(), rng.next_float());
        for (int k = 0; k < 3; ++k) {
            m.positions.push_back(c + 0.02f * Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f,
                                                   rng.next_float() - 0.5f));
            m.indices.push_back(static_cast<uint32_t>(m.positions.size() - 1));
        }
    }
    for (const Vec3& p : m.positions) m.bounds.expand(p);
    scene.meshes.push_back(std::move(m));
    scene.objects.push_back({"soup", {0}, scene.meshes[0].bounds});
    scene.instances.push_back(Instance());
    return scene;
}

enum class Which { Cornell, Sphere1M, Soup };

const Scene& scene_for(Which w) {
    static std::map<Which, Scene> scenes;
    auto it = scenes.find(w);
    if (it != scenes.end()) return it->second;
    Scene s = w == Which::Cornell ? load_gltf(PENUMBRA_SOURCE_DIR "/scenes/cornell-box.gltf")
              : w == Which::Soup  ? soup_scene()
                                  : sphere_scene(1000, 501);  // 1,000,000 triangles
    return scenes.emplace(w, std::move(s)).first->second;
}

// Incoherent rays: origins uniform in the scene's bounds, directions uniform.
void BM_Incoherent(benchmark::State& state, Which which, AccelType type) {
    const Scene& scene = scene_for(which);
    const std::unique_ptr<Accel> accel = make_accel(type, scene);
    const Bounds3 b = scene.bounds();
    Rng rng(4);
    std::vector<Ray> rays(1 << 20);
    for (Ray& r : rays) {
        r.o = b.lo + b.diagonal() * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
        r.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
    }
    size_t i = 0, hits = 0;
    for (auto _ : state) {
        hits += accel->intersect(rays[i]).has_value();
        i = (i + 1) & (rays.size() - 1);
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations());
}

#define ACCEL_BENCH(scene, type, label) \
    BENCHMARK_CAPTURE(BM_Incoherent, label, Which::scene, AccelType::type)
ACCEL_BENCH(Cornell, Embree, cornell_embree);
ACCEL_BENCH(Cornell, BvhSah, cornell_bvh_sah);
ACCEL_BENCH(Cornell, BvhMedian, cornell_bvh_median);
ACCEL_BENCH(Cornell, BvhCenter, cornell_bvh_center);
ACCEL_BENCH(Cornell, Grid, cornell_grid);
ACCEL_BENCH(Soup, Embree, soup100k_embree);
ACCEL_BENCH(Soup, BvhSah, soup100k_bvh_sah);
ACCEL_BENCH(Soup, BvhMedian, soup100k_bvh_median);
ACCEL_BENCH(Soup, BvhCenter, soup100k_bvh_center);
ACCEL_BENCH(Soup, Grid, soup100k_grid);
ACCEL_BENCH(Sphere1M, Embree, sphere1m_embree);
ACCEL_BENCH(Sphere1M, BvhSah, sphere1m_bvh_sah);
ACCEL_BENCH(Sphere1M, Grid, sphere1m_grid);

// The Cornell box's camera rays (eye at z = 3.9, vertical fov 0.69 rad, 256 x 256), in
// 4 x 2 pixel blocks so that eight consecutive rays are a coherent packet, each pixel
// jittered; and shadow rays from their hits towards the point light at (0, 0.95, 0).
struct CornellRays {
    // bounce_shadow: from the hits of one diffuse bounce off each camera hit, in the same
    // order, so that eight consecutive ones are what a batch of a 4 x 2 block's paths
    // would trace at their second vertex: one endpoint, scattered origins.
    std::vector<Ray> camera, shadow, bounce_shadow;
};

const CornellRays& cornell_rays() {
    static const CornellRays rays = [] {
        CornellRays r;
        const int n = 256;
        const float tan_half = std::tan(0.69f / 2);
        Rng rng(9);
        for (int by = 0; by < n; by += 2)
            for (int bx = 0; bx < n; bx += 4)
                for (int k = 0; k < 8; ++k) {
                    const float x = bx + (k & 3) + rng.next_float(),
                                y = by + (k >> 2) + rng.next_float();
                    Ray ray;
                    ray.o = {0, 0, 3.9f};
                    ray.d =
                        normalize(Vec3((2 * x / n - 1) * tan_half, (1 - 2 * y / n) * tan_half, -1));
                    r.camera.push_back(ray);
                }
        const EmbreeAccel accel(scene_for(Which::Cornell));
        // From just before ray's hit at t to the light, stopping short of it.
        auto to_light = [](const Ray& ray, float t) {
            Ray s;
            s.o = ray.o + ray.d * (t * (1 - 1e-4f));
            s.d = Vec3(0, 0.95f, 0) - s.o;
            s.tmax = 1 - 1e-4f;
            return s;
        };
        for (const Ray& c : r.camera) {
            const auto hit = accel.intersect(c);
            if (!hit) continue;
            const Ray s = to_light(c, hit->t);
            r.shadow.push_back(s);
            // A uniform direction on the sphere, turned back towards the camera's side
            // of the hit: a bounce into the room.
            Ray b;
            b.o = s.o;
            b.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
            if (dot(b.d, c.d) > 0) b.d = -b.d;
            const auto bounce = accel.intersect(b);
            if (bounce) r.bounce_shadow.push_back(to_light(b, bounce->t));
        }
        return r;
    }();
    return rays;
}

// Argument 1: Embree's default build (the Cornell box flattened into one level); 0: two
// levels (EmbreeBuildOptions::flatten off), each glTF node an instance.
EmbreeBuildOptions embree_levels(int64_t flatten) {
    EmbreeBuildOptions o;
    o.flatten = flatten != 0;
    return o;
}

void BM_CameraRays1(benchmark::State& state) {
    const EmbreeAccel accel(scene_for(Which::Cornell), embree_levels(state.range(0)));
    const std::vector<Ray>& rays = cornell_rays().camera;
    size_t i = 0, hits = 0;
    for (auto _ : state) {
        hits += accel.intersect(rays[i]).has_value();
        i = (i + 1) % rays.size();
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CameraRays1)->Arg(1)->Arg(0);

// Items are rays, so the figure compares with BM_CameraRays1 directly.
void BM_CameraRays8(benchmark::State& state) {
    const EmbreeAccel accel(scene_for(Which::Cornell));
    const std::vector<Ray>& rays = cornell_rays().camera;
    size_t i = 0, hits = 0;
    std::optional<Hit> out[8];
    for (auto _ : state) {
        accel.intersect8(*reinterpret_cast<const Ray(*)[8]>(&rays[i]), out);
        for (const auto& h : out) hits += h.has_value();
        i = (i + 8) % rays.size();
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations() * 8);
}
BENCHMARK(BM_CameraRays8);

// Argument 2 (when given): 1 for the shadow rays of the first bounce's hits.
const std::vector<Ray>& shadow_rays(const benchmark::State& state, int arg) {
    return state.range(arg) ? cornell_rays().bounce_shadow : cornell_rays().shadow;
}

void BM_ShadowRays1(benchmark::State& state) {
    const EmbreeAccel accel(scene_for(Which::Cornell), embree_levels(state.range(0)));
    const std::vector<Ray>& rays = shadow_rays(state, 1);
    size_t i = 0, blocked = 0;
    for (auto _ : state) {
        blocked += accel.occluded(rays[i]);
        i = (i + 1) % rays.size();
    }
    benchmark::DoNotOptimize(blocked);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ShadowRays1)->Args({1, 0})->Args({0, 0})->Args({1, 1});

// rtcOccluded1M over batches of state.range(0) rays, coherent (1) or incoherent (0) hint,
// from the camera's hits (0) or the first bounce's (1).
void BM_ShadowRaysStream(benchmark::State& state) {
    const EmbreeAccel accel(scene_for(Which::Cornell));
    const std::vector<Ray>& rays = shadow_rays(state, 2);
    const size_t batch = size_t(state.range(0));
    std::unique_ptr<bool[]> out(new bool[batch]);
    size_t i = 0, blocked = 0;
    for (auto _ : state) {
        if (i + batch > rays.size()) i = 0;
        accel.occluded_stream(&rays[i], batch, out.get(), state.range(1) != 0);
        blocked += out[0];
        i += batch;
    }
    benchmark::DoNotOptimize(blocked);
    state.SetItemsProcessed(state.iterations() * batch);
}
BENCHMARK(BM_ShadowRaysStream)
    ->Args({8, 1, 0})
    ->Args({64, 1, 0})
    ->Args({256, 1, 0})
    ->Args({256, 0, 0})
    ->Args({8, 1, 1})
    ->Args({8, 0, 1});

// Build of the 1M-triangle sphere on one core (TBB limited to one thread, which also
// holds Embree to one thread).
void BM_Build1M(benchmark::State& state, AccelType type) {
    const Scene& scene = scene_for(Which::Sphere1M);
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    for (auto _ : state) benchmark::DoNotOptimize(make_accel(type, scene));
    state.SetItemsProcessed(state.iterations() * scene.triangle_count());
}
BENCHMARK_CAPTURE(BM_Build1M, embree, AccelType::Embree)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Build1M, bvh_sah, AccelType::BvhSah)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Build1M, bvh_median, AccelType::BvhMedian)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Build1M, bvh_center, AccelType::BvhCenter)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Build1M, grid, AccelType::Grid)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra
