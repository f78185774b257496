// Ray-scene intersection, the one interface integrators see. Implementations (Embree,
// our own BVH and grid) return the same Hit, so any result can be cross-checked.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

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

// Rays every accelerator answers with a miss without tracing them: a NaN or infinite
// component, a coordinate beyond 1.844e18 (Embree's FLT_LARGE: its ray.valid() assertion
// aborts the process on such rays), a zero direction, or a NaN or empty [tmin, tmax].
// Inline: it runs before every query, twice a path vertex. With SSE, the six magnitude
// tests are two four-lane comparisons of the ray's two 16-byte spans (o and d.x, d and
// tmin; the lanes past each vector are masked off): the same decisions, in about 15
// instructions where the scalar tests and their branches took about 35.
inline bool is_traceable(const Ray& ray) {
    constexpr float kLarge = 1.844e18f;
#if defined(__SSE2__)
    static_assert(offsetof(Ray, d) == offsetof(Ray, o) + 3 * sizeof(float) &&
                  offsetof(Ray, tmin) == offsetof(Ray, d) + 3 * sizeof(float));
    const __m128 o = _mm_loadu_ps(&ray.o.x), d = _mm_loadu_ps(&ray.d.x);
    const __m128 large = _mm_set1_ps(kLarge), sign = _mm_set1_ps(-0.0f);
    // cmple is false for NaN, as the scalar test below.
    const int small = _mm_movemask_ps(_mm_cmple_ps(_mm_andnot_ps(sign, o), large)) &
                      _mm_movemask_ps(_mm_cmple_ps(_mm_andnot_ps(sign, d), large));
    const int nonzero = _mm_movemask_ps(_mm_cmpneq_ps(d, _mm_setzero_ps()));
    return (small & 7) == 7 && (nonzero & 7) != 0 && ray.tmin <= ray.tmax;
#else
    for (int a = 0; a < 3; ++a)  // written so that NaN fails every test
        if (!(std::abs(ray.o[a]) <= kLarge && std::abs(ray.d[a]) <= kLarge)) return false;
    return (ray.d.x != 0 || ray.d.y != 0 || ray.d.z != 0) && ray.tmin <= ray.tmax;
#endif
}

class Accel {
public:
    Accel();
    virtual ~Accel() = default;
    // Closest hit along ray with tmin <= t <= tmax (Embree's interval in its robust
    // mode) at ray.time. Untraceable rays (is_traceable) miss.
    std::optional<Hit> intersect(const Ray& ray) const {
        count_ray();
        if (!is_traceable(ray)) return std::nullopt;
        return do_intersect(ray);
    }
    // Any hit with tmin <= t <= tmax: for shadow rays.
    bool occluded(const Ray& ray) const {
        count_ray();
        return is_traceable(ray) && do_occluded(ray);
    }
    // Eight closest-hit queries at once, hits[i] as intersect(rays[i]) gives it, counted
    // as eight rays; for coherent batches such as a 4 x 2 block of camera rays. The
    // default traces them one by one (EmbreeAccel: one rtcIntersect8 packet).
    virtual void intersect8(const Ray (&rays)[8], std::optional<Hit> (&hits)[8]) const {
        for (int i = 0; i < 8; ++i) hits[i] = intersect(rays[i]);
    }
    virtual AccelStats stats() const = 0;
    // Points the accelerator at `scene`, a Scene object whose geometry is the one it was
    // built for: the same mesh arrays (the very memory), objects and instances, as a file
    // posed again at a time where nothing moved has. The default keeps no reference.
    virtual void rebind(const Scene& scene) { (void)scene; }
    // Rays traced so far, summed over threads.
    uint64_t rays_traced() const;

protected:
    // Adds n rays to this thread's count (for queries that bypass intersect/occluded).
    void count_rays(uint64_t n) const {
        static thread_local CounterCache cache;
        if (cache.serial != m_serial) cache = {m_serial, &m_rays.local()};
        *cache.slot += n;
    }
    virtual std::optional<Hit> do_intersect(const Ray& ray) const = 0;
    virtual bool do_occluded(const Ray& ray) const = 0;

private:
    // This thread's counter of this accelerator, remembered in a plain thread_local so
    // that a ray costs a compare and an increment, not a TBB thread-local lookup (a hash
    // of the thread id). The key is a serial number, never reused, so a cached slot of
    // a destroyed accelerator is never written.
    struct CounterCache {
        uint64_t serial = 0;
        uint64_t* slot = nullptr;
    };
    void count_ray() const { count_rays(1); }

    uint64_t m_serial;
    mutable tbb::enumerable_thread_specific<uint64_t> m_rays{0};
};

// Embree, our BVH with each of its split strategies (bvh_build.h), and the uniform grid.
enum class AccelType { Embree, BvhSah, BvhMedian, BvhCenter, Grid };
// What logs and reports call it: "embree", "bvh-sah", "bvh-median", "bvh-center", "grid".
std::string accel_type_name(AccelType type);
// Every accelerator, Embree first.
const std::vector<AccelType>& all_accel_types();
std::unique_ptr<Accel> make_accel(AccelType type, const Scene& scene);

}  // namespace penumbra
