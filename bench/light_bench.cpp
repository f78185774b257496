// Light sampling microbenchmarks: sample_Li of each light type from a fixed receiver,
// pdf_Li of the area and environment lights (what MIS pays on every BSDF-sampled hit),
// and choosing a light by power with the alias table. Figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "core/lights/directional_light.h"
#include "core/lights/environment_light.h"
#include "core/lights/light_set.h"
#include "core/lights/point_light.h"
#include "core/lights/spot_light.h"
#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "io/gltf_loader.h"

namespace penumbra {
namespace {

const ShadingPoint kReceiver{{0.1f, -0.9f, 0.2f}, {0, 1, 0}};

// The Cornell box: its ceiling panel is two emissive triangles.
const Scene& cornell_box() {
    static const Scene scene = load_gltf(PENUMBRA_SOURCE_DIR "/scenes/cornell-box.gltf");
    return scene;
}

// A 1024 x 512 sky: a smooth gradient with a small, 10^4 times brighter sun, the case
// importance sampling exists for.
Image sky_image() {
    Image img(1024, 512, 3);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float sky = 0.2f + 0.8f * (1 - y / float(img.height));
            const bool sun = std::abs(x - 700) < 4 && std::abs(y - 120) < 4;
            float* p = img.at(x, y);
            p[0] = p[1] = p[2] = sun ? 1e4f : sky;
        }
    return img;
}

std::unique_ptr<Light> make_light(int which) {
    switch (which) {
        case 0: return std::make_unique<PointLight>(Vec3(0, 0.9f, 0), Spectrum(8));
        case 1:
            return std::make_unique<SpotLight>(Vec3(0, 0.9f, 0), Vec3(0, -1, 0), Spectrum(8), 0.3f,
                                               0.6f);
        case 2: return std::make_unique<DirectionalLight>(Vec3(0.3f, -1, 0.2f), Spectrum(2), 10);
        case 3: return std::make_unique<EnvironmentLight>(Spectrum(1), 10.0f);
        default: return std::make_unique<EnvironmentLight>(sky_image(), 1.0f, 0.0f, 10.0f);
    }
}
const char* kNames[] = {"point", "spot", "directional", "environment-constant",
                        "environment-image"};

void BM_LightSampleLi(benchmark::State& state) {
    const auto light = make_light(static_cast<int>(state.range(0)));
    state.SetLabel(kNames[state.range(0)]);
    Rng rng(5);
    for (auto _ : state)
        benchmark::DoNotOptimize(light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSampleLi)->DenseRange(0, 4);

void BM_EnvironmentPdf(benchmark::State& state) {
    const auto light = make_light(4);
    Rng rng(6);
    for (auto _ : state) {
        const Vec3 wi = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        benchmark::DoNotOptimize(light->pdf_Li(kReceiver, wi, 0));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EnvironmentPdf);

// Next-event estimation's light step in the Cornell box: pick a light by power, then a
// point on it (an emissive triangle, sampled by area, converted to solid angle).
void BM_AreaLightNee(benchmark::State& state) {
    static const LightSet lights(cornell_box(), nullptr);
    Rng rng(7);
    for (auto _ : state) {
        const auto chosen = lights.sample(rng.next_float());
        benchmark::DoNotOptimize(
            chosen->light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AreaLightNee);

// MIS weight's other half: the solid-angle pdf of an area light for a direction towards it.
void BM_AreaLightPdf(benchmark::State& state) {
    static const LightSet lights(cornell_box(), nullptr);
    const Light* light = lights.lights().front();
    Rng rng(8);
    for (auto _ : state) {
        const auto s = light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0);
        benchmark::DoNotOptimize(light->pdf_Li(kReceiver, s ? s->wi : Vec3(0, 1, 0), 0));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AreaLightPdf);

// Choosing one of many lights by power: the alias table is O(1) whatever the count.
void BM_LightSetChoose(benchmark::State& state) {
    static const LightSet lights(cornell_box(), nullptr);
    Rng rng(9);
    for (auto _ : state) benchmark::DoNotOptimize(lights.sample(rng.next_float()));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSetChoose);

}  // namespace
}  // namespace penumbra
