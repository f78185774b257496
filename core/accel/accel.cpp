#include "core/accel/accel.h"

#include <stdexcept>

#include "core/accel/embree_accel.h"

namespace penumbra {

uint64_t Accel::rays_traced() const {
    uint64_t n = 0;
    for (uint64_t v : m_rays) n += v;
    return n;
}

AccelType parse_accel_type(const std::string& name) {
    if (name == "embree") return AccelType::Embree;
    throw std::invalid_argument("unknown accelerator '" + name + "' (expected embree)");
}

std::unique_ptr<Accel> make_accel(AccelType type, const Scene& scene) {
    switch (type) {
        case AccelType::Embree:
            return std::make_unique<EmbreeAccel>(scene);
    }
    throw std::invalid_argument("unknown accelerator type");
}

}  // namespace penumbra
