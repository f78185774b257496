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

const std::vector<AccelType>& all_accel_types() {
    static const std::vector<AccelType> types = {AccelType::Embree, AccelType::BvhSah,
                                                 AccelType::BvhMedian, AccelType::BvhCenter,
                                                 AccelType::Grid};
    return types;
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
