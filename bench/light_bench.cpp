// Light sampling microbenchmarks: sample_Li of each light type from a fixed receiver,
// pdf_Li of the area and environment lights (what MIS pays on every BSDF-sampled hit),
// triangle lights by area and by solid angle, and choosing one of many lights uniformly,
// by power and through the light BVH (sample and pmf). Figures: docs/performance.md.
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
#include "io/gltf/gltf_loader.h"

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
        case 0:
            return std::make_unique<PointLight>(Vec3(0, 0.9f, 0), Spectrum(8));
        case 1:
            return std::make_unique<SpotLight>(Vec3(0, 0.9f, 0), Vec3(0, -1, 0), Spectrum(8), 0.3f,
                                               0.6f);
        case 2:
            return std::make_unique<DirectionalLight>(Vec3(0.3f, -1, 0.2f), Spectrum(2), 10);
        case 3:
            return std::make_unique<EnvironmentLight>(Spectrum(1), 10.0f);
        default:
            return std::make_unique<EnvironmentLight>(sky_image(), 1.0f, 0.0f, 10.0f);
    }
}
const char* kNames[] = {"point", "spot", "directional", "environment-constant",
                        "environment-image"};

void BM_LightSampleLi(benchmark::State& state) {
    const auto light = make_light(static_cast<int>(state.range(0)));
    state.SetLabel(kNames[state.range(0)]);
    Rng rng(5);
    for (auto _ : state)
        benchmark::DoNotOptimize(
            light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0));
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

const char* kTriangleNames[] = {"area", "solid-angle"};
LightSetOptions cornell_options(int64_t triangles) {
    return {LightSamplerType::Bvh,
            triangles ? TriangleSampling::SolidAngle : TriangleSampling::Area};
}

// Next-event estimation's light step in the Cornell box: pick a light for the receiver,
// then a point on it (an emissive triangle, by area or by cosine-warped solid angle).
void BM_AreaLightNee(benchmark::State& state) {
    const LightSet lights(cornell_box(), nullptr, cornell_options(state.range(0)));
    state.SetLabel(kTriangleNames[state.range(0)]);
    Rng rng(7);
    for (auto _ : state) {
        const auto chosen = lights.sample(kReceiver, rng.next_float());
        benchmark::DoNotOptimize(
            chosen->light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AreaLightNee)->DenseRange(0, 1);

// One triangle light's sample_Li alone, by area and by solid angle.
void BM_TriangleSampleLi(benchmark::State& state) {
    const LightSet lights(cornell_box(), nullptr, cornell_options(state.range(0)));
    state.SetLabel(kTriangleNames[state.range(0)]);
    const Light* light = lights.lights().front();
    Rng rng(7);
    for (auto _ : state)
        benchmark::DoNotOptimize(
            light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TriangleSampleLi)->DenseRange(0, 1);

// MIS weight's other half: the solid-angle pdf of an area light for a direction towards
// it (the sample_Li that finds the direction is timed with it; subtract
// BM_TriangleSampleLi for pdf_Li alone).
void BM_AreaLightPdf(benchmark::State& state) {
    const LightSet lights(cornell_box(), nullptr, cornell_options(state.range(0)));
    state.SetLabel(kTriangleNames[state.range(0)]);
    const Light* light = lights.lights().front();
    Rng rng(8);
    for (auto _ : state) {
        const auto s = light->sample_Li(kReceiver, {rng.next_float(), rng.next_float()}, 0);
        benchmark::DoNotOptimize(light->pdf_Li(kReceiver, s ? s->wi : Vec3(0, 1, 0), 0));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AreaLightPdf)->DenseRange(0, 1);

// 10,000 small emissive triangles of varied emission on a dome, as
// scripts/make_many_lights.py --layout dome writes them, built in code.
const Scene& many_emitters() {
    static const Scene scene = [] {
        Scene s;
        for (int k = 0; k < 32; ++k) {
            MaterialDesc m;
            m.emissive = Spectrum(0.1f * std::pow(500.0f, k / 31.0f));
            s.materials.push_back(m);
        }
        Rng rng(3);
        for (int i = 0; i < 10000; ++i) {
            const float z = 0.15f + 0.85f * rng.next_float(), phi = 2 * kPi * rng.next_float();
            const float r = std::sqrt(1 - z * z);
            const Vec3 d(r * std::cos(phi), z, r * std::sin(phi));
            const Vec3 p = Vec3(0, 1, 0) + d * 3.0f;
            const Vec3 t =
                normalize(cross(d, std::abs(d.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 0, 1)));
            const Vec3 b = cross(d, t);
            TriangleMesh mesh;
            // Clockwise seen from outside: the front faces the dome's centre.
            mesh.positions = {p + t * 0.05f, p - t * 0.025f - b * 0.04f,
                              p - t * 0.025f + b * 0.04f};
            mesh.normals = {-d, -d, -d};
            mesh.indices = {0, 1, 2};
            mesh.material = int(rng.next_below(32));
            mesh.bounds.expand(mesh.positions[0]);
            s.meshes.push_back(mesh);
            Object obj;
            obj.meshes = {uint32_t(s.meshes.size() - 1)};
            s.objects.push_back(obj);
            Instance inst;
            inst.object = uint32_t(s.objects.size() - 1);
            s.instances.push_back(inst);
        }
        return s;
    }();
    return scene;
}
const char* kSamplerNames[] = {"uniform", "power", "bvh"};
const ShadingPoint kRoomReceiver{{0.3f, 0, -0.2f}, {0, 1, 0}};

// Choosing one of 10,000 lights for a receiver: O(1) uniformly or by power (alias
// table), O(depth) through the BVH.
void BM_LightSetChoose(benchmark::State& state) {
    const LightSet lights(many_emitters(), nullptr,
                          {LightSamplerType(state.range(0)), TriangleSampling::SolidAngle});
    state.SetLabel(kSamplerNames[state.range(0)]);
    Rng rng(9);
    for (auto _ : state) benchmark::DoNotOptimize(lights.sample(kRoomReceiver, rng.next_float()));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSetChoose)->DenseRange(0, 2);

// The pmf of a light for MIS, as a BSDF-sampled hit on an emitter asks for it.
void BM_LightSetPmf(benchmark::State& state) {
    const LightSet lights(many_emitters(), nullptr,
                          {LightSamplerType(state.range(0)), TriangleSampling::SolidAngle});
    state.SetLabel(kSamplerNames[state.range(0)]);
    Rng rng(10);
    const auto& all = lights.lights();
    for (auto _ : state)
        benchmark::DoNotOptimize(
            lights.pmf(kRoomReceiver, all[rng.next_below(uint32_t(all.size()))]));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightSetPmf)->DenseRange(0, 2);

// Building the light BVH over 10,000 triangles (once per render).
void BM_LightBvhBuild(benchmark::State& state) {
    for (auto _ : state) {
        const LightSet lights(many_emitters(), nullptr);
        benchmark::DoNotOptimize(&lights);
    }
}
BENCHMARK(BM_LightBvhBuild)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra
