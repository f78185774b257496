// Internal to io/: texture images decoded in parallel, ahead of the materials that use
// them. A first pass over the materials records each image (with its bytes and encoding)
// in use order; decode_all() decodes them with TBB; the second pass takes the results in
// the same order, so images, warnings and errors are those of a serial load.
#pragma once

#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/texture_image.h"
#include "io/image/image_reader.h"

namespace penumbra {

class ImagePrefetch {
public:
    // True until decode_all(): TextureTable records images instead of decoding them.
    bool collecting() const { return m_collecting; }
    // Queues one image (glTF image index and encoding) for decoding; repeats are ignored.
    void record(std::pair<int, int> key, std::vector<uint8_t> bytes, std::string name,
                ImageEncoding encoding, const TextureDecodeLimits& limits, bool mipmapped);
    // Decodes every queued image, in parallel, keeping each result or exception.
    void decode_all();
    // The decoded image for `key`, once (it is moved out), or the exception its decoding
    // threw, rethrown; false when `key` was not prefetched (decode it as usual).
    bool take(std::pair<int, int> key, TextureImage* out);

private:
    struct Job {
        std::vector<uint8_t> bytes;
        std::string name;
        ImageEncoding encoding;
        TextureDecodeLimits limits;
        bool mipmapped;
        TextureImage image;
        std::exception_ptr error;
    };
    bool m_collecting = true;
    std::map<std::pair<int, int>, Job> m_jobs;
};

}  // namespace penumbra
