// BSDF microbenchmarks: eval, pdf and sample of every model at a fixed view, for the
// cost side of the speed-against-error reports. Figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include <memory>

#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "materials/lobes/conductor.h"
#include "materials/lobes/cook_torrance.h"
#include "materials/lobes/dielectric.h"
#include "materials/gltf_transmission_bsdf.h"
#include "materials/lobes/lambertian.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/oren_nayar.h"

namespace penumbra {
namespace {

MetalRoughParams gltf_params(GltfLayering layering) {
    MetalRoughParams p;
    p.base_color = {0.8f, 0.5f, 0.3f};
    p.metallic = 0.5f;
    p.alpha = 0.09f;
    p.layering = layering;
    return p;
}

DielectricParams glass(float alpha) {
    DielectricParams d;
    d.eta = 1.5f;
    d.alpha = alpha;
    return d;
}

// Every model the benchmarks cover, by index (the benchmark's first argument).
std::unique_ptr<Bsdf> make_bsdf(int which) {
    switch (which) {
        case 0: return std::make_unique<LambertianBsdf>(Spectrum(0.7f));
        case 1: return std::make_unique<OrenNayarBsdf>(Spectrum(0.7f), 0.5f);
        case 2: return std::make_unique<ConductorBsdf>(Metal::Gold, MicrofacetType::Ggx, 0.09f);
        case 3: {
            CookTorranceParams p;
            p.distribution = MicrofacetType::Beckmann;
            p.alpha = 0.09f;
            p.masking = MaskingModel::VCavity;
            return std::make_unique<CookTorranceBsdf>(p);
        }
        case 4: return std::make_unique<DielectricBsdf>(glass(0));
        case 5: return std::make_unique<DielectricBsdf>(glass(0.09f));
        case 6: return std::make_unique<MetalRoughBsdf>(gltf_params(GltfLayering::AlbedoScaled));
        case 7: return std::make_unique<MetalRoughBsdf>(gltf_params(GltfLayering::Spec));
        default: {
            MetalRoughParams p = gltf_params(GltfLayering::AlbedoScaled);
            p.metallic = 0;
            return std::make_unique<GltfTransmissionBsdf>(p, 0.8f, glass(0.09f));
        }
    }
}

const char* kNames[] = {"lambertian",      "oren-nayar",      "conductor-ggx",
                        "cook-torrance-beckmann-vcavity",     "dielectric-smooth",
                        "dielectric-rough", "gltf-albedo-scaled", "gltf-spec",
                        "gltf-transmission"};
constexpr int kModels = 9;

const Vec3 kWo = normalize(Vec3(0.3f, 0.2f, 0.9f));

void BM_BsdfEval(benchmark::State& state) {
    const auto bsdf = make_bsdf(static_cast<int>(state.range(0)));
    state.SetLabel(kNames[state.range(0)]);
    Rng rng(2);
    for (auto _ : state) {
        const Vec3 wi = square_to_cosine_hemisphere({rng.next_float(), rng.next_float()});
        benchmark::DoNotOptimize(bsdf->eval(kWo, wi, Transport::Radiance));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfEval)->DenseRange(0, kModels - 1);

void BM_BsdfPdf(benchmark::State& state) {
    const auto bsdf = make_bsdf(static_cast<int>(state.range(0)));
    state.SetLabel(kNames[state.range(0)]);
    Rng rng(3);
    for (auto _ : state) {
        const Vec3 wi = square_to_cosine_hemisphere({rng.next_float(), rng.next_float()});
        benchmark::DoNotOptimize(bsdf->pdf(kWo, wi, Transport::Radiance));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfPdf)->DenseRange(0, kModels - 1);

void BM_BsdfSample(benchmark::State& state) {
    const auto bsdf = make_bsdf(static_cast<int>(state.range(0)));
    state.SetLabel(kNames[state.range(0)]);
    Rng rng(4);
    for (auto _ : state)
        benchmark::DoNotOptimize(bsdf->sample(kWo, rng.next_float(),
                                              {rng.next_float(), rng.next_float()},
                                              Transport::Radiance));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfSample)->DenseRange(0, kModels - 1);

}  // namespace
}  // namespace penumbra
