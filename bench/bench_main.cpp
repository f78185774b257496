// Microbenchmarks: sampling warps, Embree queries and whole renders of the Cornell box
// and of a textured Khronos model (BSDFs: material_bench.cpp; lights: light_bench.cpp).
// See docs/performance.md for figures and commands.
#include <benchmark/benchmark.h>

#include <memory>

#include "core/accel/embree_accel.h"
#include "core/camera/camera.h"
#include "core/camera/default_camera.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "integrators/render.h"
#include "io/gltf/gltf_loader.h"

namespace penumbra {
namespace {

void BM_CosineHemisphere(benchmark::State& state) {
    Rng rng(1);
    for (auto _ : state)
        benchmark::DoNotOptimize(square_to_cosine_hemisphere({rng.next_float(), rng.next_float()}));
}
BENCHMARK(BM_CosineHemisphere);

const Scene& cornell_box() {
    static const Scene scene = load_gltf(PENUMBRA_SOURCE_DIR "/scenes/cornell-box.gltf");
    return scene;
}

// Incoherent rays: random origins inside the box, random directions.
void BM_EmbreeIntersectIncoherent(benchmark::State& state) {
    static const EmbreeAccel accel(cornell_box());
    Rng rng(4);
    for (auto _ : state) {
        Ray r;
        r.o = {rng.next_float() * 1.8f - 0.9f, rng.next_float() * 1.8f - 0.9f,
               rng.next_float() * 1.8f - 0.9f};
        r.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        benchmark::DoNotOptimize(accel.intersect(r));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EmbreeIntersectIncoherent);

// Renders 128x128 at 4 spp and reports samples/s (items) and rays/s (a counter).
void render_benchmark(benchmark::State& state, const Scene& scene, const Accel& accel,
                      const LightSet& lights, const Camera& camera, IntegratorType integrator_name,
                      int threads) {
    const RenderContext ctx{scene, accel, lights};
    const auto integrator = make_integrator(integrator_name, {});
    RenderOptions opt;
    opt.spp = 4;
    opt.threads = threads;
    opt.progress = false;
    uint64_t rays = 0;
    for (auto _ : state) {
        RenderStats stats;
        benchmark::DoNotOptimize(render(ctx, camera, *integrator, opt, &stats));
        rays += stats.rays;
    }
    state.SetItemsProcessed(state.iterations() * 128 * 128 * 4);
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

// Args: threads, integrator (0 basic, 1 path).
void BM_RenderCornell(benchmark::State& state) {
    const Scene& scene = cornell_box();
    static const EmbreeAccel accel(scene);
    static const LightSet lights(scene, nullptr);
    const auto camera = make_camera(scene.cameras[0], 128, 128);
    render_benchmark(state, scene, accel, lights, *camera, state.range(1) ? IntegratorType::Path : IntegratorType::Basic,
                     static_cast<int>(state.range(0)));
}
BENCHMARK(BM_RenderCornell)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

// The textured Khronos box (base colour texture, GGX), path traced under a uniform
// environment of radiance 1 from the default camera. Arg: threads.
void BM_RenderBoxTextured(benchmark::State& state) {
    static const Scene scene = load_gltf(PENUMBRA_SHARED_DIR "/scenes/khronos/BoxTextured.gltf");
    static const EmbreeAccel accel(scene);
    static const LightSet lights(
        scene, std::make_unique<EnvironmentLight>(Spectrum(1), length(scene.bounds().diagonal())));
    const auto camera = make_camera(default_camera(scene.bounds(), 1), 128, 128);
    render_benchmark(state, scene, accel, lights, *camera, IntegratorType::Path, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_RenderBoxTextured)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
