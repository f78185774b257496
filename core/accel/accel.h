// Ray-scene intersection, the one interface integrators see. Implementations (Embree;
// later our own BVH) return the same Hit, so any result can be cross-checked.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <tbb/enumerable_thread_specific.h>

#include "core/ray.h"
#include "core/scene/scene.h"

namespace penumbra {

struct AccelStats {
    std::string name;
    double build_seconds = 0;
    size_t object_scenes = 0;  // bottom-level structures, one per Object
    size_t instances = 0;      // top-level instances
    size_t memory_bytes = 0;   // best estimate of the structure's own memory
};

class Accel {
public:
    virtual ~Accel() = default;
    // Closest hit along ray in (tmin, tmax) at ray.time.
    std::optional<Hit> intersect(const Ray& ray) const {
        ++m_rays.local();
        return do_intersect(ray);
    }
    // Any hit in (tmin, tmax): for shadow rays.
    bool occluded(const Ray& ray) const {
        ++m_rays.local();
        return do_occluded(ray);
    }
    virtual AccelStats stats() const = 0;
    // Rays traced so far, summed over threads.
    uint64_t rays_traced() const;

protected:
    virtual std::optional<Hit> do_intersect(const Ray& ray) const = 0;
    virtual bool do_occluded(const Ray& ray) const = 0;

private:
    mutable tbb::enumerable_thread_specific<uint64_t> m_rays{0};
};

enum class AccelType { Embree };
AccelType parse_accel_type(const std::string& name);
std::unique_ptr<Accel> make_accel(AccelType type, const Scene& scene);

}  // namespace penumbra
