// Microbenchmarks: sampling warps, BSDF evaluation and sampling, Embree queries and a
// whole render of the Cornell box. See docs/performance.md for figures and commands.
#include <benchmark/benchmark.h>

#include <memory>

#include "core/accel/embree_accel.h"
#include "core/camera/camera.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "integrators/render.h"
#include "io/gltf_loader.h"
#include "materials/metal_rough_bsdf.h"

namespace penumbra {
namespace {

void BM_CosineHemisphere(benchmark::State& state) {
    Rng rng(1);
    for (auto _ : state)
        benchmark::DoNotOptimize(square_to_cosine_hemisphere({rng.next_float(), rng.next_float()}));
}
BENCHMARK(BM_CosineHemisphere);

MetalRoughBsdf test_bsdf() {
    MetalRoughParams p;
    p.base_color = {0.8f, 0.5f, 0.3f};
    p.metallic = 0.5f;
    p.alpha = 0.09f;
    return MetalRoughBsdf(p);
}

void BM_MetalRoughEval(benchmark::State& state) {
    const MetalRoughBsdf bsdf = test_bsdf();
    Rng rng(2);
    const Vec3 wo = normalize(Vec3(0.3f, 0.2f, 0.9f));
    for (auto _ : state) {
        const Vec3 wi = square_to_cosine_hemisphere({rng.next_float(), rng.next_float()});
        benchmark::DoNotOptimize(bsdf.eval(wo, wi, Transport::Radiance));
    }
}
BENCHMARK(BM_MetalRoughEval);

void BM_MetalRoughSample(benchmark::State& state) {
    const MetalRoughBsdf bsdf = test_bsdf();
    Rng rng(3);
    const Vec3 wo = normalize(Vec3(0.3f, 0.2f, 0.9f));
    for (auto _ : state)
        benchmark::DoNotOptimize(bsdf.sample(wo, rng.next_float(),
                                             {rng.next_float(), rng.next_float()},
                                             Transport::Radiance));
}
BENCHMARK(BM_MetalRoughSample);

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

// Args: threads, integrator (0 basic, 1 path).
void BM_RenderCornell(benchmark::State& state) {
    const Scene& scene = cornell_box();
    static const EmbreeAccel accel(scene);
    static const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const auto camera = make_camera(scene.cameras[0], 128, 128);
    const auto integrator = make_integrator(state.range(1) ? "path" : "basic", {});
    RenderOptions opt;
    opt.spp = 4;
    opt.threads = static_cast<int>(state.range(0));
    opt.progress = false;
    for (auto _ : state) benchmark::DoNotOptimize(render(ctx, *camera, *integrator, opt));
    state.SetItemsProcessed(state.iterations() * 128 * 128 * 4);
}
BENCHMARK(BM_RenderCornell)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
