// Participating media: what travelling through the inside of a volume does to radiance.
// Integrators ask the medium a path is in about each segment; materials never trace.
#pragma once

#include "core/math/vec.h"
#include "core/ray.h"

namespace penumbra {

// Where a segment of length dist interacts with its medium. Media that only absorb never
// scatter: t is the segment's end and weight its transmittance.
struct MediumSample {
    float t = 0;             // distance along the unit direction, in world units
    Spectrum weight{1, 1, 1};  // throughput factor up to t (Tr / pdf for scattering media)
    bool scattered = false;  // true: a real interaction at t (a phase function follows)
};

class Medium {
public:
    virtual ~Medium() = default;
    // Transmittance exp(-integral of sigma_t) from ray.o along unit ray.d over dist world
    // units (dist may be infinite: an escaping ray).
    virtual Spectrum transmittance(const Ray& ray, float dist) const = 0;
    // Samples the first interaction along [0, dist) with u in [0, 1) (delta tracking's
    // interface, pbrt-v4's SampleT_maj); absorbing media return the segment's end.
    virtual MediumSample sample(const Ray& ray, float dist, float u) const = 0;
    // True when the medium cannot change radiance (transmittance 1 everywhere).
    virtual bool is_clear() const = 0;
};

}  // namespace penumbra
