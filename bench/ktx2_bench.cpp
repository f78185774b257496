// KTX2 decoding (io/image/ktx2_decoder.h) of the conformance files' 1024x1024 charts:
// ETC1S and UASTC + Zstandard, level 0 alone and with the pyramid (the file's levels, or
// built). Figures: docs/performance.md, "Textures".
#include <benchmark/benchmark.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/image/ktx2_decoder.h"
#include "io/image/image_reader.h"

namespace penumbra {
namespace {

std::vector<uint8_t> read_file(const std::string& name) {
    std::ifstream f(PENUMBRA_SHARED_DIR "/scenes/ktx2/" + name + ".ktx2", std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

void decode(benchmark::State& state, const char* name, bool mipmaps) {
    const std::vector<uint8_t> bytes = read_file(name);
    if (bytes.empty()) {
        state.SkipWithError("../shared/scenes/ktx2 is missing");
        return;
    }
    for (auto _ : state) {
        TextureImage img = decode_ktx2(bytes, name, kDefaultMaxTexturePixels, mipmaps);
        benchmark::DoNotOptimize(img.level_data(0));
    }
}

BENCHMARK_CAPTURE(decode, color_grid_basis, "color_grid_basis", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decode, color_grid_basis_mips, "color_grid_basis", true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decode, color_grid_uastc_zstd, "color_grid_uastc_zstd", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decode, color_grid_uastc_zstd_mips, "color_grid_uastc_zstd", true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decode, ktx_document_basis_mips, "ktx_document_basis", true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decode, ktx_document_uastc_zstd_mips, "ktx_document_uastc_rdo4_zstd5", true)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace penumbra
