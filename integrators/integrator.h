// Integrators estimate the radiance arriving along a camera ray. They see the scene
// only through the Accel interface and the plain Scene data.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/accel/accel.h"
#include "core/sampling/sampler.h"
#include "core/scene/scene.h"

namespace penumbra {

struct IntegratorOptions {
    int max_depth = 5;             // specular bounces for "basic"
    Spectrum background{0, 0, 0};  // radiance of rays that escape
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Radiance along ray (world space). Uses sampler dimensions after the camera's.
    virtual Spectrum Li(const Ray& ray, const Scene& scene, const Accel& accel,
                        Sampler& sampler) const = 0;
};

// Names accepted by make_integrator, with one-line descriptions (for --help).
const std::vector<std::pair<std::string, std::string>>& integrator_names();
// Throws std::invalid_argument for an unknown name.
std::unique_ptr<Integrator> make_integrator(const std::string& name,
                                            const IntegratorOptions& options);

}  // namespace penumbra
