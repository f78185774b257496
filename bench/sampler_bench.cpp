// Per-sample costs of the render loop's small pieces: the pixel samplers (per
// dimension), the specular albedo lookup and the pixel filters. Figures and commands:
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <memory>

#include "core/film/filter.h"
#include "core/sampling/rng.h"
#include "core/sampling/sampler.h"
#include "materials/albedo/specular_albedo.h"

namespace penumbra {
namespace {

// One camera sample's worth of dimensions as the path tracer draws them: the pixel
// position, lens, time, then 8 bounces of (light choice, light 2D, lobe, BSDF 2D) =
// 2 + 2 + 1 + 8 * 6 = 53 dimensions per sample. Items are dimensions. The argument is
// how many samples of a pixel are drawn in a row before the next pixel (a render pass:
// 1 in the first passes, up to half the budget in the last).
void BM_SamplerDimensions(benchmark::State& state, SamplerType type) {
    const uint32_t spp = 64, run = uint32_t(state.range(0));
    const std::unique_ptr<Sampler> s = make_sampler(type, spp, 7);
    uint32_t i = 0;
    int x = 0, y = 0;
    float sum = 0;
    for (auto _ : state) {
        s->start_pixel_sample({x, y}, i);
        Vec2 v = s->get_pixel_2d() + s->get_2d();
        sum += s->get_1d();
        for (int b = 0; b < 8; ++b) {
            sum += s->get_1d() + s->get_1d();
            v = v + s->get_2d() + s->get_2d();
        }
        sum += v.x + v.y;
        if (++i % run == 0) {
            if (i == spp) i = 0;
            if (++x == 256) x = 0, ++y;
        }
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations() * 53);
}
BENCHMARK_CAPTURE(BM_SamplerDimensions, independent, SamplerType::Independent)->Arg(1)->Arg(64);
BENCHMARK_CAPTURE(BM_SamplerDimensions, stratified, SamplerType::Stratified)->Arg(1)->Arg(64);
BENCHMARK_CAPTURE(BM_SamplerDimensions, sobol, SamplerType::Sobol)->Arg(1)->Arg(64);
BENCHMARK_CAPTURE(BM_SamplerDimensions, zsobol, SamplerType::ZSobol)->Arg(1)->Arg(64);
BENCHMARK_CAPTURE(BM_SamplerDimensions, tabled_sobol, SamplerType::TabledSobol)->Arg(1)->Arg(64);

void BM_SpecularAlbedoAt(benchmark::State& state) {
    const SpecularAlbedo albedo(MicrofacetType::Ggx, 0.3f);
    Rng rng(3);
    float mu[256];
    for (float& m : mu) m = rng.next_float();
    size_t i = 0;
    Vec2 sum(0, 0);
    for (auto _ : state) {
        sum = sum + albedo.at(mu[i++ & 255]);
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SpecularAlbedoAt);

void BM_FilterSample(benchmark::State& state, FilterType type) {
    const std::unique_ptr<Filter> f = make_filter(type);
    Rng rng(3);
    Vec2 u[256];
    for (Vec2& v : u) v = {rng.next_float(), rng.next_float()};
    size_t i = 0;
    float sum = 0;
    for (auto _ : state) {
        const FilterSample fs = f->sample(u[i++ & 255]);
        sum += fs.offset.x + fs.weight;
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_FilterSample, box, FilterType::Box);
BENCHMARK_CAPTURE(BM_FilterSample, gaussian, FilterType::Gaussian);

}  // namespace
}  // namespace penumbra
