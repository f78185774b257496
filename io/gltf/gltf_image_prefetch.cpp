#include "io/gltf/gltf_image_prefetch.h"

#include <tbb/parallel_for.h>

namespace penumbra {

void ImagePrefetch::record(std::pair<int, int> key, std::vector<uint8_t> bytes, std::string name,
                           ImageEncoding encoding, const TextureDecodeLimits& limits,
                           bool mipmapped) {
    if (m_jobs.count(key)) return;
    m_jobs.emplace(key, Job{std::move(bytes), std::move(name), encoding, limits, mipmapped, {},
                            nullptr});
}

void ImagePrefetch::decode_all() {
    m_collecting = false;
    std::vector<Job*> jobs;
    for (auto& [key, job] : m_jobs) jobs.push_back(&job);
    // One image per task: images are large, and decoding (inflate, conversion) dominates
    // the load of a textured scene (docs/performance.md, "Big scenes").
    tbb::parallel_for(size_t(0), jobs.size(), [&](size_t i) {
        Job& job = *jobs[i];
        try {
            job.image = decode_texture_image(job.bytes, job.name, job.encoding, job.limits,
                                             job.mipmapped);
        } catch (...) {
            job.error = std::current_exception();
        }
        std::vector<uint8_t>().swap(job.bytes);  // encoded bytes are not needed again
    });
}

bool ImagePrefetch::take(std::pair<int, int> key, TextureImage* out) {
    const auto it = m_jobs.find(key);
    if (it == m_jobs.end()) return false;
    Job job = std::move(it->second);
    m_jobs.erase(it);
    if (job.error) std::rethrow_exception(job.error);
    *out = std::move(job.image);
    return true;
}

}  // namespace penumbra
