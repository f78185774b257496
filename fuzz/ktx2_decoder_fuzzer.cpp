// libFuzzer entry point for the KTX2 decoder (io/image/ktx2_decoder.h): each input is
// decoded as a KTX2 file with its mip levels. ImageDecodeError (a message naming the
// image) is the expected end of bad input; any other exception, a CHECK failure or a
// sanitizer report is a bug, printed before abort() stops libFuzzer. Textures are held to
// 2^12 pixels (64x64): the coverage instrumentation of every comparison makes each
// decoded block and filtered texel costly, and larger textures only repeat the same code.
// Larger ones are refused from their header, as the limit's own tests check
// (tests/io/image/ktx2_corrupt_test.cpp); the six conformance files of 64x64 or less
// (ETC1S with and without alpha, UASTC with and without Zstandard) seed every path.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>
#include <vector>

#include "core/log.h"
#include "io/image/ktx2_decoder.h"
#include "io/image/image_reader.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    penumbra::set_log_level(penumbra::LogLevel::Silent);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::vector<uint8_t> bytes(data, data + size);
    try {
        penumbra::decode_ktx2(bytes, "fuzz.ktx2", uint64_t(1) << 12);
    } catch (const penumbra::ImageDecodeError&) {
        // The expected outcome for bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr,
                     "ktx2_decoder_fuzzer: decode_ktx2 threw %s, not ImageDecodeError: %s\n",
                     typeid(e).name(), e.what());
        std::abort();
    }
    return 0;
}
