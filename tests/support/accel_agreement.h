// Test helper: trace rays through an accelerator and Embree and expect agreement as
// `penumbra check-accel` defines it (study/accel_check.h).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "study/accel_check.h"
#include "core/accel/embree_accel.h"
#include "core/camera/default_camera.h"

namespace penumbra::test {

// Camera rays (the scene's first camera or a default one, 64x64), random rays and
// surface rays (shadow and bounce), fixed seed.
inline std::vector<CheckRay> agreement_rays(const Scene& scene, const Accel& reference,
                                            size_t random, size_t surface) {
    const CameraDesc cam =
        scene.cameras.empty() ? default_camera(scene.bounds(), 1.0f) : scene.cameras[0];
    const auto camera = make_camera(cam, 64, 64);
    CheckRayOptions o;
    o.random = random;
    o.shadow = o.bounce = surface;
    o.seed = 11;
    return make_check_rays(scene, *camera, reference, o);
}

// Every accelerator type against Embree on the same rays: no "other" disagreement and
// at most `threshold` of the rays disagreeing on edges, vertices or grazing hits
// (coincident faces give two right answers and are not counted). Returns the reports.
inline std::vector<AgreementReport> expect_agreement(const Scene& scene, size_t random,
                                                     size_t surface, const std::string& label,
                                                     double threshold = 1e-5) {
    const EmbreeAccel embree(scene);
    const std::vector<CheckRay> rays = agreement_rays(scene, embree, random, surface);
    const TraceResults reference = trace_rays(embree, rays);
    std::vector<AgreementReport> reports;
    for (const AccelType type : all_accel_types()) {
        const std::string name = accel_type_name(type);
        if (name == "embree") continue;
        const auto accel = make_accel(type, scene);
        AgreementReport rep =
            compare_results(scene, rays, reference, trace_rays(*accel, rays), "embree", name);
        std::string examples;
        for (const std::string& e : rep.examples) examples += "\n  " + e;
        EXPECT_TRUE(rep.passes(threshold))
            << label << ": " << name << ": " << rep.disagreements() << " of " << rep.rays
            << " rays disagree (" << rep.count(Disagreement::Other) << " other)" << examples;
        reports.push_back(std::move(rep));
    }
    return reports;
}

}  // namespace penumbra::test
