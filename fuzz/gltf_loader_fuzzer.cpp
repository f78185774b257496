// libFuzzer entry point for the glTF loader: each input is written to a file and loaded
// as .gltf JSON or, when it starts with the "glTF" magic, as .glb (the loader decides by
// the header, as the spec says), with the CLI's default options. The CLI catches every
// std::exception and prints its message; so does this target, but only SceneError (a
// message naming the file and element) is the expected end of bad input. Any other
// exception (e.g. std::length_error from a decoder: "error: vector::_M_default_append"),
// a CHECK failure or a sanitizer report is a bug: the message is printed and libFuzzer
// stops on the abort. Textures are held to 2^16 pixels (a larger one is refused from its
// header, as --max-texture-pixels would): real seeds carry megapixel images whose decoding
// and pyramids would otherwise take most of each run, away from the loader's own code;
// fuzz/make_seeds.py scales the seeds' images down to 64 pixels a side for the same reason.
// Speed: about 1000 executions a second on the 2-core VM with a core free, 430-630 when it
// is shared (`FUZZ_SECONDS=60 bash scripts/fuzz.sh gltf`; docs/performance.md, "Fuzzing").
#include <tbb/global_control.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include "core/error.h"
#include "core/log.h"
#include "io/gltf/gltf_loader.h"

namespace {

// One file per process (libFuzzer may fork workers), in a folder of its own so that
// relative URIs in the input resolve to nothing but files the input cannot create. The
// folder is on /dev/shm (tmpfs) where there is one: ext4 writes a truncated file's data
// back to disk when it is closed, which costs a tenth of each run's time. The folder is
// removed when the process exits normally.
const std::filesystem::path& input_dir() {
    static const std::filesystem::path dir = [] {
        std::error_code ec;
        const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                               ? std::filesystem::path("/dev/shm")
                                               : std::filesystem::temp_directory_path();
        return base / ("penumbra-fuzz-" + std::to_string(getpid()));
    }();
    return dir;
}

const std::string& input_path() {
    static const std::string path = [] {
        std::filesystem::create_directories(input_dir());
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(input_dir(), ec);
        });
        return (input_dir() / "input.gltf").string();
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // Warnings about the (mostly broken) inputs would dominate the run time.
    penumbra::set_log_level(penumbra::LogLevel::Silent);
    // One thread: TBB's hand-offs between workers cost more than the small inputs' work,
    // and libFuzzer's coverage is then that of the input alone.
    static tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = input_path();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        penumbra::GltfLoadOptions options;
        options.max_texture_pixels = uint64_t(1) << 16;
        penumbra::load_gltf(path, options);
    } catch (const penumbra::SceneError&) {
        // The expected outcome for bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gltf_loader_fuzzer: load_gltf threw %s, not SceneError: %s\n",
                     typeid(e).name(), e.what());
        std::abort();
    }
    return 0;
}
