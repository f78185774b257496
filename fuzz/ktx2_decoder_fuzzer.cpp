// libFuzzer entry point for the KTX2 decoder (io/image/ktx2_decoder.h): each input is
// decoded as a KTX2 file with its mip levels. ImageDecodeError (a message naming the
// image) is the expected end of bad input; any other exception, a CHECK failure or a
// sanitizer report is a bug, printed before abort() stops libFuzzer. Textures are held to
// 2^16 pixels (256x256) so that each input decodes in well under a millisecond: larger
// ones are refused from their header, which the limit's own tests cover
// (tests/io/image/ktx2_corrupt_test.cpp).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>
#include <vector>

#include "core/log.h"
#include "io/image/ktx2_decoder.h"
#include "io/image_reader.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    penumbra::set_log_level(penumbra::LogLevel::Silent);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::vector<uint8_t> bytes(data, data + size);
    try {
        penumbra::decode_ktx2(bytes, "fuzz.ktx2", uint64_t(1) << 16);
    } catch (const penumbra::ImageDecodeError&) {
        // The expected outcome for bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ktx2_decoder_fuzzer: decode_ktx2 threw %s, not ImageDecodeError: %s\n",
                     typeid(e).name(), e.what());
        std::abort();
    }
    return 0;
}
