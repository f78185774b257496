#include "core/accel/accel.h"

#include <atomic>
#include <stdexcept>

#include "core/accel/bvh_accel.h"
#include "core/accel/embree_accel.h"
#include "core/accel/grid_accel.h"

namespace penumbra {

Accel::Accel() {
    static std::atomic<uint64_t> next_serial{1};  // 0: the empty cache
    m_serial = next_serial.fetch_add(1, std::memory_order_relaxed);
}

uint64_t Accel::rays_traced() const {
    uint64_t n = 0;
    for (uint64_t v : m_rays) n += v;
    return n;
}

const std::vector<std::string>& accel_type_names() {
    static const std::vector<std::string> names = {"embree", "bvh-sah", "bvh-median",
                                                   "bvh-center", "grid"};
    return names;
}

AccelType parse_accel_type(const std::string& name) {
    if (name == "embree") return AccelType::Embree;
    if (name == "bvh" || name == "bvh-sah") return AccelType::BvhSah;
    if (name == "bvh-median") return AccelType::BvhMedian;
    if (name == "bvh-center") return AccelType::BvhCenter;
    if (name == "grid") return AccelType::Grid;
    throw std::invalid_argument("unknown accelerator '" + name +
                                "' (expected embree, bvh, bvh-sah, bvh-median, bvh-center "
                                "or grid)");
}

std::string accel_type_name(AccelType type) {
    switch (type) {
        case AccelType::Embree: return "embree";
        case AccelType::BvhSah: return "bvh-sah";
        case AccelType::BvhMedian: return "bvh-median";
        case AccelType::BvhCenter: return "bvh-center";
        case AccelType::Grid: return "grid";
    }
    throw std::invalid_argument("unknown accelerator type");
}

std::unique_ptr<Accel> make_accel(AccelType type, const Scene& scene) {
    switch (type) {
        case AccelType::Embree: return std::make_unique<EmbreeAccel>(scene);
        case AccelType::BvhSah: return std::make_unique<BvhAccel>(scene, BvhSplit::Sah);
        case AccelType::BvhMedian: return std::make_unique<BvhAccel>(scene, BvhSplit::Median);
        case AccelType::BvhCenter: return std::make_unique<BvhAccel>(scene, BvhSplit::Center);
        case AccelType::Grid: return std::make_unique<GridAccel>(scene);
    }
    throw std::invalid_argument("unknown accelerator type");
}

}  // namespace penumbra
